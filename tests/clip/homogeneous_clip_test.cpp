// Homogeneous Sutherland-Hodgman clipping: kept vertices are inside every plane, their
// barycentric weights reproduce their positions, and shared edges are cut identically.
#include <zraster/clip.hpp>

#include <gtest/gtest.h>

#include <random>

namespace zraster {
namespace {

constexpr std::uint32_t kFrustum =
    kClipDepthMin | kClipDepthMax | kClipLeft | kClipRight | kClipBottom | kClipTop;

glm::vec4 combine(const std::array<glm::vec4, 3>& v, const glm::vec3& w) {
    return v[0] * w.x + v[1] * w.y + v[2] * w.z;
}

TEST(HomogeneousClip, TriangleInsideIsUnchanged) {
    const std::array<glm::vec4, 3> v{glm::vec4(-0.5f, -0.5f, 0, 1), glm::vec4(0.5f, -0.5f, 0, 1),
                                     glm::vec4(0, 0.5f, 0, 1)};
    ClippedPolygon out;
    clip_triangle(v, kFrustum, ClipSettings{}, {}, out);
    ASSERT_EQ(out.count, 3);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(out.vertices[std::size_t(i)].position, v[std::size_t(i)]);
}

TEST(HomogeneousClip, VertexBehindTheEyeIsCutAtTheNearPlane) {
    // One vertex has w < 0 (behind the eye): it can never be divided by w; the clipper must cut
    // the triangle where z = -w first.
    const std::array<glm::vec4, 3> v{glm::vec4(-0.5f, 0, 0.5f, 1), glm::vec4(0.5f, 0, 0.5f, 1),
                                     glm::vec4(0, 0.5f, -3.0f, -1)};
    ClippedPolygon out;
    clip_triangle(v, kFrustum, ClipSettings{}, {}, out);
    ASSERT_EQ(out.count, 4);
    for (int i = 0; i < out.count; ++i) {
        const ClipVertex& c = out.vertices[std::size_t(i)];
        EXPECT_GE(c.position.z + c.position.w, -1e-6f);
        EXPECT_GT(c.position.w, 0.0f);
        const glm::vec4 r = combine(v, c.weights);
        for (int k = 0; k < 4; ++k) EXPECT_NEAR(r[k], c.position[k], 1e-6f);
        EXPECT_NEAR(c.weights.x + c.weights.y + c.weights.z, 1.0f, 1e-6f);
    }
}

TEST(HomogeneousClip, EntirelyOutsideGivesNothing) {
    const std::array<glm::vec4, 3> v{glm::vec4(0, 0, -3, 1), glm::vec4(1, 0, -3, 1),
                                     glm::vec4(0, 1, -3, 1)};
    ClippedPolygon out;
    clip_triangle(v, kFrustum, ClipSettings{}, {}, out);
    EXPECT_EQ(out.count, 0);
}

TEST(HomogeneousClip, SharedEdgeIsCutIdenticallyInBothTriangles) {
    // Two triangles share the edge (a, b), which crosses the near plane; the edge is traversed
    // in opposite directions. The points created on it must be bit-identical.
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    for (int iteration = 0; iteration < 1000; ++iteration) {
        const glm::vec4 a(u(rng), u(rng), u(rng), 1.0f + 0.5f * u(rng));
        const glm::vec4 b(u(rng), u(rng), u(rng), 0.2f * u(rng));
        const glm::vec4 c(u(rng), u(rng), u(rng), 1.5f);
        const glm::vec4 d(u(rng), u(rng), u(rng), 1.5f);
        ClippedPolygon p, q;
        clip_triangle({a, b, c}, kFrustum, ClipSettings{}, {}, p);
        clip_triangle({b, a, d}, kFrustum, ClipSettings{}, {}, q);
        // Points of p that lie on segment ab (weight of c is 0) must also appear in q.
        for (int i = 0; i < p.count; ++i) {
            const ClipVertex& pv = p.vertices[std::size_t(i)];
            if (pv.weights.z != 0.0f) continue;
            bool found = false;
            for (int j = 0; j < q.count; ++j)
                found |= q.vertices[std::size_t(j)].position == pv.position;
            EXPECT_TRUE(found) << "iteration " << iteration;
        }
    }
}

TEST(HomogeneousClip, UserPlaneDistancesTravelWithVertices) {
    // A user plane keeps points with distance >= 0; distances are given per vertex.
    const std::array<glm::vec4, 3> v{glm::vec4(-0.5f, -0.5f, 0, 1), glm::vec4(0.5f, -0.5f, 0, 1),
                                     glm::vec4(0, 0.5f, 0, 1)};
    ClipSettings s;
    s.user_plane_count = 1;
    const std::array<std::array<float, 3>, 1> d{{{1.0f, -1.0f, 1.0f}}};
    ClippedPolygon out;
    clip_triangle(v, kClipUser0, s, d, out);
    ASSERT_EQ(out.count, 4);
    // Vertex 1 is cut away at the midpoints of its two edges.
    for (int i = 0; i < out.count; ++i)
        EXPECT_LE(out.vertices[std::size_t(i)].weights.y, 0.5f + 1e-6f);
}

TEST(HomogeneousClip, OutcodesNameTheViolatedPlanes) {
    ClipSettings s;
    EXPECT_EQ(clip_outcode({0, 0, 0, 1}, s, {}), 0u);
    EXPECT_EQ(clip_outcode({2, 0, 0, 1}, s, {}), std::uint32_t(kClipRight));
    EXPECT_EQ(clip_outcode({0, -2, 0, 1}, s, {}), std::uint32_t(kClipBottom));
    EXPECT_EQ(clip_outcode({0, 0, -2, 1}, s, {}), std::uint32_t(kClipDepthMin));
    EXPECT_EQ(clip_outcode({0, 0, 2, 1}, s, {}), std::uint32_t(kClipDepthMax));
    s.depth_range = ClipDepthRange::ZeroToOne;
    EXPECT_EQ(clip_outcode({0, 0, -0.5f, 1}, s, {}), std::uint32_t(kClipDepthMin));
    // NaN is outside of everything (and the renderer drops it before clipping).
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(clip_outcode({nan, 0, 0, 1}, s, {}) & (kClipLeft | kClipRight),
              kClipLeft | kClipRight);
}

}  // namespace
}  // namespace zraster
