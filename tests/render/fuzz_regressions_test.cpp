// Frames fuzz_pipeline (fuzz/, RELIABILITY.md) found to overrun memory or to reach undefined
// behaviour, minimized and kept inline.
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace zraster {
namespace {

Scene cube_scene() {
    return make_procedural_scene("builtin:cube");
}

// A reused Renderer kept the color, normal and id targets of an earlier, smaller frame when the
// next frame did not ask for them; tile clearing then wrote the new size into them
// (heap-buffer-overflow in clear_tile_targets).
TEST(FuzzRegressions, ReusedRendererWithSmallerEarlierTargets) {
    const Scene scene = cube_scene();
    Renderer renderer;
    RenderOptions small;
    small.width = 8;
    small.height = 8;
    small.threads = 1;
    small.normal_target = true;
    small.id_targets = true;
    small.coverage_counts = true;
    renderer.render(scene, small);

    RenderOptions large;
    large.width = 96;
    large.height = 80;
    large.threads = 2;
    large.color_target = false;
    const RenderResult& reused = renderer.render(scene, large);
    const RenderResult fresh = render(scene, large);
    EXPECT_TRUE(reused.targets.color.empty());
    EXPECT_TRUE(reused.targets.normal.empty());
    EXPECT_TRUE(reused.targets.instance_id.empty());
    EXPECT_TRUE(reused.targets.front_hits.empty());
    EXPECT_EQ(reused.targets.depth, fresh.targets.depth);

    // And back: every target again, at the small size, identical to a fresh renderer's.
    const RenderResult& again = renderer.render(scene, small);
    const RenderResult fresh_small = render(scene, small);
    EXPECT_EQ(again.targets.color, fresh_small.targets.color);
    EXPECT_EQ(again.targets.primitive_id, fresh_small.targets.primitive_id);
    EXPECT_EQ(again.targets.front_hits, fresh_small.targets.front_hits);
}

// Shininess 1e30, inf or NaN was converted to int before its range was checked (undefined
// behaviour, reported by UBSan in specular_power and phong_kernel_applies). Now such exponents
// take the pow() path; the frame renders on the scalar and SIMD paths alike.
TEST(FuzzRegressions, NonFiniteShininess) {
    for (float shininess : {1e30f, std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN(), -5.0f, 4097.0f}) {
        for (bool simd : {false, true}) {
            for (ShadingMode mode : {ShadingMode::Phong, ShadingMode::Gouraud}) {
                SCOPED_TRACE(testing::Message() << shininess << " simd " << simd);
                Scene scene = cube_scene();
                for (Material& m : scene.materials) m.shininess = shininess;
                RenderOptions o;
                o.width = 32;
                o.height = 24;
                o.simd = simd;
                o.shading = mode;
                const RenderResult r = render(scene, o);
                EXPECT_EQ(r.targets.color.size(), 32u * 24u * 4u);
            }
        }
    }
}

}  // namespace
}  // namespace zraster
