// Binary little-endian PLY point clouds (point_cloud_io.hpp).
#include <zraster/error.hpp>
#include <zraster/point_cloud_io.hpp>

#include "io/atomic_write.hpp"

#include <bit>
#include <cstdint>
#include <string>

namespace zraster {

namespace {

// Explicit little-endian bytes: the header says binary_little_endian whatever the host is.
void put_float(std::vector<std::uint8_t>& out, float value) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (int shift = 0; shift < 32; shift += 8)
        out.push_back(static_cast<std::uint8_t>(bits >> shift));
}

}  // namespace

std::vector<std::uint8_t> encode_ply_points(std::span<const glm::vec3> positions,
                                            std::span<const std::uint8_t> rgb,
                                            std::span<const glm::vec3> normals) {
    const std::size_t n = positions.size();
    if (!rgb.empty() && rgb.size() != 3 * n)
        throw InputError("rgb", "holds " + std::to_string(rgb.size()) +
                                    " bytes, not 3 per point (" + std::to_string(3 * n) + ")");
    if (!normals.empty() && normals.size() != n)
        throw InputError("normals", "holds " + std::to_string(normals.size()) +
                                        " normals, not one per point (" + std::to_string(n) + ")");
    if (n > 0xFFFFFFFFu)
        throw InputError("positions", "more than 2^32 - 1 points do not fit a PLY vertex count");
    std::string header = "ply\nformat binary_little_endian 1.0\ncomment zraster point cloud\n";
    header += "element vertex " + std::to_string(n) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    if (!rgb.empty()) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    if (!normals.empty()) header += "property float nx\nproperty float ny\nproperty float nz\n";
    header += "end_header\n";
    const std::size_t stride = 12 + (rgb.empty() ? 0 : 3) + (normals.empty() ? 0 : 12);
    std::vector<std::uint8_t> out;
    out.reserve(header.size() + n * stride);
    out.insert(out.end(), header.begin(), header.end());
    for (std::size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) put_float(out, positions[i][c]);
        if (!rgb.empty()) out.insert(out.end(), &rgb[3 * i], &rgb[3 * i] + 3);
        if (!normals.empty())
            for (int c = 0; c < 3; ++c) put_float(out, normals[i][c]);
    }
    return out;
}

void write_ply_points(const std::filesystem::path& path, std::span<const glm::vec3> positions,
                      std::span<const std::uint8_t> rgb, std::span<const glm::vec3> normals) {
    io::write_file_atomically(path, encode_ply_points(positions, rgb, normals));
}

}  // namespace zraster
