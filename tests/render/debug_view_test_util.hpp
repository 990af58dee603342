// Scenes and pixel helpers for the debug view tests (debug_view_*_test.cpp).
#pragma once
#include <zraster/debug_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/scenes.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "render_test_util.hpp"

namespace zraster::test {

using ViewRgb = std::array<std::uint8_t, 3>;

inline RenderOptions view_options(int width, int height, DebugView view) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.threads = 2;
    o.view = view;
    return o;
}

inline Camera looking_down_z(double eye_z, double near, double far) {
    Camera c;
    c.eye = {0.0, 0.0, eye_z};
    c.target = {0.0, 0.0, 0.0};
    c.near = near;
    c.far = far;
    return c;
}

inline ViewRgb pixel(const RenderTargets& t, int px, int py) {
    const std::size_t at = (std::size_t(py) * std::size_t(t.width) + std::size_t(px)) * 4;
    return {t.color[at], t.color[at + 1], t.color[at + 2]};
}

// The color the overdraw, hiz and tiles views give a count (the library's log scale).
inline ViewRgb expected_count_color(std::uint64_t count, std::uint64_t largest) {
    if (count == 0) return {0, 0, 0};
    const double t = largest > 1 ? std::log(double(count)) / std::log(double(largest)) : 1.0;
    return debug_view_scale_color(t);
}

// Where on the color scale a color lies (the nearest of 1025 samples).
inline double scale_position(ViewRgb c) {
    double best = 0.0;
    int best_distance = 1 << 30;
    for (int i = 0; i <= 1024; ++i) {
        const ViewRgb s = debug_view_scale_color(i / 1024.0);
        int d = 0;
        for (std::size_t k = 0; k < 3; ++k) d += (int(s[k]) - c[k]) * (int(s[k]) - c[k]);
        if (d < best_distance) {
            best_distance = d;
            best = i / 1024.0;
        }
    }
    return best;
}

// An axis-aligned quad in the plane z (counter-clockwise seen from +z, or clockwise).
inline std::vector<glm::vec3> quad(float x0, float y0, float x1, float y1, float z,
                                   bool facing_plus_z = true) {
    std::vector<glm::vec3> q{{x0, y0, z}, {x1, y0, z}, {x1, y1, z},
                             {x0, y0, z}, {x1, y1, z}, {x0, y1, z}};
    if (!facing_plus_z) {
        std::swap(q[1], q[2]);
        std::swap(q[4], q[5]);
    }
    return q;
}

// A large wall at z = 0.5 drawn first, then 20 walls behind it (hierarchical z hides them).
inline Scene occluder_scene() {
    std::vector<std::vector<glm::vec3>> meshes{quad(-3, -3, 3, 3, 0.5f)};
    for (int i = 0; i < 20; ++i) meshes.push_back(quad(-2, -2, 2, 2, -0.05f * float(i)));
    return scene_from_triangles(meshes);
}

// Two nearly coplanar quads (1e-4 apart at about 3 from the eye), the far one drawn first:
// D16 cannot tell them apart, so the near one loses where their depths quantize equal.
inline Scene zfight_scene() {
    return scene_from_triangles({quad(-1, -1, 1, 1, 0.0f), quad(-0.6f, -0.6f, 0.6f, 0.6f, 1e-4f)});
}

// A checkered ground plane seen from a low eye: farther rows need coarser mip levels.
inline Scene textured_plane_scene() {
    Scene scene = scene_from_meshes({make_ground_plane(40.0f, 40.0f)});
    Material m;
    m.name = "checker";
    m.base_color = glm::vec3(1.0f);
    m.base_color_texture = std::make_shared<Texture>(
        make_checkerboard_texture(8, 32, {255, 255, 255, 255}, {30, 30, 30, 255}));
    scene.materials.push_back(m);
    scene.meshes[0].material = 1;
    return scene;
}

inline Camera low_camera() {
    Camera c;
    c.eye = {0.0, 1.0, 8.0};
    c.target = {0.0, 0.0, -10.0};
    c.near = 0.1;
    c.far = 100.0;
    return c;
}

}  // namespace zraster::test
