// Materials' alpha on every path besides the z-buffer (the painter's algorithm, the BSP tree,
// Warnock's subdivision, multisampling, the A-buffer, SVG), each against the z-buffer's picture
// (tests/render/alpha_modes_test.cpp): a Mask checkerboard quad shows the wall through its cut
// cells with the wall's depth and ids; a blended quad over an opaque one submitted after it is
// the analytic "over" within 1/255; every submission order gives the same image; the Opaque
// alpha mode draws what opaque materials draw.
//
// Cost: a few dozen 64 x 64 frames; well under a second.
#include <zraster/abuffer.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/svg.hpp>
#include <zraster/texture.hpp>
#include <zraster/visibility.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "support/alpha_test_scenes.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

RenderOptions alpha_path_options() {
    RenderOptions o = alpha_test_options();
    o.id_targets = true;
    return o;
}
enum class Path { ZBuffer, Painter, Bsp, Warnock, Multisample, ABuffer };
constexpr std::array<Path, 6> kPaths = {Path::ZBuffer, Path::Painter,     Path::Bsp,
                                        Path::Warnock, Path::Multisample, Path::ABuffer};
const char* path_name(Path p) {
    constexpr const char* names[] = {"zbuffer", "painter", "bsp", "warnock", "msaa", "abuffer"};
    return names[int(p)];
}
// Paths that sample one point per pixel (the pixel center), as the z-buffer does.
bool point_sampled(Path p) {
    return p != Path::Multisample && p != Path::ABuffer;
}

RenderResult draw_with(Path path, const Scene& scene, const RenderOptions& options) {
    switch (path) {
        case Path::ZBuffer:
            return render(scene, options);
        case Path::Painter:
            return render_with_visibility(scene, options, VisibilityAlgorithm::Painter);
        case Path::Bsp:
            return render_with_visibility(scene, options, VisibilityAlgorithm::Bsp);
        case Path::Warnock:
            return render_with_visibility(scene, options, VisibilityAlgorithm::Warnock);
        case Path::Multisample:
            return render_multisampled(scene, options, 4);
        case Path::ABuffer:
            return render_abuffer(scene, options);
    }
    return {};
}

std::size_t at_pixel(int px, int py) {
    return std::size_t(py) * kAlphaImage + std::size_t(px);
}

// The scene without its last instance (the wall alone, the opaque layers alone).
Scene without_last(Scene scene) {
    scene.instances.pop_back();
    return scene;
}

TEST(AlphaPaths, MaskCheckerShowsTheWallThroughItsCutCells) {
    const RenderOptions options = alpha_path_options();
    const RenderResult reference = render(checker_scene(AlphaMode::Mask, false), options);
    for (const Path path : kPaths) {
        SCOPED_TRACE(path_name(path));
        const RenderResult wall =
            draw_with(path, without_last(checker_scene(AlphaMode::Mask, false)), options);
        const RenderResult r = draw_with(path, checker_scene(AlphaMode::Mask, false), options);
        const RenderResult swapped = draw_with(path, checker_scene(AlphaMode::Mask, true), options);
        EXPECT_EQ(r.targets.color, swapped.targets.color);
        int cut = 0, kept = 0;
        for (int cy = 0; cy < 4; ++cy)
            for (int cx = 0; cx < 4; ++cx) {
                // A pixel well inside the cell (and off the squares' diagonals, where the
                // subsample paths' ids are either triangle's): texel alpha 0 at the top left
                // cell, alternating.
                const int px = 16 + 8 * cx + 4, py = 16 + 8 * cy + 2;
                const bool transparent = ((cx + cy) & 1) == 0;
                const std::size_t p = at_pixel(px, py);
                EXPECT_EQ(r.targets.instance_id[p], reference.targets.instance_id[p]);
                EXPECT_EQ(r.targets.primitive_id[p], reference.targets.primitive_id[p]);
                if (transparent) {
                    EXPECT_EQ(r.targets.depth[p], wall.targets.depth[p]) << px << "," << py;
                    EXPECT_EQ(alpha_test_rgb(r, px, py),
                              glm::ivec3(analytic_unorm8(0.9), analytic_unorm8(0.2),
                                         analytic_unorm8(0.1)))
                        << px << "," << py;
                    EXPECT_EQ(r.targets.instance_id[p], 0) << px << "," << py;
                    ++cut;
                } else {
                    EXPECT_LT(r.targets.depth[p], wall.targets.depth[p]) << px << "," << py;
                    EXPECT_EQ(alpha_test_rgb(r, px, py), glm::ivec3(40, 200, 60))
                        << px << "," << py;
                    EXPECT_EQ(r.targets.instance_id[p], 1) << px << "," << py;
                    ++kept;
                }
            }
        EXPECT_EQ(cut, 8);
        EXPECT_EQ(kept, 8);
        // One sample a pixel, the texture's alpha sampled as render() samples it: the same holes
        // pixel for pixel, and the same depth and ids everywhere.
        if (point_sampled(path)) {
            EXPECT_EQ(r.targets.color, reference.targets.color);
            EXPECT_TRUE(same_bits(r.targets.depth, reference.targets.depth));
            EXPECT_EQ(r.targets.instance_id, reference.targets.instance_id);
            EXPECT_EQ(r.targets.primitive_id, reference.targets.primitive_id);
        }
    }
}

