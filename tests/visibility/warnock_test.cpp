// Warnock's area subdivision: polygon-region classification (exact, with the fill rule) and the
// subdivision counts on cases whose answer is known.
#include <gtest/gtest.h>

#include "visibility/visibility_test_util.hpp"

namespace zraster::test {
namespace {

// A polygon given directly in window coordinates (only what classification looks at).
ScreenPolygon window_polygon(const std::vector<glm::dvec2>& points) {
    ScreenPolygon p;
    for (const glm::dvec2& q : points) {
        PolygonVertex v;
        v.window = {q.x, q.y, 0.5};
        v.snapped = snap_to_grid(q);
        p.vertices.push_back(v);
    }
    return p;
}

ScreenPolygon window_rect(double x0, double y0, double x1, double y1) {
    return window_polygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

TEST(WarnockClassify, TheFourRelations) {
    const PixelRegion r{0, 0, 10, 10};  // pixel centers 0.5 .. 9.5
    EXPECT_EQ(classify_polygon(window_rect(-5, -5, 20, 20), r), RegionRelation::Surrounding);
    EXPECT_EQ(classify_polygon(window_polygon({{2, 2}, {5, 2}, {3, 5}}), r),
              RegionRelation::Contained);
    EXPECT_EQ(classify_polygon(window_rect(30, 30, 40, 40), r), RegionRelation::Disjoint);
    EXPECT_EQ(classify_polygon(window_rect(5, 5, 15, 15), r), RegionRelation::Intersecting);
    // Either winding.
    EXPECT_EQ(classify_polygon(window_polygon({{-5, -5}, {-5, 20}, {20, 20}, {20, -5}}), r),
              RegionRelation::Surrounding);
}

TEST(WarnockClassify, FollowsTheTopLeftRuleAtCornerCenters) {
    const PixelRegion r{0, 0, 10, 10};
    // Left edge exactly through the left column of centers: a left edge covers them.
    EXPECT_EQ(classify_polygon(window_rect(0.5, -5, 20, 20), r), RegionRelation::Surrounding);
    // Right edge exactly through the right column of centers: a right edge does not.
    EXPECT_EQ(classify_polygon(window_rect(-5, -5, 9.5, 20), r), RegionRelation::Intersecting);
    // Top edge through the top row: covered; bottom edge through the bottom row: not.
    EXPECT_EQ(classify_polygon(window_rect(-5, 0.5, 20, 20), r), RegionRelation::Surrounding);
    EXPECT_EQ(classify_polygon(window_rect(-5, -5, 20, 9.5), r), RegionRelation::Intersecting);
    // Touching the center rectangle from outside is not disjoint (it may cover a center)...
    EXPECT_EQ(classify_polygon(window_rect(9.5, 2, 12, 4), r), RegionRelation::Intersecting);
    // ...but just beyond it is.
    EXPECT_EQ(classify_polygon(window_rect(9.51, 2, 12, 4), r), RegionRelation::Disjoint);
}

TEST(WarnockClassify, SeparatedByAnEdgeNotByTheBoundingBox) {
    const PixelRegion r{0, 0, 10, 10};
    // The bounding box overlaps the region's corner; the hypotenuse x + y = -2 separates them.
    EXPECT_EQ(classify_polygon(window_polygon({{-5, 3}, {3, -5}, {-5, -5}}), r),
              RegionRelation::Disjoint);
    // Moved so the hypotenuse x + y = 2 passes beyond the corner center (0.5, 0.5).
    EXPECT_EQ(classify_polygon(window_polygon({{-5, 7}, {7, -5}, {-5, -5}}), r),
              RegionRelation::Intersecting);
}

TEST(WarnockClassify, SinglePixelRegion) {
    const PixelRegion pixel{3, 4, 4, 5};  // center (3.5, 4.5)
    EXPECT_EQ(classify_polygon(window_rect(3, 4, 4, 5), pixel), RegionRelation::Surrounding);
    // Inside the pixel but away from its center: covers nothing the rasterizer samples.
    EXPECT_EQ(classify_polygon(window_rect(3.6, 4.1, 3.9, 4.9), pixel), RegionRelation::Disjoint);
    // Inside the pixel with its right edge through the center: touches it, does not cover it.
    EXPECT_EQ(classify_polygon(window_rect(3, 4, 3.5, 5), pixel), RegionRelation::Contained);
    EXPECT_EQ(classify_polygon(window_rect(3.6, 0, 9, 9), pixel), RegionRelation::Disjoint);
}

struct Case {
    WarnockResult warnock;
    RenderResult zbuffer;
};

Case run(const std::vector<std::vector<glm::vec3>>& triangles) {
    const Scene scene = scene_from_triangles(triangles);
    RenderOptions options = id_options(320, 240);
    options.camera = front_camera();
    Case c;
    c.warnock = warnock_render(project_scene(scene, options), options, *options.camera);
    c.zbuffer = render_with_visibility(scene, options, VisibilityAlgorithm::ZBuffer);
    return c;
}

// Covers the whole view of front_camera() at any depth near 0.
std::vector<glm::vec3> screen_filling(float depth) {
    return {{-40, -40, depth}, {40, -40, depth}, {0, 40, depth}};
}

std::uint64_t sum(const std::array<std::uint64_t, 4>& a) {
    return a[0] + a[1] + a[2] + a[3];
}

TEST(Warnock, SinglePolygonTerminatesAtLevelZero) {
    const Case c = run({flat_triangle(-1, -1, 2, 0)});
    const WarnockStats& s = c.warnock.stats;
    EXPECT_EQ(s.regions_per_level, std::vector<std::uint64_t>{1});
    EXPECT_EQ(s.subdivisions_per_level, std::vector<std::uint64_t>{0});
    EXPECT_EQ(s.single_leaves, 1u);
    EXPECT_EQ(sum(s.classifications), 1u);
    EXPECT_EQ(s.classifications[std::size_t(RegionRelation::Contained)], 1u);
    EXPECT_EQ(compare_ids(c.zbuffer.targets, c.warnock.targets).differing, 0u);
}

TEST(Warnock, ScreenFillingPolygonSurroundsTheViewport) {
    const Case c = run({screen_filling(0)});
    EXPECT_EQ(c.warnock.stats.regions_per_level, std::vector<std::uint64_t>{1});
    EXPECT_EQ(c.warnock.stats.classifications[std::size_t(RegionRelation::Surrounding)], 1u);
    EXPECT_EQ(c.warnock.stats.single_leaves, 1u);
    EXPECT_EQ(compare_ids(c.zbuffer.targets, c.warnock.targets).differing, 0u);
}

TEST(Warnock, NearSurroundingPolygonHidesEverythingAtLevelZero) {
    const Case c = run({flat_triangle(-1, -1, 2, -1), screen_filling(1)});
    const WarnockStats& s = c.warnock.stats;
    EXPECT_EQ(s.regions_per_level, std::vector<std::uint64_t>{1});
    EXPECT_EQ(s.surrounded_leaves, 1u);
    EXPECT_EQ(s.classifications[std::size_t(RegionRelation::Surrounding)], 1u);
    EXPECT_EQ(s.classifications[std::size_t(RegionRelation::Contained)], 1u);
    EXPECT_EQ(compare_ids(c.zbuffer.targets, c.warnock.targets).differing, 0u);
}

TEST(Warnock, TwoPolygonsInSeparateQuadrantsNeedOneSubdivision) {
    // Both in the top half, one in each of the top quadrants (the image is 320 x 240; world x of
    // +-1 to +-3 and y of 0.5 to 2.5 land well inside them).
    const Case c = run({flat_triangle(-3, 0.5, 2, 0), flat_triangle(1, 0.5, 2, 0)});
    const WarnockStats& s = c.warnock.stats;
    EXPECT_EQ(s.regions_per_level, (std::vector<std::uint64_t>{1, 4}));
    EXPECT_EQ(s.subdivisions_per_level, (std::vector<std::uint64_t>{1, 0}));
    EXPECT_EQ(s.single_leaves, 2u);
    EXPECT_EQ(s.empty_leaves, 2u);
    EXPECT_EQ(s.pixel_leaves, 0u);
    EXPECT_EQ(compare_ids(c.zbuffer.targets, c.warnock.targets).differing, 0u);
}

TEST(Warnock, FarBackgroundIsSubdividedAroundTheNearPolygon) {
    const Case c = run({screen_filling(-1), {{-1, -1, 1}, {1.3f, -0.8f, 1}, {-0.6f, 1.1f, 1}}});
    const WarnockStats& s = c.warnock.stats;
    EXPECT_EQ(s.subdivisions_per_level[0], 1u);
    // Inside the near triangle, and away from it, regions end surrounded by one polygon in front;
    // its edges are followed down to single pixels (level 9 at 320 x 240), where the triangle
    // either covers the pixel center (surrounds the pixel) or does not touch it.
    EXPECT_GT(s.surrounded_leaves, 200u);
    EXPECT_EQ(s.regions_per_level.size(), 10u);
    EXPECT_EQ(compare_ids(c.zbuffer.targets, c.warnock.targets).differing, 0u);
}

TEST(Warnock, PixelCentersOnAnEdgeAreDecidedAtPixelLeavesByTheFillRule) {
    // The hypotenuse of this triangle runs at 45 degrees through a diagonal of pixel centers
    // (window x - y = 40 exactly). There the near triangle touches each center without covering
    // it (a right edge): only the single-pixel leaf can decide, and it must agree with the
    // rasterizer's fill rule.
    const Case c = run({screen_filling(-1), flat_triangle(-1, -1, 2, 1)});
    EXPECT_GT(c.warnock.stats.pixel_leaves, 50u);
    EXPECT_EQ(compare_ids(c.zbuffer.targets, c.warnock.targets).differing, 0u);
}

}  // namespace
}  // namespace zraster::test
