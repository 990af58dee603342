// Atomic file output of one file: OutputFiles (zraster/output_files.hpp) with a single output, so
// that the library's writers (write_png8, write_npy, ...) check the path and name their
// temporary as every command's outputs do.
#pragma once
#include <cstdint>
#include <filesystem>
#include <span>

namespace zraster::io {

// Throws InputError(path, "cannot write: <reason>") as OutputFiles::check and commit do; a
// failure leaves the old file (or none) and no temporary.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

}  // namespace zraster::io