// The checker's transparent cells at alpha 64 instead of 0, blended: the A-buffer and MSAA
// sample the texture's alpha per fragment as render() does at each pixel.
TEST(AlphaPaths, TextureAlphaBlendsAsTheZBufferBlends) {
    const RenderOptions options = alpha_path_options();
    Scene scene = checker_scene(AlphaMode::Blend, false);
    scene.materials[1].base_color_texture = std::make_shared<Texture>(
        make_checkerboard_texture(4, 16, {40, 200, 60, 64}, {40, 200, 60, 255}));
    const RenderResult reference = render(scene, options);
    const glm::dvec3 wall(0.9, 0.2, 0.1), green(40 / 255.0, 200 / 255.0, 60 / 255.0);
    for (const Path path : kPaths) {
        SCOPED_TRACE(path_name(path));
        const RenderResult wall_only = draw_with(path, without_last(scene), options);
        const RenderResult r = draw_with(path, scene, options);
        for (int cy = 0; cy < 4; ++cy)
            for (int cx = 0; cx < 4; ++cx) {
                const int px = 16 + 8 * cx + 4, py = 16 + 8 * cy + 2;
                const double a = ((cx + cy) & 1) == 0 ? 64 / 255.0 : 1.0;
                const glm::dvec3 expected = a * green + (1.0 - a) * wall;
                const glm::ivec3 got = alpha_test_rgb(r, px, py);
                for (int c = 0; c < 3; ++c)
                    EXPECT_LE(std::abs(got[c] - analytic_unorm8(expected[c])), 1)
                        << px << "," << py << " channel " << c;
                // Blended fragments write no depth and no ids: the wall's everywhere.
                const std::size_t p = at_pixel(px, py);
                EXPECT_EQ(r.targets.instance_id[p], 0);
                EXPECT_EQ(r.targets.depth[p], wall_only.targets.depth[p]);
            }
        if (point_sampled(path)) {
            EXPECT_EQ(r.targets.color, reference.targets.color);
            EXPECT_EQ(r.targets.instance_id, reference.targets.instance_id);
        }
    }
}

// --stats: every path counts the cut-out fragments, the blended fragments in front of the opaque
// surfaces and the pixels they cover as the z-buffer does, where no blended surface is hidden
// (the area-sampled paths also count the fragments of pixels a square covers only in part).
TEST(AlphaPaths, EveryPathCountsCutOutAndBlendedFragments) {
    const RenderOptions options = alpha_path_options();
    const Scene mask = checker_scene(AlphaMode::Mask, false);
    const Scene blend = alpha_layers_scene(kAlphaLayers, {0, 1, 2});
    const RenderStats mask_reference = render(mask, options).stats;
    const RenderStats blend_reference = render(blend, options).stats;
    EXPECT_EQ(mask_reference.fragments_alpha_discarded, 16u * 32u);
    EXPECT_EQ(blend_reference.fragments_blended, 28u * 28u + 16u * 16u);
    for (const Path path : kPaths) {
        SCOPED_TRACE(path_name(path));
        const RenderStats m = draw_with(path, mask, options).stats;
        EXPECT_EQ(m.fragments_alpha_discarded, mask_reference.fragments_alpha_discarded);
        EXPECT_EQ(m.fragments_blended, 0u);
        const RenderStats b = draw_with(path, blend, options).stats;
        EXPECT_EQ(b.fragments_alpha_discarded, 0u);
        if (point_sampled(path)) {
            EXPECT_EQ(b.fragments_blended, blend_reference.fragments_blended);
        } else {  // also the edge pixels whose centers the squares miss: one row each side
            EXPECT_GE(b.fragments_blended, blend_reference.fragments_blended);
            EXPECT_LE(b.fragments_blended, blend_reference.fragments_blended + 4u * (29 + 17));
        }
        EXPECT_EQ(b.pixels_blended, blend_reference.pixels_blended);
    }
}

