// Reading whole input files, with the user-facing errors for missing and unreadable ones.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

namespace zraster::io {

// Throws InputError(path, "file not found" / "not a regular file" / "cannot read: <reason>").
std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& path);

}  // namespace zraster::io
