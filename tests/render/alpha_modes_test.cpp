// Materials' alpha in the z-buffer pipeline (RenderOptions::alpha_mode): blended surfaces
// composited over the opaque ones farthest first, the same image in every submission order and
// equal to the analytic "over" within 1/255; alpha-tested (Mask) surfaces discarding their
// fragments under the cutoff before they write depth; both unchanged by the pipeline's exact
// optimizations (SIMD, hierarchical z, occlusion and cluster culling, threads).
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/texture.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <span>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "support/alpha_test_scenes.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

TEST(AlphaModes, BlendIsIndependentOfSubmissionOrderAndMatchesOver) {
    const RenderOptions options = alpha_test_options();
    const RenderResult first =
        same_image_in_every_order([&](const Scene& scene) { return render(scene, options); });

    // Inside every layer: the background hidden by the opaque one, then "over" twice.
    const glm::dvec3 inner = alpha_over(3), middle = alpha_over(2);
    for (const auto& [px, py, expected] :
         {std::tuple{32, 32, inner}, std::tuple{26, 38, inner}, std::tuple{20, 20, middle},
          std::tuple{14, 14, glm::dvec3(kAlphaLayers[0].color)}}) {
        const glm::ivec3 got = alpha_test_rgb(first, px, py);
        for (int c = 0; c < 3; ++c)
            EXPECT_LE(std::abs(got[c] - analytic_unorm8(expected[c])), 1)
                << "pixel " << px << "," << py << " channel " << c;
    }
    // Blended surfaces write no depth: the opaque layer's alone.
    Scene opaque_only = alpha_layers_scene(kAlphaLayers, {0, 1, 2});
    opaque_only.instances.resize(1);
    const RenderResult reference = render(opaque_only, options);
    EXPECT_TRUE(same_bits(first.targets.depth, reference.targets.depth));
    EXPECT_EQ(first.stats.pixels_blended, std::uint64_t(28 * 28));
    EXPECT_EQ(first.stats.fragments_blended, std::uint64_t(28 * 28 + 16 * 16));
}

// More blended layers than a pixel keeps in slots (render/blend_kernels.hpp): six squares
// over an opaque one, nested so pixels see one to six layers; two pairs at equal depths, whose
// order comes from content and ids. Every submission order, SIMD or not, 1 or 2 threads: one
// image, the analytic "over" where the depths differ.
TEST(AlphaModes, MoreLayersThanSlotsInAnyOrder) {
    const std::array<AlphaLayer, 7> squares = {{{24.0f, -6.0f, {0.9f, 0.2f, 0.1f}, 1.0f},
                                                {22.0f, -4.0f, {0.1f, 0.8f, 0.3f}, 0.5f},
                                                {18.0f, -2.0f, {0.2f, 0.3f, 0.9f}, 0.35f},
                                                {14.0f, 0.0f, {0.7f, 0.7f, 0.1f}, 0.6f},
                                                {10.0f, 2.0f, {0.3f, 0.1f, 0.6f}, 0.25f},
                                                {6.0f, 2.0f, {0.9f, 0.9f, 0.9f}, 0.4f},
                                                {3.0f, 0.0f, {0.0f, 0.5f, 0.5f}, 0.7f}}};
    const auto scene_in = [&](const std::vector<int>& order) {
        return alpha_layers_scene(squares, order);
    };
    std::vector<int> order = {0, 1, 2, 3, 4, 5, 6};
    const RenderOptions options = alpha_test_options();
    const RenderResult reference = render(scene_in(order), options);
    EXPECT_EQ(reference.stats.pixels_blended, std::uint64_t(44 * 44));
    std::mt19937 rng(9);
    for (int round = 0; round < 8; ++round) {
        std::shuffle(order.begin(), order.end(), rng);
        RenderOptions o = options;
        o.simd = round % 2 == 0;
        o.threads = round % 3 == 0 ? 1 : 2;
        const RenderResult r = render(scene_in(order), o);
        EXPECT_EQ(r.targets.color, reference.targets.color) << "round " << round;
    }
    // Where the depths differ (inside square 4, outside 5 and 6: layers 1 to 4 over 0).
    glm::dvec3 expected(squares[0].color);
    for (std::size_t k = 1; k <= 4; ++k)
        expected = double(squares[k].opacity) * glm::dvec3(squares[k].color) +
                   (1.0 - double(squares[k].opacity)) * expected;
    const glm::ivec3 got = alpha_test_rgb(reference, 32 + 8, 32);
    for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(got[c] - analytic_unorm8(expected[c])), 1) << c;
}

