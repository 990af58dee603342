// The painter's algorithm (Newell, Newell & Sancha): operation counts on small cases whose
// answer is known, and the cases a plain depth sort gets wrong (cyclic overlap,
// interpenetration), which must come out exactly right away from edges.
#include <gtest/gtest.h>

#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

struct Painted {
    PainterResult sorted;
    RenderTargets image;
};

Painted paint(const Scene& scene, const RenderOptions& options) {
    Painted p;
    p.sorted = painter_sort(project_scene(scene, options), {options.width, options.height});
    p.image = paint_polygons(p.sorted.order, options, *options.camera);
    return p;
}

RenderOptions front_options(CullMode cull = CullMode::Back) {
    RenderOptions o = id_options(320, 240);
    o.camera = front_camera();
    o.cull = cull;
    return o;
}

TEST(Painter, DepthSeparatedPairNeedsOneComparison) {
    const Scene scene =
        scene_from_triangles({flat_triangle(-1, -1, 2, 1.0f), flat_triangle(-1.5, -1.5, 2, -1.0f)});
    const Painted p = paint(scene, front_options());
    const PainterStats& s = p.sorted.stats;
    EXPECT_EQ(s.comparisons, 1u);
    EXPECT_EQ(s.resolved_by[0], 1u);  // depth extents
    EXPECT_EQ(s.swaps, 0u);
    EXPECT_EQ(s.splits, 0u);
    ASSERT_EQ(p.sorted.order.size(), 2u);
    EXPECT_EQ(p.sorted.order[0].instance, 1);  // the farther one first
}

TEST(Painter, SideBySidePairIsSettledByTheXExtents) {
    // Equal depth ranges (both tilted the same way), apart on screen.
    const Scene scene = scene_from_triangles(
        {{{-3, -1, -1}, {-1, -1, -1}, {-2, 1, 1}}, {{1, -1, -1}, {3, -1, -1}, {2, 1, 1}}});
    const Painted p = paint(scene, front_options());
    EXPECT_EQ(p.sorted.stats.comparisons, 1u);
    EXPECT_EQ(p.sorted.stats.resolved_by[1], 1u);
    EXPECT_EQ(p.sorted.stats.swaps, 0u);
}

TEST(Painter, SteepPolygonInFrontIsSwappedOnce) {
    // P reaches farther than Q (so the sort puts it first) but lies in front of Q where they
    // overlap: one swap, no split. Then Q (moved) against P: Q is behind P's plane (test 4).
    const Scene scene = scene_from_triangles(
        {{{-2, -3, -2}, {2, -3, -2}, {0, 3, 2}}, {{-0.5f, 1, 0}, {0.5f, 1, 0}, {0, 2.5f, 0}}});
    const Painted p = paint(scene, front_options());
    const PainterStats& s = p.sorted.stats;
    EXPECT_EQ(s.swaps, 1u);
    EXPECT_EQ(s.splits, 0u);
    EXPECT_EQ(s.comparisons, 2u);
    EXPECT_EQ(s.resolved_by[3], 1u);
    ASSERT_EQ(p.sorted.order.size(), 2u);
    EXPECT_EQ(p.sorted.order[0].instance, 1);  // Q first after all

    const RenderResult z =
        render_with_visibility(scene, front_options(), VisibilityAlgorithm::ZBuffer);
    EXPECT_EQ(compare_ids(z.targets, p.image).differing, 0u);
}

TEST(Painter, InterpenetratingPairIsSplitOnce) {
    const Scene scene = scene_from_triangles(interpenetrating_pair());
    const RenderOptions options = front_options(CullMode::None);
    const Painted p = paint(scene, options);
    EXPECT_EQ(p.sorted.stats.splits, 1u);
    EXPECT_EQ(p.sorted.stats.cycle_splits, 0u);
    EXPECT_EQ(p.sorted.order.size(), 3u);

    const RenderResult z = render_with_visibility(scene, options, VisibilityAlgorithm::ZBuffer);
    const IdAgreement good = compare_ids(z.targets, p.image);
    EXPECT_EQ(good.differing_interior, 0u);
    // Only pixel centers within rounding of the intersection line may differ.
    EXPECT_LE(good.differing, 4u);

    // Without the split, one triangle is wholly in front of the other: half the overlap is wrong.
    const RenderTargets naive = paint_polygons(
        sort_by_farthest_depth(project_scene(scene, options)), options, *options.camera);
    EXPECT_GT(compare_ids(z.targets, naive).differing_interior, 200u);
}

