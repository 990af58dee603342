// Scenes of the alpha-mode tests (tests/render/alpha_modes_test.cpp, the z-buffer;
// tests/visibility/alpha_paths_test.cpp, every other path): squares facing an orthographic
// camera at 64 x 64, Unlit so colors are base colors, and the analytic "over" to check them by.
#pragma once
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/texture.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>

#include <gtest/gtest.h>

#include <utility>
#include "support/test_support.hpp"

namespace zraster::test {

inline constexpr int kAlphaImage = 64;

// Orthographic on +z: world (x, y) lands on window (x + 32, 32 - y), so a square from -h to h
// covers the pixels 32 - h .. 32 + h - 1 each way.
inline RenderOptions alpha_test_options() {
    RenderOptions o;
    o.width = kAlphaImage;
    o.height = kAlphaImage;
    o.threads = 2;
    o.shading = ShadingMode::Unlit;  // colors = base colors, for the analytic blend
    o.background = {0.25f, 0.5f, 0.75f};
    Camera c;
    c.eye = {0.0, 0.0, 8.0};
    c.target = {0.0, 0.0, 0.0};
    c.projection = Camera::Projection::Orthographic;
    c.ortho_height = kAlphaImage;
    c.near = 1.0;
    c.far = 20.0;
    o.camera = c;
    return o;
}

// A square of half-width h at depth z, as two triangles with texture coordinates 0..1.
inline Mesh alpha_test_square(float h, float z) {
    Mesh m;
    m.positions = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
    m.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.indices = {0, 1, 2, 0, 2, 3};
    update_bounds(m);
    return m;
}

struct AlphaLayer {
    float half_width, z;
    glm::vec3 color;
    float opacity;
};

// Far opaque, then two blended layers nearer, each smaller.
inline constexpr std::array<AlphaLayer, 3> kAlphaLayers = {{
    {20.0f, -2.0f, {0.9f, 0.2f, 0.1f}, 1.0f},
    {14.0f, 0.0f, {0.1f, 0.8f, 0.3f}, 0.5f},
    {8.0f, 2.0f, {0.2f, 0.3f, 0.9f}, 0.35f},
}};

// The squares layers[order[0]], layers[order[1]], ... in that submission order, a material each
// (material 0 is a default one nothing uses).
inline Scene alpha_layers_scene(std::span<const AlphaLayer> layers, std::span<const int> order) {
    Scene scene;
    scene.materials.push_back(Material{});
    for (const int k : order) {
        const AlphaLayer& layer = layers[std::size_t(k)];
        Material m;
        m.base_color = layer.color;
        m.opacity = layer.opacity;
        scene.materials.push_back(m);
        Mesh mesh = alpha_test_square(layer.half_width, layer.z);
        mesh.material = std::uint32_t(scene.materials.size() - 1);
        scene.meshes.push_back(std::move(mesh));
        Instance instance;
        instance.mesh = std::uint32_t(scene.meshes.size() - 1);
        scene.instances.push_back(instance);
    }
    return scene;
}

inline Scene alpha_layers_scene(std::span<const AlphaLayer> layers,
                                std::initializer_list<int> order) {
    return alpha_layers_scene(layers, std::span<const int>(order.begin(), order.size()));
}

// A wall and, in front of it, a square with a checkerboard of transparent and opaque 8x8-pixel
// cells (texel alpha 0 and 255) in alpha mode `mode`: the transparent cells show (and keep the
// depth and ids of) the wall. `cut_out_first`: the square is submitted before the wall.
inline Scene checker_scene(AlphaMode mode, bool cut_out_first) {
    Scene scene;
    Material wall;
    wall.base_color = {0.9f, 0.2f, 0.1f};
    Material front;
    front.base_color = {1.0f, 1.0f, 1.0f};
    front.alpha_mode = mode;
    front.alpha_cutoff = 0.5f;
    // 4 x 4 cells of 16 texels over a square 32 pixels wide: 8 pixels a cell.
    front.base_color_texture = std::make_shared<Texture>(
        make_checkerboard_texture(4, 16, {40, 200, 60, 0}, {40, 200, 60, 255}));
    scene.materials = {wall, front};
    Mesh far = alpha_test_square(24.0f, -2.0f);
    Mesh near = alpha_test_square(16.0f, 1.0f);
    near.material = 1;
    scene.meshes = {far, near};
    scene.instances.resize(2);
    scene.instances[1].mesh = 1;
    if (cut_out_first) std::swap(scene.instances[0], scene.instances[1]);
    return scene;
}

// The analytic "over" where the first `layers` of kAlphaLayers overlap (3: inside all of them).
inline glm::dvec3 alpha_over(int layers) {
    glm::dvec3 c(kAlphaLayers[0].color);
    for (int k = 1; k < layers; ++k)
        c = double(kAlphaLayers[std::size_t(k)].opacity) *
                glm::dvec3(kAlphaLayers[std::size_t(k)].color) +
            (1.0 - double(kAlphaLayers[std::size_t(k)].opacity)) * c;
    return c;
}

// kAlphaLayers drawn by draw(scene) in all 6 submission orders: one color and depth image,
// returned.
template <class Draw>
RenderResult same_image_in_every_order(const Draw& draw) {
    std::array<int, 3> order = {0, 1, 2};
    RenderResult first;
    int orders = 0;
    do {
        const RenderResult r = draw(alpha_layers_scene(kAlphaLayers, order));
        if (orders++ == 0) {
            first = r;
            continue;
        }
        EXPECT_EQ(r.targets.color, first.targets.color)
            << "order " << order[0] << order[1] << order[2];
        EXPECT_TRUE(same_bits(r.targets.depth, first.targets.depth));
    } while (std::next_permutation(order.begin(), order.end()));
    EXPECT_EQ(orders, 6);
    return first;
}

// The scene drawn with each of the pipeline's exact optimizations turned off in turn (SIMD,
// hierarchical z), occlusion culling on, cluster culling off, one thread with forward shading:
// the same color and depth as with `options` as given, which it returns.
inline RenderResult same_image_under_every_optimization(const Scene& scene,
                                                        const RenderOptions& options) {
    const RenderResult reference = render(scene, options);
    for (int variant = 0; variant < 5; ++variant) {
        RenderOptions o = options;
        o.simd = variant != 0;
        o.hierarchical_z = variant != 1;
        o.occlusion_cull = variant == 2;
        o.cluster_culling = variant != 3;
        o.threads = variant == 4 ? 1 : 2;
        o.strategy = variant == 4 ? ShadingStrategy::Forward : ShadingStrategy::Auto;
        const RenderResult r = render(scene, o);
        EXPECT_EQ(r.targets.color, reference.targets.color) << "variant " << variant;
        EXPECT_TRUE(same_bits(r.targets.depth, reference.targets.depth)) << "variant " << variant;
    }
    return reference;
}

// An analytic channel value as an 8-bit target stores it.
inline int analytic_unorm8(double v) {
    return int(std::clamp(float(v), 0.0f, 1.0f) * 255.0f + 0.5f);
}

// The RGB of pixel (px, py) of a kAlphaImage-wide color target.
inline glm::ivec3 alpha_test_rgb(const RenderResult& r, int px, int py) {
    const std::uint8_t* p = &r.targets.color[(std::size_t(py) * kAlphaImage + std::size_t(px)) * 4];
    return {p[0], p[1], p[2]};
}

}  // namespace zraster::test