TEST(AlphaModes, OpaqueModeIgnoresAlpha) {
    RenderOptions options = alpha_test_options();
    options.alpha_mode = MaterialAlpha::Opaque;
    Scene scene = alpha_layers_scene(kAlphaLayers, {0, 1, 2});
    const RenderResult ignored = render(scene, options);
    for (Material& m : scene.materials) m.opacity = 1.0f;
    options.alpha_mode = MaterialAlpha::Auto;
    const RenderResult opaque = render(scene, options);
    EXPECT_EQ(ignored.targets.color, opaque.targets.color);
    EXPECT_EQ(ignored.stats.fragments_blended, 0u);
    // And a material that says Opaque keeps its alpha ignored in Auto.
    scene = alpha_layers_scene(kAlphaLayers, {0, 1, 2});
    for (Material& m : scene.materials) m.alpha_mode = AlphaMode::Opaque;
    EXPECT_EQ(render(scene, options).targets.color, opaque.targets.color);
}

TEST(AlphaModes, MaskDiscardsFragmentsUnderTheCutoffBeforeTheyWriteDepth) {
    const RenderOptions options = alpha_test_options();
    const RenderResult r = render(checker_scene(AlphaMode::Mask, false), options);
    EXPECT_EQ(render(checker_scene(AlphaMode::Mask, true), options).targets.color, r.targets.color);
    const float far_depth =
        r.targets.depth[std::size_t(10) * kAlphaImage + 32];  // back square only
    int cut = 0, kept = 0;
    for (int cy = 0; cy < 4; ++cy)
        for (int cx = 0; cx < 4; ++cx) {
            // The cell's center pixel: texel alpha 0 at the top left cell, alternating.
            const int px = 16 + 8 * cx + 4, py = 16 + 8 * cy + 4;
            const bool transparent = ((cx + cy) & 1) == 0;
            const glm::ivec3 got = alpha_test_rgb(r, px, py);
            const float depth = r.targets.depth[std::size_t(py) * kAlphaImage + std::size_t(px)];
            if (transparent) {
                EXPECT_EQ(got, glm::ivec3(analytic_unorm8(0.9), analytic_unorm8(0.2),
                                          analytic_unorm8(0.1)))
                    << px << "," << py;
                EXPECT_EQ(depth, far_depth);
                ++cut;
            } else {
                EXPECT_EQ(got, glm::ivec3(40, 200, 60)) << px << "," << py;
                EXPECT_LT(depth, far_depth);
                ++kept;
            }
        }
    EXPECT_EQ(cut, 8);
    EXPECT_EQ(kept, 8);
    EXPECT_GT(r.stats.fragments_alpha_discarded, 8u * 60u);
    EXPECT_EQ(r.stats.fragments_blended, 0u);
    // A depth-only frame cuts the same holes.
    RenderOptions depth_only = options;
    depth_only.color_target = false;
    EXPECT_TRUE(same_bits(render(checker_scene(AlphaMode::Mask, false), depth_only).targets.depth,
                          r.targets.depth));
}

// A cut-out texture minified 8 times (256 texels over 32 pixels): trilinear filtering samples
// its mip levels (the 32x32 level and the next), whose alpha the box filter keeps inside the
// cells; the cells cut out where the finest level, sampled without mipmaps, cuts them.
TEST(AlphaModes, MaskSamplesTheMipLevelsOfAMinifiedTexture) {
    Scene scene = checker_scene(AlphaMode::Mask, false);
    scene.materials[1].base_color_texture = std::make_shared<Texture>(
        make_checkerboard_texture(4, 64, {40, 200, 60, 0}, {40, 200, 60, 255}));
    ASSERT_GE(scene.materials[1].base_color_texture->levels(), 6);
    const RenderOptions options = alpha_test_options();
    RenderOptions finest = options;
    finest.texture_filter = TextureFilter::Nearest;
    const RenderResult r = render(scene, options), reference = render(scene, finest);
    for (int cy = 0; cy < 4; ++cy)
        for (int cx = 0; cx < 4; ++cx) {
            const int px = 16 + 8 * cx + 4, py = 16 + 8 * cy + 4;
            const bool transparent = ((cx + cy) & 1) == 0;
            const glm::ivec3 expected =
                transparent
                    ? glm::ivec3(analytic_unorm8(0.9), analytic_unorm8(0.2), analytic_unorm8(0.1))
                    : glm::ivec3(40, 200, 60);
            EXPECT_EQ(alpha_test_rgb(r, px, py), expected) << px << "," << py;
            EXPECT_EQ(alpha_test_rgb(reference, px, py), expected) << px << "," << py;
        }
    EXPECT_GT(r.stats.fragments_alpha_discarded, 8u * 36u);
}

