// Writing point clouds: binary little-endian PLY (Turk 1994, the Stanford polygon format), the
// format point-cloud tools (CloudCompare, MeshLab, Open3D, PCL) all read.
//
// The file has one element, vertex, with the properties float x, y, z; then, when colors are
// given, uchar red, green, blue; then, when normals are given, float nx, ny, nz. Writers are
// atomic as those of image_io.hpp; the encoder gives the same bytes in memory (for OutputFiles).
#pragma once
#include <zraster/export.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace zraster {

// rgb holds 3 bytes per point or is empty; normals one per point or are empty. Throws InputError
// for other sizes and for more than 2^32 - 1 points (PLY counts are 32-bit in practice).
ZRASTER_API std::vector<std::uint8_t> encode_ply_points(std::span<const glm::vec3> positions,
                                                        std::span<const std::uint8_t> rgb = {},
                                                        std::span<const glm::vec3> normals = {});
ZRASTER_API void write_ply_points(const std::filesystem::path& path,
                                  std::span<const glm::vec3> positions,
                                  std::span<const std::uint8_t> rgb = {},
                                  std::span<const glm::vec3> normals = {});

}  // namespace zraster
