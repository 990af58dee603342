#include "io/atomic_write.hpp"

#include <zraster/output_files.hpp>

#include <vector>

namespace zraster::io {

void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    OutputFiles outputs;
    outputs.check(path, "");
    outputs.add(path, std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
    outputs.commit();
}

}  // namespace zraster::io
