// The debug views that map numbers to the color scale (depth, normals, overdraw, hiz, tiles,
// ids): each picture re-derived from the renderer's own targets and counts, the other targets
// unchanged by the view, and the same picture at any thread count.
#include <zraster/camera.hpp>
#include <zraster/debug_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "debug_view_test_util.hpp"

namespace zraster::test {
namespace {

TEST(DebugViewNames, RoundTripAndLod) {
    for (const DebugView view : debug_views())
        EXPECT_EQ(parse_debug_view(debug_view_name(view)), view);
    EXPECT_EQ(parse_debug_view("lod"), DebugView::Mip);
    EXPECT_FALSE(parse_debug_view("bogus").has_value());
    EXPECT_EQ(debug_view_names().find("none, depth, normals"), 0u);
}

TEST(DebugViewScaleColors, RunFromBlueToYellow) {
    EXPECT_EQ(debug_view_scale_color(0.0), (ViewRgb{13, 8, 135}));
    EXPECT_EQ(debug_view_scale_color(1.0), (ViewRgb{240, 249, 33}));
    EXPECT_EQ(debug_view_scale_color(-1.0), debug_view_scale_color(0.0));
    EXPECT_NEAR(scale_position(debug_view_scale_color(0.3)), 0.3, 0.002);
}

// Depth, normals and ids are those of the frame without the view, for every view.
TEST(DebugViews, LeaveDepthNormalsAndIdsAlone) {
    const Scene scene = make_procedural_scene("city:200");
    RenderOptions plain = view_options(160, 120, DebugView::None);
    plain.normal_target = plain.id_targets = true;
    const RenderResult reference = render(scene, plain);
    for (const DebugView view : debug_views()) {
        RenderOptions o = plain;
        o.view = view;
        const RenderResult r = render(scene, o);
        EXPECT_EQ(r.targets.depth, reference.targets.depth) << debug_view_name(view);
        EXPECT_EQ(r.targets.normal, reference.targets.normal) << debug_view_name(view);
        EXPECT_EQ(r.targets.instance_id, reference.targets.instance_id) << debug_view_name(view);
        EXPECT_EQ(r.targets.primitive_id, reference.targets.primitive_id) << debug_view_name(view);
        EXPECT_EQ(r.stats.fragments_passed, reference.stats.fragments_passed);
        // (city:200 shows no back faces and no clipped triangles: those two are its image.)
        if (view != DebugView::None && view != DebugView::Backfaces && view != DebugView::Clipped) {
            EXPECT_NE(r.targets.color, reference.targets.color) << debug_view_name(view);
        }
    }
}

TEST(DebugViews, SamePictureAtAnyThreadCount) {
    const Scene city = make_procedural_scene("city:200");
    const Scene walls = occluder_scene();
    for (const DebugView view : debug_views()) {
        const Scene& scene = view == DebugView::HiZ ? walls : city;
        RenderOptions o = view_options(200, 150, view);
        if (view == DebugView::HiZ) o.camera = looking_down_z(3.0, 0.5, 10.0);
        if (view == DebugView::ZFight) o.depth_format = DepthFormat::D16;
        o.threads = 1;
        const RenderResult one = render(scene, o);
        for (const int threads : {2, 3}) {
            o.threads = threads;
            const RenderResult r = render(scene, o);
            EXPECT_EQ(r.targets.color, one.targets.color)
                << debug_view_name(view) << " with " << threads << " threads";
            EXPECT_EQ(r.stats.view_scale.high, one.stats.view_scale.high);
        }
    }
}

// A Renderer showing a view, then none, draws the frame as a fresh one does.
TEST(DebugViews, RendererReturnsToTheShadedImage) {
    const Scene scene = make_procedural_scene("sphere:2000");
    const RenderResult plain = render(scene, view_options(130, 100, DebugView::None));
    Renderer renderer;
    (void)renderer.render(scene, view_options(130, 100, DebugView::None));
    (void)renderer.render(scene, view_options(130, 100, DebugView::Tiles));
    EXPECT_EQ(renderer.render(scene, view_options(130, 100, DebugView::None)).targets.color,
              plain.targets.color);
}

TEST(DebugViews, DepthIsLinearEyeDistanceNearYellow) {
    const Scene scene = make_procedural_scene("sphere:2000");
    RenderOptions o = view_options(160, 120, DebugView::Depth);
    o.id_targets = true;
    const RenderResult r = render(scene, o);
    const DebugViewScale scale = r.stats.view_scale;
    ASSERT_LT(scale.low, scale.high);
    int visible = 0;
    for (int py = 0; py < 120; py += 2)
        for (int px = 0; px < 160; px += 2) {
            const std::size_t at = std::size_t(py) * 160 + std::size_t(px);
            if (r.targets.instance_id[at] < 0) continue;
            ++visible;
            const double d = linear_depth(r.stats.camera, r.targets.depth[at]);
            const double t = 1.0 - (d - scale.low) / (scale.high - scale.low);
            ASSERT_NEAR(scale_position(pixel(r.targets, px, py)), t, 0.01) << px << "," << py;
        }
    EXPECT_GT(visible, 250);
}

TEST(DebugViews, NormalsAreTheNormalTargetAsColor) {
    const Scene scene = make_procedural_scene("sphere:2000");
    RenderOptions o = view_options(160, 120, DebugView::Normals);
    o.normal_target = o.id_targets = true;
    const RenderResult r = render(scene, o);
    for (int py = 0; py < 120; ++py)
        for (int px = 0; px < 160; ++px) {
            const std::size_t at = std::size_t(py) * 160 + std::size_t(px);
            if (r.targets.instance_id[at] < 0) continue;
            const glm::vec3 n = r.targets.normal[at] * 0.5f + 0.5f;
            const ViewRgb c = pixel(r.targets, px, py);
            for (std::size_t k = 0; k < 3; ++k)
                ASSERT_NEAR(c[k], n[int(k)] * 255.0f, 0.51f) << px << "," << py;
        }
}

// The overdraw view is the coverage count of a frame with the depth test off.
TEST(DebugViews, OverdrawIsTheCoverageCountWithoutDepthTest) {
    const Scene scene = make_procedural_scene("city:200");
    RenderOptions counts = view_options(200, 150, DebugView::None);
    counts.depth_test = false;
    counts.coverage_counts = true;
    counts.color_target = false;
    const RenderResult c = render(scene, counts);
    RenderOptions o = view_options(200, 150, DebugView::Overdraw);
    o.id_targets = true;
    const RenderResult r = render(scene, o);
    std::uint64_t largest = 0;
    for (std::size_t i = 0; i < c.targets.front_hits.size(); ++i)
        largest =
            std::max<std::uint64_t>(largest, c.targets.front_hits[i] + c.targets.back_hits[i]);
    ASSERT_GT(largest, 2u);
    EXPECT_EQ(r.stats.view_scale.high, double(largest));
    for (int py = 0; py < 150; ++py)
        for (int px = 0; px < 200; ++px) {
            const std::size_t at = std::size_t(py) * 200 + std::size_t(px);
            const std::uint64_t n = c.targets.front_hits[at] + c.targets.back_hits[at];
            if (r.targets.instance_id[at] >= 0) {
                ASSERT_GE(n, 1u);
            }
            ASSERT_EQ(pixel(r.targets, px, py), expected_count_color(n, largest))
                << px << "," << py;
        }
}

TEST(DebugViews, HizMarksBlocksBehindALargeOccluder) {
    const Scene scene = occluder_scene();
    RenderOptions o = view_options(256, 192, DebugView::HiZ);
    o.camera = looking_down_z(3.0, 0.5, 10.0);
    const RenderResult r = render(scene, o);
    EXPECT_GT(r.stats.blocks_hidden, 0u);
    EXPECT_GE(r.stats.view_scale.high, 10.0);  // most of the 20 walls, behind the occluder
    // The center block is behind the wall and every wall: it is on the scale, not grey.
    const ViewRgb center = pixel(r.targets, 128, 96);
    EXPECT_NE(center[0], center[2]);

    o.hierarchical_z = false;
    const RenderResult off = render(scene, o);
    EXPECT_EQ(off.stats.blocks_hidden, 0u);
    EXPECT_EQ(off.stats.view_scale.high, 0.0);
    for (int py = 0; py < 192; ++py)
        for (int px = 0; px < 256; ++px) {
            const ViewRgb c = pixel(off.targets, px, py);
            ASSERT_TRUE(c[0] == c[1] && c[1] == c[2]) << px << "," << py;  // grey: none
        }
}

// Small triangles, each inside one 64x64 tile, 0 to 3 per tile: the tiles view shows the count.
TEST(DebugViews, TilesShowTrianglesBinnedPerTile) {
    const int width = 320, height = 192;  // 5 x 3 tiles
    Camera camera = looking_down_z(5.0, 1.0, 10.0);
    const double half_height = 5.0 * std::tan(glm::radians(30.0));
    const double half_width = half_height * width / height;
    const auto world = [&](double px, double py) {
        return glm::vec3(float((px / width * 2.0 - 1.0) * half_width),
                         float((1.0 - py / height * 2.0) * half_height), 0.0f);
    };
    std::vector<glm::vec3> triangles;
    std::map<int, std::uint64_t> expected;
    for (int ty = 0; ty < 3; ++ty)
        for (int tx = 0; tx < 5; ++tx) {
            const int n = (tx + 2 * ty) % 4;
            expected[ty * 5 + tx] = std::uint64_t(n);
            for (int i = 0; i < n; ++i) {
                const double x = tx * 64 + 10 + 16 * i, y = ty * 64 + 20;
                triangles.push_back(world(x, y));
                triangles.push_back(world(x, y + 12));
                triangles.push_back(world(x + 12, y));
            }
        }
    const Scene scene = scene_from_triangles({triangles});
    RenderOptions o = view_options(width, height, DebugView::Tiles);
    o.camera = camera;
    o.cull = CullMode::None;
    const RenderResult r = render(scene, o);
    EXPECT_EQ(r.stats.view_scale.high, 3.0);
    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px)
            ASSERT_EQ(pixel(r.targets, px, py),
                      expected_count_color(expected[py / 64 * 5 + px / 64], 3))
                << px << "," << py;
}

TEST(DebugViews, IdsGiveEachTriangleOneColor) {
    const Scene scene = make_procedural_scene("city:200");
    RenderOptions o = view_options(200, 150, DebugView::Ids);
    o.id_targets = true;
    const RenderResult r = render(scene, o);
    std::map<std::pair<int, int>, ViewRgb> colors;
    std::set<ViewRgb> distinct;
    for (int py = 0; py < 150; ++py)
        for (int px = 0; px < 200; ++px) {
            const std::size_t at = std::size_t(py) * 200 + std::size_t(px);
            const std::pair<int, int> id{r.targets.instance_id[at], r.targets.primitive_id[at]};
            if (id.first < 0) {
                ASSERT_EQ(pixel(r.targets, px, py), (ViewRgb{51, 51, 51}));
                continue;
            }
            const auto [it, inserted] = colors.emplace(id, pixel(r.targets, px, py));
            ASSERT_EQ(it->second, pixel(r.targets, px, py));
            distinct.insert(it->second);
        }
    EXPECT_GT(colors.size(), 50u);
    EXPECT_GT(distinct.size(), colors.size() * 9 / 10);
}

}  // namespace
}  // namespace zraster::test
