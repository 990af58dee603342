// Atomic file output: the bytes go to a temporary file beside the target, which is then renamed
// over it, so readers never see a half-written file and a failure leaves the old file (or none).
#pragma once
#include <cstdint>
#include <filesystem>
#include <span>

namespace zraster::io {

// Throws InputError(path, "cannot write: <reason>"); the temporary file is removed on failure.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

}  // namespace zraster::io
