// Vertex colors (Mesh::colors) in the z-buffer pipeline: the interpolated color multiplies the
// material's base color and its alpha the material's alpha, so a vertex-alpha gradient blends as
// the analytic "over" and cuts out at the cutoff where the interpolated alpha crosses it; the
// same image in every submission order, with SIMD on or off, any thread count, hierarchical z,
// occlusion and cluster culling; malformed colors are refused by name.
#include <zraster/error.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/visibility.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "support/alpha_test_scenes.hpp"
#include "support/test_support.hpp"

namespace zraster::test {
namespace {

// The front square's half-width: it covers pixels 16..47 each way.
constexpr float kHalf = 16.0f;
// Its corners' colors: red-ish and transparent on the left (x = -16), green-ish and opaque on
// the right (x = +16); color and alpha vary linearly in x only, so both triangles agree on them.
constexpr glm::vec4 kLeft{1.0f, 0.2f, 0.4f, 0.0f}, kRight{0.0f, 0.8f, 0.4f, 1.0f};
const glm::dvec3 kWall{0.9, 0.2, 0.1};

// A wall (opaque, 48 pixels wide, behind) and the gradient square in front of it in `mode`,
// white base color, submitted first when `front_first`.
Scene gradient_scene(AlphaMode mode, bool front_first) {
    Scene scene;
    Material wall;
    wall.base_color = glm::vec3(kWall);
    Material front;
    front.base_color = {1.0f, 1.0f, 1.0f};
    front.alpha_mode = mode;
    front.alpha_cutoff = 0.5f;
    scene.materials = {wall, front};
    Mesh far = alpha_test_square(24.0f, -2.0f);
    Mesh near = alpha_test_square(kHalf, 1.0f);
    near.material = 1;
    // alpha_test_square's corners: (-h,-h), (h,-h), (h,h), (-h,h).
    near.colors = {kLeft, kRight, kRight, kLeft};
    scene.meshes = {far, near};
    scene.instances.resize(2);
    scene.instances[1].mesh = 1;
    if (front_first) std::swap(scene.instances[0], scene.instances[1]);
    return scene;
}

// The interpolated vertex color at the center of pixel column px.
glm::dvec4 color_at_column(int px) {
    const double x = px + 0.5 - 32.0;  // world x (alpha_test_options' orthographic camera)
    const double t = (x + kHalf) / (2.0 * kHalf);
    return (1.0 - t) * glm::dvec4(kLeft) + t * glm::dvec4(kRight);
}

template <class Action>
void expect_input_error_containing(Action&& action, const std::string& part) {
    try {
        action();
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
}

void expect_rgb_near(const RenderResult& r, int px, int py, const glm::dvec3& expected) {
    const glm::ivec3 got = alpha_test_rgb(r, px, py);
    for (int c = 0; c < 3; ++c)
        EXPECT_LE(std::abs(got[c] - analytic_unorm8(expected[c])), 1)
            << "pixel " << px << "," << py << " channel " << c << ": " << got[c] << " vs "
            << analytic_unorm8(expected[c]);
}

TEST(VertexColors, MultiplyTheBaseColorAsInterpolated) {
    Scene scene = gradient_scene(AlphaMode::Opaque, false);
    scene.materials[1].base_color = {0.5f, 1.0f, 0.75f};
    const RenderResult r = render(scene, alpha_test_options());
    for (int px = 16; px < 48; px += 3) {
        const glm::dvec4 c = color_at_column(px);
        expect_rgb_near(r, px, 30, glm::dvec3(0.5 * c.x, c.y, 0.75 * c.z));
    }
    // Opaque: its depth and ids everywhere it covers, whatever the vertex alpha.
    EXPECT_EQ(r.stats.fragments_blended, 0u);
}

TEST(VertexColors, VertexAlphaBlendsAsOverInEitherOrder) {
    const RenderOptions options = alpha_test_options();
    const RenderResult r = render(gradient_scene(AlphaMode::Blend, false), options);
    const RenderResult swapped = render(gradient_scene(AlphaMode::Blend, true), options);
    EXPECT_EQ(r.targets.color, swapped.targets.color);
    for (int px = 16; px < 48; px += 3) {
        const glm::dvec4 c = color_at_column(px);
        expect_rgb_near(r, px, 40, c.w * glm::dvec3(c) + (1.0 - c.w) * kWall);
    }
    // Blended fragments write no depth: the wall's alone.
    Scene wall_only = gradient_scene(AlphaMode::Blend, false);
    wall_only.instances.pop_back();
    EXPECT_TRUE(same_bits(r.targets.depth, render(wall_only, options).targets.depth));
    EXPECT_EQ(r.stats.pixels_blended, std::uint64_t(32 * 32));
}

TEST(VertexColors, VertexAlphaCutsOutWhereItCrossesTheCutoff) {
    const RenderResult r = render(gradient_scene(AlphaMode::Mask, false), alpha_test_options());
    // Alpha (x + 16) / 32 at world x = px - 31.5: under 0.5 left of column 32.
    for (int px = 16; px < 48; ++px) {
        SCOPED_TRACE(px);
        if (px < 32) {
            expect_rgb_near(r, px, 24, kWall);
        } else {
            expect_rgb_near(r, px, 24, glm::dvec3(color_at_column(px)));
        }
    }
    EXPECT_EQ(r.stats.fragments_alpha_discarded, std::uint64_t(16 * 32));
}

// glTF: an OPAQUE material ignores alpha, vertex alpha too; the colors still count.
TEST(VertexColors, OpaqueMaterialsIgnoreVertexAlpha) {
    const RenderOptions options = alpha_test_options();
    const RenderResult r = render(gradient_scene(AlphaMode::Opaque, false), options);
    for (int px = 16; px < 48; px += 5) expect_rgb_near(r, px, 20, glm::dvec3(color_at_column(px)));
    RenderOptions opaque = options;
    opaque.alpha_mode = MaterialAlpha::Opaque;
    EXPECT_EQ(render(gradient_scene(AlphaMode::Blend, false), opaque).targets.color,
              r.targets.color);
}

TEST(VertexColors, TheOptimizationsAndTheSimdPathDoNotChangeABit) {
    for (const AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend})
        for (const ShadingMode shading :
             {ShadingMode::Unlit, ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong})
            for (const bool first : {false, true}) {
                SCOPED_TRACE(std::to_string(int(mode)) + " " + std::to_string(int(shading)) +
                             (first ? " front first" : ""));
                const Scene scene = gradient_scene(mode, first);
                RenderOptions options = alpha_test_options();
                options.shading = shading;
                options.camera->projection = Camera::Projection::Perspective;
                same_image_under_every_optimization(scene, options);
            }
}

// An interleaved vertex buffer (position, color) through a MeshView draws what the owning
// scene draws.
TEST(VertexColors, StridedColorsInAViewDrawTheSame) {
    const Scene scene = gradient_scene(AlphaMode::Blend, false);
    const RenderOptions options = alpha_test_options();
    const RenderResult expected = render(scene, options);

    struct Vertex {
        glm::vec3 position;
        glm::vec4 color;
    };
    std::vector<MeshView> meshes;
    std::vector<InstanceView> instances;
    SceneView view = view_of(scene, meshes, instances);
    const Mesh& front = scene.meshes[1];
    std::vector<Vertex> interleaved;
    for (std::size_t v = 0; v < front.positions.size(); ++v)
        interleaved.push_back({front.positions[v], front.colors[v]});
    meshes[1].positions = {&interleaved[0].position.x, interleaved.size(), sizeof(Vertex)};
    meshes[1].colors = {&interleaved[0].color.x, interleaved.size(), sizeof(Vertex)};
    view.meshes = meshes;

    RenderTargets got = expected.targets;
    std::fill(got.color.begin(), got.color.end(), std::uint8_t{0});
    Renderer renderer;
    renderer.render(view, options, view_of(got));
    EXPECT_EQ(got.color, expected.targets.color);
}

TEST(VertexColors, MalformedColorsAreRefusedByName) {
    const RenderOptions options = alpha_test_options();
    Scene nan = gradient_scene(AlphaMode::Blend, false);
    nan.meshes[1].colors[2].y = std::numeric_limits<float>::quiet_NaN();
    expect_input_error_containing([&] { render(nan, options); }, "colors[2] is not finite");
    Scene short_colors = gradient_scene(AlphaMode::Blend, false);
    short_colors.meshes[1].colors.pop_back();
    expect_input_error_containing([&] { render(short_colors, options); },
                                  "3 colors for 4 positions");
    // The classic algorithms refuse them the same way.
    expect_input_error_containing(
        [&] { render_with_visibility(nan, options, VisibilityAlgorithm::Painter); },
        "colors[2] is not finite");
}

}  // namespace
}  // namespace zraster::test
