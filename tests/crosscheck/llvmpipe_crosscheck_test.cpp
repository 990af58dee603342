// zraster against Mesa llvmpipe, pixel for pixel: the same float geometry and MVP drawn by both
// (bench/gl_reference.cpp draws it as ../shared/tools/glbench does) must cover the same pixels,
// up to edge pixels where the two break ties differently, at the same depth.
#include <zraster/bench_workload.hpp>
#include <zraster/camera.hpp>
#include <zraster/load.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <iostream>
#include <memory>
#include <string>

#include "bench/gl_reference.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

constexpr int kWidth = 320, kHeight = 240;

// One context for the whole binary: llvmpipe reads its settings when EGL initializes.
bench::GlContext* gl_context(std::string& why) {
    static std::string failure;
    static const std::unique_ptr<bench::GlContext> context = [] {
        try {
            return std::make_unique<bench::GlContext>(1);
        } catch (const bench::GlUnavailable& e) {
            failure = e.what();
            return std::unique_ptr<bench::GlContext>();
        }
    }();
    why = failure;
    return context.get();
}

#define REQUIRE_LLVMPIPE()                                                          \
    do {                                                                            \
        std::string why;                                                            \
        if (!gl_context(why))                                                       \
            GTEST_SKIP() << "no llvmpipe context (EGL surfaceless, Mesa): " << why; \
    } while (0)

struct Outcome {
    bench::DepthComparison depth;
    bench::ColorComparison color;
};

Outcome render_both(const std::string& spec, BenchMode mode) {
    Scene scene = is_procedural_spec(spec) ? make_procedural_scene(spec) : load_scene(spec);
    apply_bench_shading(scene, mode);
    RenderOptions options = bench_render_options(mode, kWidth, kHeight, 1, true);
    const Camera camera = fit_camera(scene.world_positions());
    options.camera = camera;

    const bench::GlMesh mesh(bench::flatten_scene(scene));
    bench::GlRenderer gl(mesh, mode, kWidth, kHeight, true, camera);
    gl.draw();
    const std::vector<float> gl_depth = gl.read_depth();
    const RenderResult zr = render(scene, options);

    Outcome out;
    out.depth = bench::compare_depth(gl_depth, zr.targets.depth);
    if (mode != BenchMode::Depth)
        out.color =
            bench::compare_color(gl.read_color(), zr.targets.color, gl_depth, zr.targets.depth);
    return out;
}

// Depth: both evaluate the depth plane from the unsnapped window positions (zraster snaps only
// for coverage), so they agree to float rounding: measured max 1.4e-5 (sphere:20000, one pixel)
// and 1.5e-6 (bunny) at 320x240.
constexpr double kMaxDepthDifference = 5e-5;
constexpr double kMinFractionWithin1e5 = 0.999;

void expect_agreement(const Outcome& o) {
    const bench::DepthComparison& d = o.depth;
    ASSERT_GT(d.both_covered, std::size_t(kWidth * kHeight / 20)) << "the scene is not in view";
    EXPECT_GE(d.coverage_agreement(), 0.995)
        << "only llvmpipe covers " << d.only_gl << " pixels, only zraster " << d.only_zraster;
    EXPECT_LT(d.max_abs_difference, kMaxDepthDifference);
    const double within = 1.0 - double(d.differing_over_1e5) / double(d.both_covered);
    EXPECT_GE(within, kMinFractionWithin1e5) << d.differing_over_1e5 << " of " << d.both_covered
                                             << " common pixels differ in depth by 1e-5 or more";
    // The same shading formulas in float on both sides: at most a rounding step apart.
    if (o.color.compared) {
        EXPECT_LE(o.color.max_difference, 2);
    }
    std::cout << "coverage agreement " << 100.0 * d.coverage_agreement() << "% (only llvmpipe "
              << d.only_gl << ", only zraster " << d.only_zraster << "), max depth difference "
              << d.max_abs_difference << " over " << d.both_covered << " common pixels ("
              << d.differing_over_1e5 << " differ by >= 1e-5)";
    if (o.color.compared)
        std::cout << "; color: max channel difference " << o.color.max_difference << ", "
                  << o.color.over_1 << " pixels off by more than 1";
    std::cout << "\n";
}

TEST(LlvmpipeCrossCheck, Sphere20000Phong) {
    REQUIRE_LLVMPIPE();
    expect_agreement(render_both("sphere:20000", BenchMode::Phong));
}

TEST(LlvmpipeCrossCheck, BunnyPhong) {
    ZRASTER_REQUIRE_SHARED_DATA();
    REQUIRE_LLVMPIPE();
    expect_agreement(render_both(shared_data("meshes/obj/bunny.obj").string(), BenchMode::Phong));
}

TEST(LlvmpipeCrossCheck, BunnyDepthOnly) {
    ZRASTER_REQUIRE_SHARED_DATA();
    REQUIRE_LLVMPIPE();
    expect_agreement(render_both(shared_data("meshes/obj/bunny.obj").string(), BenchMode::Depth));
}

}  // namespace
}  // namespace zraster::test
