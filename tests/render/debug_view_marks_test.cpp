// The debug views that mark surfaces (backfaces, clipped, zfight) and the mip view: each marks
// exactly the pixels the pipeline's own decisions say.
#include <zraster/debug_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "debug_view_test_util.hpp"

namespace zraster::test {
namespace {

// What the marking views make of a shaded color: a quarter of it, three quarters of the tint.
ViewRgb tint_of(ViewRgb c, ViewRgb tint) {
    ViewRgb out{};
    for (std::size_t k = 0; k < 3; ++k) out[k] = std::uint8_t((c[k] + 3 * tint[k]) / 4);
    return out;
}

TEST(DebugViewMarks, BackfacesTintExactlyTheBackHits) {
    // Side by side, no overlap: the left quad faces the eye, the right one away.
    const Scene scene = scene_from_triangles(
        {quad(-1.6f, -1, -0.1f, 1, 0.0f, true), quad(0.1f, -1, 1.6f, 1, 0.0f, false)});
    RenderOptions plain = view_options(200, 150, DebugView::None);
    plain.camera = looking_down_z(3.0, 0.5, 10.0);
    plain.cull = CullMode::None;
    plain.coverage_counts = true;
    const RenderResult shaded = render(scene, plain);
    RenderOptions o = plain;
    o.view = DebugView::Backfaces;
    const RenderResult r = render(scene, o);
    int back = 0;
    for (int py = 0; py < 150; ++py)
        for (int px = 0; px < 200; ++px) {
            const std::size_t at = std::size_t(py) * 200 + std::size_t(px);
            const bool is_back = shaded.targets.back_hits[at] > 0;
            ASSERT_FALSE(is_back && shaded.targets.front_hits[at] > 0);
            back += is_back;
            const ViewRgb c = pixel(shaded.targets, px, py);
            ASSERT_EQ(pixel(r.targets, px, py), is_back ? tint_of(c, {230, 40, 40}) : c)
                << px << "," << py;
        }
    EXPECT_GT(back, 1000);
}

TEST(DebugViewMarks, ClippedTintsTrianglesCrossingTheNearPlane) {
    // The ground runs under and behind the eye (its two triangles cross the near plane); the
    // box stands in front of it, clear of the near plane.
    Scene scene = scene_from_meshes({make_ground_plane(40.0f, 1.0f), make_box(glm::vec3(0.5f))});
    scene.instances[1].transform = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0.5f, 0));
    RenderOptions plain = view_options(200, 150, DebugView::None);
    plain.camera = low_camera();
    plain.id_targets = true;
    const RenderResult shaded = render(scene, plain);
    ASSERT_GT(shaded.stats.triangles_clipped, 0u);
    RenderOptions o = plain;
    o.view = DebugView::Clipped;
    const RenderResult r = render(scene, o);
    int ground = 0, box = 0;
    for (int py = 0; py < 150; ++py)
        for (int px = 0; px < 200; ++px) {
            const std::size_t at = std::size_t(py) * 200 + std::size_t(px);
            const int instance = shaded.targets.instance_id[at];
            const ViewRgb c = pixel(shaded.targets, px, py);
            ground += instance == 0;
            box += instance == 1;
            ASSERT_EQ(pixel(r.targets, px, py), instance == 0 ? tint_of(c, {0, 200, 255}) : c)
                << px << "," << py;
        }
    EXPECT_GT(ground, 1000);
    EXPECT_GT(box, 100);
}

int zfight_marks(const Scene& scene, RenderOptions o, RenderResult* out = nullptr) {
    o.view = DebugView::ZFight;
    RenderResult r = render(scene, o);
    int marked = 0;
    for (int py = 0; py < o.height; ++py)
        for (int px = 0; px < o.width; ++px)
            marked += pixel(r.targets, px, py) == ViewRgb{255, 0, 0};
    EXPECT_EQ(r.stats.view_scale.high, double(marked));
    if (out != nullptr) *out = std::move(r);
    return marked;
}

TEST(DebugViewMarks, ZFightMarksNearlyCoplanarQuadsWithD16) {
    const Scene scene = zfight_scene();
    RenderOptions o = view_options(200, 150, DebugView::None);
    o.camera = looking_down_z(3.0, 1.0, 10.0);
    o.id_targets = true;
    o.depth_format = DepthFormat::D16;
    RenderResult r;
    const int marked = zfight_marks(scene, o, &r);
    EXPECT_GT(marked, 100);
    // Only where the near quad should win: inside it, where the far one shows instead.
    for (int py = 0; py < 150; ++py)
        for (int px = 0; px < 200; ++px)
            if (pixel(r.targets, px, py) == ViewRgb{255, 0, 0}) {
                ASSERT_EQ(r.targets.instance_id[std::size_t(py) * 200 + std::size_t(px)], 0);
            }
    o.depth_format = DepthFormat::D32F;
    EXPECT_EQ(zfight_marks(scene, o), 0);
}

TEST(DebugViewMarks, ZFightMarksNothingWithoutCoplanarSurfaces) {
    const Scene scene = make_procedural_scene("sphere:2000");
    RenderOptions o = view_options(200, 150, DebugView::None);
    EXPECT_EQ(zfight_marks(scene, o), 0);
    o.depth_format = DepthFormat::D24;
    EXPECT_EQ(zfight_marks(scene, o), 0);
}

TEST(DebugViewMarks, MipLevelGrowsWithDistance) {
    const Scene scene = textured_plane_scene();
    RenderOptions o = view_options(200, 150, DebugView::Mip);
    o.camera = low_camera();
    const RenderResult r = render(scene, o);
    const int coarsest = int(r.stats.view_scale.high);
    EXPECT_EQ(coarsest, 8);  // a 256 x 256 checkerboard
    // Down the middle column from the horizon to the bottom row: nearer, finer.
    double previous = coarsest + 1.0;
    int finer_steps = 0;
    for (int py = 80; py < 150; py += 10) {
        const double level = scale_position(pixel(r.targets, 100, py)) * coarsest;
        EXPECT_LE(level, previous + 0.05) << py;
        finer_steps += level < previous - 0.05;
        previous = level;
    }
    EXPECT_GE(finer_steps, 3);

    o.textures = false;  // untextured: grey
    const RenderResult grey = render(scene, o);
    EXPECT_EQ(pixel(grey.targets, 100, 140), (ViewRgb{128, 128, 128}));
}

}  // namespace
}  // namespace zraster::test
