// The top-left fill rule on hand-built cases where pixel centers lie exactly on edges and
// vertices. Window coordinates are y-down; pixel (x, y) has its center at (x + 0.5, y + 0.5).
#include <gtest/gtest.h>

#include "raster/raster_test_util.hpp"

namespace zraster::test {
namespace {

std::vector<std::pair<int, int>> covered(const CoverageGrid& g) {
    std::vector<std::pair<int, int>> out;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            if (g.at(x, y)) out.emplace_back(x, y);
    return out;
}

TEST(FillRule, SquareWithEdgesThroughPixelCentersCoversTopLeftOnly) {
    // The square [0.5, 2.5]^2 has all four edges through pixel centers: the left and top edges
    // are in, the right and bottom edges are out, so exactly pixels (0..1, 0..1) are covered.
    CoverageGrid g(4, 4);
    ASSERT_TRUE(rasterize_window_triangle(g, {0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}));
    ASSERT_TRUE(rasterize_window_triangle(g, {0.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}));
    const std::vector<std::pair<int, int>> expected{{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    EXPECT_EQ(covered(g), expected);
    for (auto [x, y] : expected) EXPECT_EQ(g.at(x, y), 1) << x << "," << y;
}

TEST(FillRule, DiagonalThroughPixelCentersIsClaimedOnce) {
    // Two triangles share the diagonal (0,0)-(4,4) which passes through 4 pixel centers.
    CoverageGrid g(4, 4);
    ASSERT_TRUE(rasterize_window_triangle(g, {0, 0}, {4, 0}, {4, 4}));
    ASSERT_TRUE(rasterize_window_triangle(g, {0, 0}, {4, 4}, {0, 4}));
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) EXPECT_EQ(g.at(x, y), 1) << x << "," << y;
}

TEST(FillRule, WindingDoesNotChangeCoverage) {
    CoverageGrid cw(6, 6), ccw(6, 6);
    ASSERT_TRUE(rasterize_window_triangle(cw, {0.5, 0.5}, {4.5, 1.5}, {1.5, 4.5}));
    ASSERT_TRUE(rasterize_window_triangle(ccw, {0.5, 0.5}, {1.5, 4.5}, {4.5, 1.5}));
    EXPECT_EQ(cw.hits, ccw.hits);
}

TEST(FillRule, VertexOnPixelCenterSharedByFanIsClaimedOnce) {
    // Eight triangles around the pixel center (3.5, 3.5), which is a vertex of all of them.
    CoverageGrid g(8, 8);
    const glm::dvec2 c{3.5, 3.5};
    const glm::dvec2 ring[8] = {{0.5, 0.5}, {3.5, 0.2}, {6.5, 0.5}, {6.8, 3.5},
                                {6.5, 6.5}, {3.5, 6.8}, {0.5, 6.5}, {0.2, 3.5}};
    for (int i = 0; i < 8; ++i) rasterize_window_triangle(g, c, ring[i], ring[(i + 1) % 8]);
    EXPECT_EQ(g.at(3, 3), 1);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_LE(g.at(x, y), 1) << x << "," << y;
    // Pixels well inside the octagon are covered exactly once.
    for (int y = 1; y <= 5; ++y)
        for (int x = 1; x <= 5; ++x) EXPECT_EQ(g.at(x, y), 1) << x << "," << y;
}

TEST(FillRule, HorizontalEdgeTopIncludedBottomExcluded) {
    // A triangle with a horizontal top edge at y = 1.5 covers row 1; one with a horizontal
    // bottom edge at y = 1.5 does not.
    CoverageGrid top(4, 4), bottom(4, 4);
    ASSERT_TRUE(rasterize_window_triangle(top, {0, 1.5}, {4, 1.5}, {2, 3.9}));
    ASSERT_TRUE(rasterize_window_triangle(bottom, {0, 1.5}, {2, 0.1}, {4, 1.5}));
    EXPECT_EQ(top.at(1, 1), 1);
    EXPECT_EQ(top.at(2, 1), 1);
    EXPECT_EQ(bottom.at(1, 1), 0);
    EXPECT_EQ(bottom.at(2, 1), 0);
}

TEST(FillRule, VerticalEdgeLeftIncludedRightExcluded) {
    CoverageGrid left(4, 4), right(4, 4);
    ASSERT_TRUE(rasterize_window_triangle(left, {1.5, 0}, {3.9, 2}, {1.5, 4}));
    ASSERT_TRUE(rasterize_window_triangle(right, {1.5, 0}, {1.5, 4}, {0.1, 2}));
    EXPECT_EQ(left.at(1, 1), 1);
    EXPECT_EQ(left.at(1, 2), 1);
    EXPECT_EQ(right.at(1, 1), 0);
    EXPECT_EQ(right.at(1, 2), 0);
}

TEST(FillRule, TinyTrianglesBetweenCentersCoverNothing) {
    SetupSettings settings;
    settings.viewport = {8, 8};
    settings.cull = CullMode::None;
    TriangleSetup t;
    const auto r = setup_triangle({window_to_clip(2.6, 2.6, 8, 8), window_to_clip(3.4, 2.6, 8, 8),
                                   window_to_clip(3.0, 3.4, 8, 8)},
                                  settings, t);
    EXPECT_EQ(r, SetupResult::NoCoverage);
}

TEST(FillRule, DegenerateTriangleIsRejected) {
    SetupSettings settings;
    settings.viewport = {8, 8};
    settings.cull = CullMode::None;
    TriangleSetup t;
    const auto r = setup_triangle(
        {window_to_clip(1, 1, 8, 8), window_to_clip(3, 3, 8, 8), window_to_clip(5, 5, 8, 8)},
        settings, t);
    EXPECT_EQ(r, SetupResult::Degenerate);
}

TEST(FillRule, BackFaceCullingFollowsWindingAndFrontFace) {
    SetupSettings settings;
    settings.viewport = {8, 8};
    TriangleSetup t;
    // Counter-clockwise with y up = clockwise in y-down window coordinates.
    const std::array<glm::vec4, 3> ccw{window_to_clip(1, 7, 8, 8), window_to_clip(7, 7, 8, 8),
                                       window_to_clip(4, 1, 8, 8)};
    const std::array<glm::vec4, 3> cw{ccw[0], ccw[2], ccw[1]};
    settings.cull = CullMode::Back;
    EXPECT_EQ(setup_triangle(ccw, settings, t), SetupResult::Visible);
    EXPECT_TRUE(t.front_facing);
    EXPECT_EQ(setup_triangle(cw, settings, t), SetupResult::Culled);
    settings.cull = CullMode::Front;
    EXPECT_EQ(setup_triangle(ccw, settings, t), SetupResult::Culled);
    EXPECT_EQ(setup_triangle(cw, settings, t), SetupResult::Visible);
    settings.front_face = FrontFace::Clockwise;
    EXPECT_EQ(setup_triangle(ccw, settings, t), SetupResult::Visible);
}

}  // namespace
}  // namespace zraster::test
