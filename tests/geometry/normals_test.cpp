#include <zraster/mesh.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace zraster {
namespace {

// A unit cube [-1, 1]^3 with one vertex per corner (shared by the three faces that meet there).
// Corner k has coordinates (k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1).
// Each face is a quad (counter-clockwise from outside) split along the diagonal q0-q2.
Mesh corner_cube() {
    Mesh m;
    for (int k = 0; k < 8; ++k)
        m.positions.push_back({k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f});
    const std::uint32_t quads[6][4] = {
        {1, 3, 7, 5},  // +x
        {0, 4, 6, 2},  // -x
        {2, 6, 7, 3},  // +y
        {0, 1, 5, 4},  // -y
        {4, 5, 7, 6},  // +z
        {0, 2, 3, 1},  // -z
    };
    for (const auto& q : quads)
        m.indices.insert(m.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    return m;
}

glm::vec3 corner_direction(int k) {
    return glm::normalize(
        glm::vec3(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f));
}

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-6f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// Area-weighted normals, the alternative the angle weighting is chosen over.
std::vector<glm::vec3> area_weighted_normals(const Mesh& m) {
    std::vector<glm::vec3> sum(m.positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        const glm::vec3 n = glm::cross(b - a, c - a);
        for (int k = 0; k < 3; ++k) sum[m.indices[t + k]] += n;
    }
    for (glm::vec3& n : sum) n = glm::normalize(n);
    return sum;
}

TEST(AngleWeightedNormals, CubeCornersPointAlongTheDiagonal) {
    Mesh m = corner_cube();
    compute_angle_weighted_normals(m);
    ASSERT_EQ(m.normals.size(), 8u);
    for (int k = 0; k < 8; ++k) expect_near(m.normals[k], corner_direction(k));
}

TEST(AngleWeightedNormals, AreaWeightingWouldDependOnTheTriangulation) {
    // The cube's diagonal split is asymmetric: some corners touch two triangles of a face, others
    // one. Area weighting tilts those corners' normals; angle weighting does not (test above).
    const auto area = area_weighted_normals(corner_cube());
    float worst = 0.0f;
    for (int k = 0; k < 8; ++k) worst = std::max(worst, glm::length(area[k] - corner_direction(k)));
    EXPECT_GT(worst, 0.05f);
}

TEST(AngleWeightedNormals, SplittingAFaceDoesNotChangeTheNormals) {
    Mesh m = corner_cube();
    // Replace the +y face (triangles 4 and 5) by a fan of four triangles around its center, and
    // the +x face by three triangles using a vertex in the middle of its edge 1-3.
    m.indices.erase(m.indices.begin() + 4 * 3, m.indices.begin() + 6 * 3);
    m.indices.erase(m.indices.begin(), m.indices.begin() + 2 * 3);
    const auto center = std::uint32_t(m.positions.size());
    m.positions.push_back({0.0f, 1.0f, 0.0f});
    m.indices.insert(m.indices.end(), {2, 6, center, 6, 7, center, 7, 3, center, 3, 2, center});
    const auto mid = std::uint32_t(m.positions.size());
    m.positions.push_back({1.0f, 0.0f, -1.0f});  // middle of edge 1-3 (x = 1, z = -1)
    m.indices.insert(m.indices.end(), {1, mid, 5, mid, 7, 5, mid, 3, 7});

    compute_angle_weighted_normals(m);
    for (int k = 0; k < 8; ++k) expect_near(m.normals[k], corner_direction(k));
    expect_near(m.normals[center], {0.0f, 1.0f, 0.0f});
    // The edge midpoint belongs to the +x face only (a T-junction with the -z face).
    expect_near(m.normals[mid], {1.0f, 0.0f, 0.0f});

    // Area weighting does change under the same split.
    const auto area = area_weighted_normals(m);
    float worst = 0.0f;
    for (int k = 0; k < 8; ++k) worst = std::max(worst, glm::length(area[k] - corner_direction(k)));
    EXPECT_GT(worst, 0.05f);
}

TEST(AngleWeightedNormals, DegenerateTrianglesAreIgnored) {
    Mesh m = corner_cube();
    compute_angle_weighted_normals(m);
    const auto reference = m.normals;

    // A repeated index, a collinear triangle along an edge, and one made only of a new vertex.
    const auto lone = std::uint32_t(m.positions.size());
    m.positions.push_back({5.0f, 5.0f, 5.0f});
    const auto on_edge = std::uint32_t(m.positions.size());
    m.positions.push_back({0.0f, -1.0f, -1.0f});  // on edge 0-1
    m.indices.insert(m.indices.end(), {0, 0, 7, 0, on_edge, 1, lone, lone, lone});
    compute_angle_weighted_normals(m);
    for (int k = 0; k < 8; ++k) expect_near(m.normals[k], reference[k], 0.0f);
    expect_near(m.normals[lone], {0.0f, 1.0f, 0.0f}, 0.0f);
    expect_near(m.normals[on_edge], {0.0f, 1.0f, 0.0f}, 0.0f);
}

TEST(AngleWeightedNormals, UnreferencedVertexAndCancellingFacesGetUp) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {7, 7, 7}};
    // The same triangle with both windings: the contributions cancel to zero.
    m.indices = {0, 1, 2, 0, 2, 1};
    compute_angle_weighted_normals(m);
    ASSERT_EQ(m.normals.size(), 4u);
    for (const glm::vec3& n : m.normals) expect_near(n, {0.0f, 1.0f, 0.0f}, 0.0f);
}

TEST(AngleWeightedNormals, ReplacesExistingNormalsAndIsUnitLength) {
    Mesh m;
    m.positions = {{0, 0, 0}, {3, 0, 0}, {0, 2, 0}, {0, 0, 5}};
    m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    m.normals = {{9, 9, 9}};
    compute_angle_weighted_normals(m);
    ASSERT_EQ(m.normals.size(), 4u);
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    // Vertex 0 is the right-angled corner of three axis planes; each contributes 90 degrees.
    expect_near(m.normals[0], -glm::normalize(glm::vec3(1.0f)));
}

TEST(FaceNormals, UnitCounterClockwiseAndUpForDegenerate) {
    Mesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {4, 0, 0}};
    m.indices = {0, 1, 2, 0, 2, 1, 0, 1, 3};
    const auto n = compute_face_normals(m);
    ASSERT_EQ(n.size(), 3u);
    expect_near(n[0], {0.0f, 0.0f, 1.0f}, 0.0f);
    expect_near(n[1], {0.0f, 0.0f, -1.0f}, 0.0f);
    expect_near(n[2], {0.0f, 1.0f, 0.0f}, 0.0f);
}

TEST(UpdateBounds, BoxOfPositions) {
    Mesh m;
    m.positions = {{1, -2, 3}, {-4, 5, 0.5f}};
    update_bounds(m);
    EXPECT_EQ(m.bounds.lo, glm::vec3(-4, -2, 0.5f));
    EXPECT_EQ(m.bounds.hi, glm::vec3(1, 5, 3));
    m.positions.clear();
    update_bounds(m);
    EXPECT_TRUE(m.bounds.empty());
}

}  // namespace
}  // namespace zraster