// A square whose vertex alpha runs from 0 (left) to 1 (right) over the wall, white times its
// vertex colors: blended, the analytic "over" of the interpolated color; as a cut-out, the wall
// left of the middle. Point-sampled paths equal the z-buffer bit for bit.
Scene vertex_alpha_scene(AlphaMode mode) {
    Scene scene = checker_scene(mode, false);
    scene.materials[1].base_color_texture.reset();
    const glm::vec4 left(1.0f, 0.2f, 0.4f, 0.0f), right(0.0f, 0.8f, 0.4f, 1.0f);
    scene.meshes[1].colors = {left, right, right, left};  // corners (-h,-h), (h,-h), (h,h), (-h,h)
    return scene;
}

TEST(AlphaPaths, VertexAlphaBlendsAndCutsOutAsTheZBuffer) {
    const RenderOptions options = alpha_path_options();
    const glm::dvec3 wall(0.9, 0.2, 0.1);
    const glm::dvec4 left(1.0, 0.2, 0.4, 0.0), right(0.0, 0.8, 0.4, 1.0);
    for (const AlphaMode mode : {AlphaMode::Blend, AlphaMode::Mask}) {
        const Scene scene = vertex_alpha_scene(mode);
        const RenderResult reference = render(scene, options);
        for (const Path path : kPaths) {
            SCOPED_TRACE(std::string(path_name(path)) + (mode == AlphaMode::Mask ? " mask" : ""));
            const RenderResult r = draw_with(path, scene, options);
            for (int px = 18; px < 47; px += 4) {
                const double t = (px + 0.5 - 32.0 + 16.0) / 32.0;
                const glm::dvec4 c = (1.0 - t) * left + t * right;
                const glm::dvec3 expected = mode == AlphaMode::Blend
                                                ? c.w * glm::dvec3(c) + (1.0 - c.w) * wall
                                                : (c.w >= 0.5 ? glm::dvec3(c) : wall);
                const glm::ivec3 got = alpha_test_rgb(r, px, 30);
                for (int k = 0; k < 3; ++k)
                    EXPECT_LE(std::abs(got[k] - analytic_unorm8(expected[k])), 1)
                        << px << " channel " << k;
            }
            if (point_sampled(path)) {
                EXPECT_EQ(r.targets.color, reference.targets.color);
                EXPECT_EQ(r.targets.instance_id, reference.targets.instance_id);
            }
        }
    }
}

// The blended layers in every submission order (the half-transparent one first, the opaque one
// after it among them): the same image, "over" within 1/255, the opaque layer's depth and ids.
TEST(AlphaPaths, BlendIsOverInAnyOrder) {
    const RenderOptions options = alpha_path_options();
    const glm::dvec3 inner = alpha_over(3), middle = alpha_over(2);
    const RenderResult reference = render(alpha_layers_scene(kAlphaLayers, {1, 0, 2}), options);
    for (const Path path : kPaths) {
        SCOPED_TRACE(path_name(path));
        Scene opaque_only = alpha_layers_scene(kAlphaLayers, {0, 1, 2});
        opaque_only.instances.resize(1);
        const RenderResult wall = draw_with(path, opaque_only, options);
        const RenderResult first = same_image_in_every_order(
            [&](const Scene& scene) { return draw_with(path, scene, options); });
        for (const auto& [px, py, expected] :
             {std::tuple{32, 32, inner}, std::tuple{26, 38, inner}, std::tuple{20, 20, middle},
              std::tuple{14, 14, glm::dvec3(kAlphaLayers[0].color)}}) {
            const glm::ivec3 got = alpha_test_rgb(first, px, py);
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(std::abs(got[c] - analytic_unorm8(expected[c])), 1)
                    << "pixel " << px << "," << py << " channel " << c;
            // The opaque layer's depth and ids, as the path has them without the others.
            const std::size_t p = at_pixel(px, py);
            EXPECT_EQ(first.targets.depth[p], wall.targets.depth[p]);
            EXPECT_EQ(first.targets.primitive_id[p], reference.targets.primitive_id[p]);
        }
        if (point_sampled(path)) {
            EXPECT_EQ(first.targets.color, reference.targets.color);
        }
    }
}

// --alpha-mode opaque: every path draws what it draws when every material says Opaque.
TEST(AlphaPaths, OpaqueModeDrawsEverythingOpaque) {
    RenderOptions opaque = alpha_path_options();
    opaque.alpha_mode = MaterialAlpha::Opaque;
    for (const Path path : kPaths) {
        SCOPED_TRACE(path_name(path));
        for (Scene scene :
             {checker_scene(AlphaMode::Mask, false), alpha_layers_scene(kAlphaLayers, {2, 0, 1})}) {
            const RenderResult ignored = draw_with(path, scene, opaque);
            for (Material& m : scene.materials) m.alpha_mode = AlphaMode::Opaque;
            const RenderResult reference = draw_with(path, scene, alpha_path_options());
            EXPECT_EQ(ignored.targets.color, reference.targets.color);
            EXPECT_EQ(ignored.targets.instance_id, reference.targets.instance_id);
        }
    }
}