TEST(Painter, CyclicOverlapIsSplitAndExactAwayFromEdges) {
    const Scene scene = scene_from_triangles(cyclic_sticks());
    const RenderOptions options = front_options();
    const RenderResult z = render_with_visibility(scene, options, VisibilityAlgorithm::ZBuffer);
    // The cycle is really there: each stick is on top somewhere and underneath somewhere else.
    for (std::int32_t k = 0; k < 3; ++k) {
        std::size_t seen = 0;
        for (const std::int32_t id : z.targets.instance_id) seen += id == k;
        EXPECT_GT(seen, 500u) << k;
    }

    // Moves until a moved stick must move again: the cycle is cut by exactly one split.
    const Painted p = paint(scene, options);
    EXPECT_GE(p.sorted.stats.swaps, 2u);
    EXPECT_EQ(p.sorted.stats.cycle_splits, 1u);
    EXPECT_EQ(p.sorted.stats.splits, 1u);
    EXPECT_EQ(p.sorted.order.size(), 4u);
    const IdAgreement good = compare_ids(z.targets, p.image);
    EXPECT_EQ(good.differing_interior, 0u);
    EXPECT_EQ(good.differing, 0u);

    // Any order of the three unsplit sticks is wrong on one of the three overlaps: the plain depth
    // sort paints one stick over another where it should be under it (this is what makes the test
    // able to fail).
    const RenderTargets naive = paint_polygons(
        sort_by_farthest_depth(project_scene(scene, options)), options, *options.camera);
    EXPECT_GT(compare_ids(z.targets, naive).differing_interior, 50u);
}

TEST(Painter, SoupNaiveSortIsWrongWhereTheAlgorithmIsRight) {
    const Scene scene = scene_from_meshes({make_interpenetrating_soup(500, 0.2, 3)});
    RenderOptions options = id_options(240, 180);
    options.cull = CullMode::None;
    options.camera = effective_camera(scene, options);
    const RenderResult z = render_with_visibility(scene, options, VisibilityAlgorithm::ZBuffer);
    const Painted p = paint(scene, options);
    EXPECT_GT(p.sorted.stats.splits, 100u);
    EXPECT_EQ(p.sorted.stats.unresolved, 0u);
    EXPECT_EQ(compare_ids(z.targets, p.image).differing_interior, 0u);
    const RenderTargets naive = paint_polygons(
        sort_by_farthest_depth(project_scene(scene, options)), options, *options.camera);
    const IdAgreement bad = compare_ids(z.targets, naive);
    EXPECT_GT(bad.fraction(), 0.01);
}

TEST(Painter, SplitPiecesKeepTheirIdentityAndCoverExactlyTheOriginal) {
    // The interpenetrating pair drawn alone, one triangle at a time: the pieces of a split
    // triangle must cover the same pixels as the triangle (no crack, no overlap along the cut).
    const Scene scene = scene_from_triangles(interpenetrating_pair());
    const RenderOptions options = front_options(CullMode::None);
    const Painted p = paint(scene, options);
    for (std::int32_t k = 0; k < 2; ++k) {
        std::vector<ScreenPolygon> whole, pieces;
        for (const ScreenPolygon& s : project_scene(scene, options))
            if (s.instance == k) whole.push_back(s);
        for (const ScreenPolygon& s : p.sorted.order)
            if (s.instance == k) pieces.push_back(s);
        const RenderTargets a = paint_polygons(whole, options, *options.camera);
        const RenderTargets b = paint_polygons(pieces, options, *options.camera);
        // Outline pixels may move where a new vertex on the outline snaps (half a subpixel).
        EXPECT_LE(compare_ids(a, b).differing, 2u) << k;
        EXPECT_EQ(compare_ids(a, b).differing_interior, 0u) << k;
    }
}

}  // namespace
}  // namespace zraster::test
