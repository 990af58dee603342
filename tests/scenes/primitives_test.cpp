// Primitives checked for what a renderer relies on: closed, consistently counter-clockwise from
// outside, and enclosing the right volume.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numbers>

namespace zraster {
namespace {

constexpr double pi = std::numbers::pi;

// Sum of dot(a, cross(b, c)) / 6: the enclosed volume, positive when the triangles face outwards.
double signed_volume(const Mesh& m) {
    double v = 0.0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::dvec3 a{m.positions[m.indices[t]]}, b{m.positions[m.indices[t + 1]]},
            c{m.positions[m.indices[t + 2]]};
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

// Every edge, after welding vertices with equal positions (UV seams duplicate them), must be
// used by exactly two triangles, once in each direction: closed and consistently oriented.
void expect_closed_and_oriented(const Mesh& m) {
    std::map<std::array<float, 3>, std::uint32_t> welded_ids;
    std::vector<std::uint32_t> weld(m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        const std::array<float, 3> key{m.positions[v].x, m.positions[v].y, m.positions[v].z};
        weld[v] = welded_ids.emplace(key, std::uint32_t(welded_ids.size())).first->second;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const std::uint32_t w[3] = {weld[m.indices[t]], weld[m.indices[t + 1]],
                                    weld[m.indices[t + 2]]};
        ASSERT_TRUE(w[0] != w[1] && w[1] != w[2] && w[2] != w[0])
            << "degenerate triangle " << t / 3;
        for (int k = 0; k < 3; ++k) ++directed[{w[k], w[(k + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        EXPECT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " used twice";
        const auto reverse = directed.find({edge.second, edge.first});
        EXPECT_TRUE(reverse != directed.end() && reverse->second == 1)
            << "edge " << edge.first << "-" << edge.second << " has no opposite";
    }
}

void expect_attributes(const Mesh& m) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    ASSERT_EQ(m.uvs.size(), m.positions.size());
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    for (const std::uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
    EXPECT_FALSE(m.bounds.empty());
}

TEST(UvSphere, ClosedOrientedAndVolume) {
    const double r = 1.5;
    const Mesh m = make_uv_sphere(float(r), 32, 64);
    expect_attributes(m);
    expect_closed_and_oriented(m);
    EXPECT_EQ(m.vertex_count(), 33u * 65u);
    EXPECT_EQ(m.triangle_count(), 2u * 64u * (32u - 1u));  // one triangle per pole quad
    const double exact = 4.0 / 3.0 * pi * r * r * r;
    const double v = signed_volume(m);
    EXPECT_GT(v, 0.0);
    EXPECT_LT(v, exact);  // inscribed polyhedron
    EXPECT_NEAR(v, exact, 0.01 * exact);
    // Finer tessellation converges.
    EXPECT_NEAR(signed_volume(make_uv_sphere(float(r), 128, 256)), exact, 0.001 * exact);
}

TEST(UvSphere, NormalsPointOutwardsAndUvsCoverTheImage) {
    const Mesh m = make_uv_sphere(2.0f, 8, 16);
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        EXPECT_NEAR(glm::length(m.positions[v] - 2.0f * m.normals[v]), 0.0f, 1e-6f);
        EXPECT_GE(m.uvs[v].x, 0.0f);
        EXPECT_LE(m.uvs[v].x, 1.0f);
    }
    EXPECT_EQ(m.uvs.front(), glm::vec2(0, 0));  // north pole at the image's top row
    EXPECT_EQ(m.uvs.back(), glm::vec2(1, 1));
    EXPECT_EQ(m.positions.front(), glm::vec3(0, 2, 0));
}

TEST(Box, TwentyFourVerticesClosedExactVolume) {
    const glm::vec3 h{1.0f, 2.0f, 0.5f};
    const Mesh m = make_box(h);
    expect_attributes(m);
    expect_closed_and_oriented(m);
    EXPECT_EQ(m.vertex_count(), 24u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(signed_volume(m), 8.0 * 1.0 * 2.0 * 0.5);
    EXPECT_EQ(m.bounds.lo, -h);
    EXPECT_EQ(m.bounds.hi, h);
    // Per-face normals agree with the triangles' winding.
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
        for (int k = 0; k < 3; ++k) EXPECT_EQ(m.normals[m.indices[t + k]], face);
    }
}

TEST(Torus, ClosedOrientedAndVolume) {
    const double big = 2.0, small = 0.5;
    const Mesh m = make_torus(float(big), float(small), 64, 32);
    expect_attributes(m);
    expect_closed_and_oriented(m);
    EXPECT_EQ(m.triangle_count(), 2u * 64u * 32u);
    const double exact = 2.0 * pi * pi * big * small * small;
    const double v = signed_volume(m);
    EXPECT_GT(v, 0.0);
    EXPECT_NEAR(v, exact, 0.01 * exact);
    EXPECT_NEAR(signed_volume(make_torus(float(big), float(small), 256, 128)), exact,
                0.001 * exact);
    // Normals point away from the tube's center circle.
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const glm::vec3 p = m.positions[i];
        const glm::vec3 ring = float(big) * glm::normalize(glm::vec3(p.x, 0.0f, p.z));
        EXPECT_NEAR(glm::length(p - ring - float(small) * m.normals[i]), 0.0f, 1e-5f);
    }
}

TEST(GroundPlane, FacesUpWithRepeatedUvs) {
    const Mesh m = make_ground_plane(10.0f, 4.0f);
    expect_attributes(m);
    EXPECT_EQ(m.triangle_count(), 2u);
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
    }
    EXPECT_EQ(m.bounds.lo, glm::vec3(-5, 0, -5));
    EXPECT_EQ(m.bounds.hi, glm::vec3(5, 0, 5));
    float max_u = 0.0f;
    for (const glm::vec2& uv : m.uvs) max_u = std::max(max_u, uv.x);
    EXPECT_EQ(max_u, 4.0f);
}

}  // namespace
}  // namespace zraster
