// BSP trees (Fuchs, Kedem & Naylor): split counts and shapes on cases whose answer is known, the
// depth limit, deep trees without recursion, and one tree reused from several viewpoints.
#include <zraster/error.hpp>

#include <gtest/gtest.h>

#include <cstdio>

#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

BspPolygon make_polygon(const std::vector<glm::dvec3>& points, std::int32_t id) {
    BspPolygon p;
    for (const glm::dvec3& q : points) p.vertices.push_back({q, glm::vec3(q)});
    const glm::dvec3 n = glm::normalize(glm::cross(points[1] - points[0], points[2] - points[0]));
    p.plane = glm::dvec4(n, -glm::dot(n, points[0]));
    p.instance = id;
    p.primitive = 0;
    return p;
}

// count quads in the planes z = 0, 1, 2, ... facing +z.
std::vector<BspPolygon> parallel_quads(int count) {
    std::vector<BspPolygon> out;
    for (int i = 0; i < count; ++i) {
        const double z = i;
        out.push_back(make_polygon({{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}}, i));
    }
    return out;
}

double side_of(const glm::dvec4& plane, const glm::dvec3& p) {
    return glm::dot(glm::dvec3(plane), p) + plane.w;
}

TEST(BspTree, TwoCrossingQuadsSplitExactlyOnce) {
    // In the planes x = 0 and y = 0, crossing along the z axis: whichever is the root, the other
    // crosses its plane.
    const std::vector<BspPolygon> quads = {
        make_polygon({{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}}, 0),
        make_polygon({{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, 1)};
    const BspTree tree = BspTree::build(quads);
    EXPECT_EQ(tree.stats().input_polygons, 2u);
    EXPECT_EQ(tree.stats().splits, 1u);
    EXPECT_EQ(tree.stats().nodes, 3u);
    EXPECT_EQ(tree.stats().depth, 2u);
    EXPECT_EQ(tree.stats().polygons, 3u);

    // Seen from anywhere off both planes: far piece, the unsplit root, near piece.
    for (const glm::dvec3 eye : {glm::dvec3(3, 2, 1), glm::dvec3(-3, 2, 0), glm::dvec3(1, -4, 2)}) {
        const std::vector<std::uint32_t> order = tree.back_to_front(glm::dvec4(eye, 1.0));
        ASSERT_EQ(order.size(), 3u);
        const BspPolygon& root = tree.polygons()[order[1]];
        EXPECT_EQ(root.vertices.size(), 4u);  // not split
        const glm::dvec4 plane = root.plane * (side_of(root.plane, eye) > 0 ? 1.0 : -1.0);
        for (const BspVertex& v : tree.polygons()[order[0]].vertices)
            EXPECT_LE(side_of(plane, v.world), 1e-12);
        for (const BspVertex& v : tree.polygons()[order[2]].vertices)
            EXPECT_GE(side_of(plane, v.world), -1e-12);
    }
}

TEST(BspTree, BalancedSplitterChoiceOnParallelPlanes) {
    // No candidate splits anything; balance picks the middle plane each time.
    const BspTree tree = BspTree::build(parallel_quads(10));
    EXPECT_EQ(tree.stats().splits, 0u);
    EXPECT_EQ(tree.stats().nodes, 10u);
    EXPECT_EQ(tree.stats().depth, 4u);  // ceil(log2(10 + 1))
}

TEST(BspTree, DepthLimitIsAClearError) {
    BspOptions chain;
    chain.candidates = 1;  // always the first polygon: a chain of 10 nodes
    chain.max_depth = 10;
    EXPECT_EQ(BspTree::build(parallel_quads(10), chain).stats().depth, 10u);
    chain.max_depth = 5;
    try {
        BspTree::build(parallel_quads(10), chain);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("max_depth = 5"), std::string::npos) << e.what();
    }
}

TEST(BspTree, DeepChainNeedsNoCallStack) {
    // A chain 5,000 levels deep (building it is quadratic, hence not deeper): the build and the
    // walk use explicit stacks, and the limit is checked on the way down.
    const int n = 5'000;
    BspOptions chain;
    chain.candidates = 1;
    chain.max_depth = 4'000;
    EXPECT_THROW(BspTree::build(parallel_quads(n), chain), InputError);
    chain.max_depth = BspOptions{}.max_depth;
    const BspTree tree = BspTree::build(parallel_quads(n), chain);
    EXPECT_EQ(tree.stats().depth, std::size_t(n));
    const std::vector<std::uint32_t> from_above = tree.back_to_front({0, 0, 1e6, 1});
    const std::vector<std::uint32_t> from_below = tree.back_to_front({0, 0, -1e6, 1});
    ASSERT_EQ(from_above.size(), std::size_t(n));
    ASSERT_EQ(from_below.size(), std::size_t(n));
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(tree.polygons()[from_above[std::size_t(i)]].instance, i);
        EXPECT_EQ(tree.polygons()[from_below[std::size_t(i)]].instance, n - 1 - i);
    }
}

