// PLY and OFF headers declare element counts, and Assimp reserves memory for them before reading
// the body: a 200-byte file claiming 2^40 faces makes it allocate gigabytes or run for minutes
// (and with Debian's Assimp, whose assertions are enabled, a short OFF body aborts the process).
// Every record takes at least a few bytes, so the counts can be checked against the file size.
#pragma once
#include <zraster/load.hpp>

#include <cstdint>
#include <filesystem>

namespace zraster::io {

// Does nothing for other formats. Throws InputError("truncated or malformed file: ...").
void check_declared_counts(const std::filesystem::path& path, std::uintmax_t file_size,
                           const LoadOptions& options);

}  // namespace zraster::io