// With one sample a pixel (at its center) multisampling and the A-buffer cut out exactly the
// pixels render() cuts out: the alpha is sampled where render() samples it.
TEST(AlphaPaths, OneSampleAPixelCutsOutAsTheZBuffer) {
    const RenderOptions options = alpha_path_options();
    const Scene scene = checker_scene(AlphaMode::Mask, true);
    const RenderResult reference = render(scene, options);
    const RenderResult msaa = render_multisampled(scene, options, 1);
    EXPECT_EQ(msaa.targets.color, reference.targets.color);
    EXPECT_EQ(msaa.targets.instance_id, reference.targets.instance_id);
    ABufferOptions one;
    one.samples_per_side = 1;
    const RenderResult abuffer = render_abuffer(scene, options, one);
    EXPECT_EQ(abuffer.targets.color, reference.targets.color);
    EXPECT_EQ(abuffer.targets.instance_id, reference.targets.instance_id);
}

// Multisampling composites per sample: any thread count gives the same bits.
TEST(AlphaPaths, MultisampledBlendIsTheSameForAnyThreadCount) {
    RenderOptions options = alpha_path_options();
    const Scene scene = alpha_layers_scene(kAlphaLayers, {2, 0, 1});
    options.threads = 1;
    const RenderResult one = render_multisampled(scene, options, 4);
    options.threads = 3;
    const RenderResult three = render_multisampled(scene, options, 4);
    EXPECT_EQ(one.targets.color, three.targets.color);
    EXPECT_GT(one.stats.fragments_blended, 0u);
    EXPECT_GT(one.stats.pixels_blended, 0u);
}

// SVG: a blended polygon gets fill-opacity and leaves what is behind it in the drawing; a Mask
// material under its cutoff is left out; a textured cut-out is clipped to its kept pixels.
TEST(AlphaPaths, SvgBlendsAndCutsOut) {
    const RenderOptions options = alpha_path_options();
    for (const SvgOptions::Order order : {SvgOptions::Order::Bsp, SvgOptions::Order::Painter}) {
        SvgOptions svg_options;
        svg_options.order = order;
        Scene layers = alpha_layers_scene(kAlphaLayers, {1, 0, 2});
        const std::string svg = render_svg(layers, options, svg_options);
        EXPECT_NE(svg.find("fill=\"#e6331a\""), std::string::npos) << svg;  // the opaque wall
        EXPECT_NE(svg.find("fill-opacity=\"0.5\""), std::string::npos) << svg;
        EXPECT_NE(svg.find("fill-opacity=\"0.35\""), std::string::npos) << svg;
        // Back to front: the wall, then the 0.5 layer, then the 0.35 one.
        EXPECT_LT(svg.find("fill=\"#e6331a\""), svg.find("fill-opacity=\"0.5\""));
        EXPECT_LT(svg.find("fill-opacity=\"0.5\""), svg.find("fill-opacity=\"0.35\""));
        // Opaque mode: no opacity anywhere.
        RenderOptions opaque = options;
        opaque.alpha_mode = MaterialAlpha::Opaque;
        EXPECT_EQ(render_svg(layers, opaque, svg_options).find("fill-opacity"), std::string::npos);
        // The 0.5 layer as a Mask under a cutoff of 0.6: left out whole.
        Material& half = layers.materials.at(layers.meshes.at(0).material);
        ASSERT_EQ(half.opacity, 0.5f);
        half.alpha_mode = AlphaMode::Mask;
        half.alpha_cutoff = 0.6f;
        const std::string masked = render_svg(layers, options, svg_options);
        EXPECT_EQ(masked.find("fill-opacity=\"0.5\""), std::string::npos) << masked;
        EXPECT_EQ(masked.find("#1acc4d"), std::string::npos) << masked;  // its color
        EXPECT_NE(masked.find("fill-opacity=\"0.35\""), std::string::npos) << masked;
        // The checker: clipped to the 16 rows of kept pixels in each of the 8 kept cells.
        const std::string checker =
            render_svg(checker_scene(AlphaMode::Mask, false), options, svg_options);
        EXPECT_NE(checker.find("<clipPath id=\"zraster-cut-0\">"), std::string::npos) << checker;
        EXPECT_NE(checker.find("clip-path=\"url(#zraster-cut-0)\""), std::string::npos);
        EXPECT_NE(checker.find("M16 16h8v1h-8z") == std::string::npos,
                  checker.find("M24 16h8v1h-8z") == std::string::npos)
            << "exactly one of the two top-left cells is kept";
    }
}

}  // namespace
}  // namespace zraster::test
