// The benchmark generators against BENCH-SCENES.md's reference table: vertex and triangle counts
// and the geometry hash must match the llvmpipe harness bit for bit.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace zraster {
namespace {

TEST(SplitMix64, FirstOutputsForSeedOne) {
    SplitMix64 rng(1);
    EXPECT_EQ(rng.next(), 0x910a2dec89025cc1ull);
    EXPECT_EQ(rng.next(), 0xbeeb8da1658eec67ull);
    EXPECT_EQ(rng.next(), 0xf893a2eefb32555eull);
}

TEST(SplitMix64, UnitIsInHalfOpenInterval) {
    SplitMix64 rng(42);
    for (int i = 0; i < 1000; ++i) {
        const double u = rng.unit();
        EXPECT_GE(u, 0.0);
        EXPECT_LT(u, 1.0);
    }
}

TEST(GeometryHash, EmptyIsTheOffsetBasisAndOrderMatters) {
    Mesh m;
    EXPECT_EQ(geometry_hash(m), 0xcbf29ce484222325ull);
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    const auto h = geometry_hash(m);
    m.indices = {1, 2, 0};
    EXPECT_NE(geometry_hash(m), h);
    // Re-indexing the same corners does not change it.
    m.positions = {{0, 1, 0}, {0, 0, 0}, {9, 9, 9}, {1, 0, 0}};
    m.indices = {1, 3, 0};
    EXPECT_EQ(geometry_hash(m), h);
}

TEST(BenchSphere, ReferenceTable) {
    const Mesh m = make_bench_sphere(1'000'000);
    EXPECT_EQ(m.vertex_count(), 501'501u);
    EXPECT_EQ(m.triangle_count(), 998'000u);
    EXPECT_EQ(geometry_hash(m), 0xa006c80ed0f36341ull);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    EXPECT_EQ(m.normals[12345], m.positions[12345]);  // normal = position on the unit sphere
    EXPECT_NEAR(m.bounds.hi.x, 1.0f, 1e-6f);
}

TEST(BenchSphere, SmallSizesSkipPoleTriangles) {
    // S = max(2, lround(sqrt(N / 4))): N = 1 gives 2 stacks, 4 slices, 4 S (S - 1) = 8 triangles.
    const Mesh m = make_bench_sphere(1);
    EXPECT_EQ(m.vertex_count(), 3u * 5u);
    EXPECT_EQ(m.triangle_count(), 8u);
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        EXPECT_GT(glm::length(glm::cross(b - a, c - a)), 1e-3f);
        // Counter-clockwise from outside: the face normal points away from the center.
        EXPECT_GT(glm::dot(glm::cross(b - a, c - a), a + b + c), 0.0f);
    }
}

TEST(BenchCity, ReferenceTable) {
    const Mesh m = make_bench_city(20'000);
    EXPECT_EQ(m.vertex_count(), 400'004u);
    EXPECT_EQ(m.triangle_count(), 200'002u);
    EXPECT_EQ(geometry_hash(m), 0x2ecc612cd13d8f0eull);
    // Ground first, boxes 1 to 16 high.
    EXPECT_EQ(m.normals[0], glm::vec3(0, 1, 0));
    EXPECT_EQ(m.bounds.lo.y, 0.0f);
    EXPECT_LE(m.bounds.hi.y, 16.0f);
    EXPECT_GT(m.bounds.hi.y, 10.0f);
}

TEST(BenchCity, SeedChangesTheGeometry) {
    EXPECT_EQ(geometry_hash(make_bench_city(10, 1)), geometry_hash(make_bench_city(10)));
    EXPECT_NE(geometry_hash(make_bench_city(10, 2)), geometry_hash(make_bench_city(10, 1)));
}

TEST(BenchSoup, ReferenceTable) {
    const Mesh m = make_bench_soup(1'000'000);
    EXPECT_EQ(m.vertex_count(), 3'000'000u);
    EXPECT_EQ(m.triangle_count(), 1'000'000u);
    EXPECT_EQ(geometry_hash(m), 0xcdc28ecb2e3c4d81ull);
}

TEST(BenchSoup, NormalsFromTheFloatPositions) {
    const Mesh m = make_bench_soup(1000, 7);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); v += 3) {
        const glm::dvec3 a{m.positions[v]}, b{m.positions[v + 1]}, c{m.positions[v + 2]};
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(m.normals[v + k].x, n.x, 1e-6);
            EXPECT_NEAR(m.normals[v + k].y, n.y, 1e-6);
            EXPECT_NEAR(m.normals[v + k].z, n.z, 1e-6);
        }
    }
    // Every corner stays within s = 0.02 of a center inside [-1, 1]^3.
    EXPECT_GE(m.bounds.lo.x, -1.02f);
    EXPECT_LE(m.bounds.hi.z, 1.02f);
}

}  // namespace
}  // namespace zraster