TEST(BspTree, SplitterCandidatesReduceSplits) {
    const Scene scene = scene_from_meshes({make_interpenetrating_soup(500, 0.2, 11)});
    const std::vector<BspPolygon> polygons = bsp_polygons_from_scene(scene);
    BspOptions first;
    first.candidates = 1;
    const BspTree naive = BspTree::build(polygons, first);
    const BspTree chosen = BspTree::build(polygons);
    std::printf("soup:500 splits: first polygon %zu, best of 12 %zu\n", naive.stats().splits,
                chosen.stats().splits);
    EXPECT_LT(chosen.stats().splits, naive.stats().splits);
    // Every split replaces one polygon by two.
    EXPECT_EQ(chosen.stats().polygons, chosen.stats().input_polygons + chosen.stats().splits);
}

TEST(BspTree, OneTreeServesManyViewpoints) {
    // Built once, in world space; every camera (including an orthographic one and one inside the
    // soup) gets a correct back-to-front order from the same tree.
    const Scene scene = scene_from_meshes({make_interpenetrating_soup(800, 0.2, 5)});
    const BspTree tree = BspTree::build(bsp_polygons_from_scene(scene));
    std::vector<Camera> cameras;
    for (const double azimuth : {0.0, 130.0, 250.0}) {
        Camera c = orbit_camera({0, 0, 0}, 4.0, azimuth, 25.0);
        c.near = 0.5;
        c.far = 10.0;
        cameras.push_back(c);
    }
    Camera inside = orbit_camera({0, 0, 0}, 0.3, 40.0, 10.0);
    inside.near = 0.05;
    inside.far = 10.0;
    cameras.push_back(inside);
    Camera ortho = orbit_camera({0, 0, 0}, 4.0, 70.0, -30.0);
    ortho.projection = Camera::Projection::Orthographic;
    ortho.ortho_height = 3.0;
    ortho.near = 0.5;
    ortho.far = 10.0;
    cameras.push_back(ortho);
    for (std::size_t i = 0; i < cameras.size(); ++i) {
        RenderOptions options = id_options(200, 150);
        options.cull = CullMode::None;
        options.camera = cameras[i];
        const RenderResult z = render_with_visibility(scene, options, VisibilityAlgorithm::ZBuffer);
        const RenderResult b = render_bsp(tree, scene, options);
        const IdAgreement a = compare_ids(z.targets, b.targets);
        EXPECT_GT(a.covered, 3000u) << "camera " << i;
        EXPECT_LE(a.fraction(), 0.005) << "camera " << i;
        // Single interior pixels can differ along split lines (T-junction slivers, see
        // agreement_test.cpp); a wrong order over an area cannot hide.
        EXPECT_EQ(a.interior_blocks, 0u) << "camera " << i;
    }
}

}  // namespace
}  // namespace zraster::test
