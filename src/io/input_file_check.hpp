// Checks on a model file made before Assimp sees it, so that the common mistakes get a clear
// message and absurd inputs are refused before anything large is allocated.
#pragma once
#include <cstdint>
#include <filesystem>

namespace zraster::io {

// The file exists, is a regular file, is readable, not empty and at most max_bytes long.
// Returns its size. Throws InputError; LimitExceeded(file, limit, ...) for a file over max_bytes
// when `limit` names the LoadOptions field max_bytes comes from (a plain InputError for null).
std::uintmax_t check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                                const char* limit = "max_file_bytes");

}  // namespace zraster::io