TEST(AlphaModes, TheOptimizationsAndTheSimdShaderDoNotChangeABit) {
    // (Phong: blended fragments lit by the SIMD shader, against the scalar one without SIMD.)
    for (const auto& [mode, shading] : {std::pair{AlphaMode::Mask, ShadingMode::Unlit},
                                        {AlphaMode::Blend, ShadingMode::Unlit},
                                        {AlphaMode::Mask, ShadingMode::Phong},
                                        {AlphaMode::Blend, ShadingMode::Phong}}) {
        for (const bool first : {false, true}) {
            Scene scene = checker_scene(mode, first);
            if (shading == ShadingMode::Phong)  // untextured, alpha from the opacity: SIMD-lit
                for (Material& m : scene.materials) {
                    m.base_color_texture.reset();
                    if (m.alpha_mode == AlphaMode::Blend) m.opacity = 0.6f;
                }
            RenderOptions options = alpha_test_options();
            options.shading = shading;
            options.camera->projection = Camera::Projection::Perspective;
            const RenderResult reference = same_image_under_every_optimization(scene, options);
            if (mode == AlphaMode::Blend) {
                EXPECT_GT(reference.stats.fragments_blended, 0u);
            }
        }
    }
}

// A cut-out or blended square in front of a smaller opaque one, which it would hide if it were
// opaque: it must not serve as an occluder.
TEST(AlphaModes, CutOutsAndBlendedSurfacesDoNotOcclude) {
    for (const AlphaMode mode : {AlphaMode::Mask, AlphaMode::Blend}) {
        // (Instance 0 draws mesh 1, the cut-out square; instance 1 mesh 0, the wall.)
        Scene scene = checker_scene(mode, true);
        scene.meshes[1] = alpha_test_square(2.0f, 1.0f);  // the cut-out square, 4 x 4 cells
        scene.meshes[1].material = 1;
        // Small (under the 1% of the screen that makes every instance an occluder), behind the
        // middle of a transparent cell (the second in each direction).
        scene.meshes[0] = alpha_test_square(0.15f, -2.0f);
        scene.meshes[0].material = 0;
        scene.instances[1].transform = glm::translate(glm::mat4(1.0f), {-0.5f, 0.5f, 0.0f});
        // (In perspective: the occlusion buffer compares 1/w, constant in an orthographic view.)
        RenderOptions options = alpha_test_options();
        options.camera->projection = Camera::Projection::Perspective;
        options.camera->fovy_degrees = 40.0;
        const RenderResult plain = render(scene, options);
        options.occlusion_cull = true;
        const RenderResult culled = render(scene, options);
        EXPECT_EQ(culled.stats.instances_occlusion_culled, 0u);
        // (Opaque, the square does hide the other one: the test above could fail.)
        scene.materials[1].alpha_mode = AlphaMode::Opaque;
        EXPECT_EQ(render(scene, options).stats.instances_occlusion_culled, 1u);
        scene.materials[1].alpha_mode = mode;
        EXPECT_EQ(culled.targets.color, plain.targets.color);
        EXPECT_TRUE(same_bits(culled.targets.depth, plain.targets.depth));
        // The opaque square shows through the holes.
        EXPECT_EQ(alpha_test_rgb(plain, 27, 27),
                  glm::ivec3(analytic_unorm8(0.9), analytic_unorm8(0.2), analytic_unorm8(0.1)));
    }
}

}  // namespace
}  // namespace zraster::test
