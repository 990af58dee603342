// Binary PLY point clouds: the header declares exactly the properties given, the body is
// little-endian with one record per point, and sizes that disagree are refused.
#include <zraster/error.hpp>
#include <zraster/point_cloud_io.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace zraster {
namespace {

std::string text_of(const std::vector<std::uint8_t>& bytes) {
    return {bytes.begin(), bytes.end()};
}

TEST(PlyWrite, PositionsColorsAndNormals) {
    const std::vector<glm::vec3> positions{{1.0f, 2.0f, 3.0f}, {-0.5f, 0.25f, 8.0f}};
    const std::vector<std::uint8_t> rgb{10, 20, 30, 200, 210, 220};
    const std::vector<glm::vec3> normals{{0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}};
    const std::string file = text_of(encode_ply_points(positions, rgb, normals));
    const std::string header =
        "ply\nformat binary_little_endian 1.0\ncomment zraster point cloud\nelement vertex 2\n"
        "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
        "property uchar green\nproperty uchar blue\nproperty float nx\nproperty float ny\n"
        "property float nz\nend_header\n";
    ASSERT_EQ(file.substr(0, header.size()), header);
    ASSERT_EQ(file.size(), header.size() + 2 * 27);
    const char* second = file.data() + header.size() + 27;
    float x = 0.0f, nx = 0.0f;
    std::memcpy(&x, second, 4);  // the test host is little-endian, as the file
    std::memcpy(&nx, second + 15, 4);
    EXPECT_EQ(x, -0.5f);
    EXPECT_EQ(std::uint8_t(second[12]), 200);
    EXPECT_EQ(std::uint8_t(second[14]), 220);
    EXPECT_EQ(nx, 1.0f);
}

TEST(PlyWrite, PositionsOnly) {
    const std::vector<glm::vec3> positions{{1.0f, 2.0f, 3.0f}};
    const std::string file = text_of(encode_ply_points(positions));
    EXPECT_EQ(file.find("red"), std::string::npos);
    EXPECT_EQ(file.find("nx"), std::string::npos);
    EXPECT_EQ(file.size(), file.find("end_header\n") + 11 + 12);
}

TEST(PlyWrite, RefusesSizesThatDisagree) {
    const std::vector<glm::vec3> positions(3);
    const std::vector<std::uint8_t> rgb(8);
    const std::vector<glm::vec3> normals(2);
    EXPECT_THROW(encode_ply_points(positions, rgb), InputError);
    EXPECT_THROW(encode_ply_points(positions, {}, normals), InputError);
}

}  // namespace
}  // namespace zraster
