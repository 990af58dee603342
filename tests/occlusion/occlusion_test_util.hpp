// Scenes of occluders and test boxes, and the exact answer for each box from zraster's own exact
// z-buffer (Renderer, D32F, LESS): the box is visible when one of its pixels is nearer than the
// occluders' depth at that pixel.
#pragma once
#include <zraster/occlusion_buffer.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <vector>

namespace zraster::test {

struct Placed {
    glm::vec3 half_extent;
    glm::mat4 transform;  // object to world
};

struct OcclusionScene {
    Camera camera;
    int width = 480, height = 270;
    std::vector<Placed> occluders;
    std::vector<Placed> boxes;  // the objects to test
};

inline Scene boxes_scene(const std::vector<Placed>& placed) {
    Scene scene;
    for (const Placed& p : placed) {
        Instance instance;
        instance.mesh = static_cast<std::uint32_t>(scene.meshes.size());
        instance.transform = p.transform;
        scene.meshes.push_back(make_box(p.half_extent));
        scene.instances.push_back(instance);
    }
    return scene;
}

inline RenderOptions exact_options(const OcclusionScene& s) {
    RenderOptions o;
    o.width = s.width;
    o.height = s.height;
    o.camera = s.camera;
    o.color_target = false;
    o.id_targets = true;
    o.threads = 1;
    return o;
}

enum class Exact { NoPixels, Visible, Hidden };

// For each test box: NoPixels (outside the view or between pixel centers), Visible or Hidden.
inline std::vector<Exact> exact_visibility(const OcclusionScene& s) {
    const RenderOptions options = exact_options(s);
    Renderer renderer;
    const std::vector<float> occluder_depth =
        renderer.render(boxes_scene(s.occluders), options).targets.depth;
    std::vector<Exact> out;
    for (const Placed& box : s.boxes) {
        const RenderTargets& t = renderer.render(boxes_scene({box}), options).targets;
        Exact e = Exact::NoPixels;
        for (std::size_t i = 0; i < t.depth.size(); ++i) {
            if (t.instance_id[i] < 0) continue;
            if (t.depth[i] < occluder_depth[i]) {
                e = Exact::Visible;
                break;
            }
            e = Exact::Hidden;
        }
        out.push_back(e);
    }
    return out;
}

inline glm::mat4 view_projection(const OcclusionScene& s) {
    return s.camera.view_projection(double(s.width) / double(s.height));
}

// The buffer's answers, with the occluders drawn as engines draw them for MSOC-style buffers:
// nearest first (by the distance of their centers), back faces culled; with the 1/256-pixel
// margin of the Renderer's vertex snapping, since the Renderer is the exact reference.
inline std::vector<OcclusionResult> buffer_answers(const OcclusionScene& s, bool simd = true) {
    OcclusionBuffer buffer(s.width, s.height);
    buffer.set_simd(simd);
    const glm::mat4 vp = view_projection(s);
    std::vector<Placed> occluders = s.occluders;
    const auto distance = [&](const Placed& p) {
        return glm::length(glm::dvec3(p.transform[3]) - s.camera.eye);
    };
    std::stable_sort(occluders.begin(), occluders.end(),
                     [&](const Placed& a, const Placed& b) { return distance(a) < distance(b); });
    for (const Placed& p : occluders) {
        const Mesh box = make_box(p.half_extent);
        OccluderOptions options;
        options.subpixel_margin = 1.0f / 256.0f;
        buffer.render_occluders(std::span<const glm::vec3>(box.positions), box.indices,
                                vp * p.transform, options);
    }
    std::vector<OcclusionResult> out;
    for (const Placed& p : s.boxes)
        out.push_back(buffer.test_box(Bounds3f{-p.half_extent, p.half_extent}, vp * p.transform));
    return out;
}

inline glm::mat4 place(glm::vec3 at, float yaw_radians = 0.0f) {
    return glm::rotate(glm::translate(glm::mat4(1.0f), at), yaw_radians, glm::vec3(0, 1, 0));
}

// 320x180 (or the given size), 2 threads, id targets, the camera at (0, 0, 4) looking down -z:
// the renderer-level scenes of walls and objects in front of it.
inline RenderOptions wall_view_options(int width = 320, int height = 180) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.threads = 2;
    o.id_targets = true;
    Camera c;
    c.eye = {0, 0, 4};
    c.target = {0, 0, -10};
    c.near = 0.5;
    c.far = 100.0;
    o.camera = c;
    return o;
}

// A city: a grid of buildings on a ground slab, the camera in a street at head height looking
// along it, and small objects (boxes of 0.3 to 1.5 units) strewn over the blocks and streets.
inline OcclusionScene city_scene(std::uint64_t seed, int objects) {
    SplitMix64 rng(seed);
    OcclusionScene s;
    s.occluders.push_back({glm::vec3(200.0f, 0.5f, 200.0f), place({0.0f, -0.5f, 0.0f})});
    for (int i = -8; i <= 8; ++i)
        for (int j = -8; j <= 8; ++j) {
            const float h = static_cast<float>(rng.uniform(3.0, 25.0));
            const float wx = static_cast<float>(rng.uniform(3.0, 4.5));
            const float wz = static_cast<float>(rng.uniform(3.0, 4.5));
            s.occluders.push_back(
                {glm::vec3(wx, h * 0.5f, wz), place({i * 12.0f, h * 0.5f, j * 12.0f},
                                                    static_cast<float>(rng.uniform(-0.2, 0.2)))});
        }
    const double street = 6.0 + 12.0 * static_cast<int>(rng.uniform(-3.0, 3.0));
    // One draw per statement: the order of a call's arguments is unspecified, and GCC and clang
    // differ, which would give each compiler a different scene.
    const double eye_x = street + rng.uniform(-1.0, 1.0);
    const double eye_y = rng.uniform(1.5, 4.0);
    s.camera.eye = glm::dvec3(eye_x, eye_y, 90.0);
    s.camera.target = glm::dvec3(street + rng.uniform(-15.0, 15.0), 2.0, -20.0);
    s.camera.near = 0.5;
    s.camera.far = 400.0;
    for (int k = 0; k < objects; ++k) {
        const float e = static_cast<float>(rng.uniform(0.3, 1.5));
        const float at_x = static_cast<float>(rng.uniform(-100.0, 100.0));
        const float at_z = static_cast<float>(rng.uniform(-100.0, 80.0));
        const glm::vec3 at(at_x, e, at_z);
        s.boxes.push_back({glm::vec3(e), place(at, static_cast<float>(rng.uniform(0.0, 3.0)))});
    }
    return s;
}

// Random large occluders (walls and blocks of 4 to 30 units, 5 to 40 units away, any
// orientation) in front of random boxes 10 to 80 units away.
inline OcclusionScene random_occluder_scene(std::uint64_t seed, int objects) {
    SplitMix64 rng(seed);
    OcclusionScene s;
    s.camera.eye = glm::dvec3(0.0);
    s.camera.target = glm::dvec3(0.0, 0.0, -1.0);
    s.camera.near = 0.25;
    s.camera.far = 200.0;
    const auto rotation = [&] {
        glm::mat4 r(1.0f);
        r = glm::rotate(r, static_cast<float>(rng.uniform(0.0, 6.3)), glm::vec3(0, 1, 0));
        r = glm::rotate(r, static_cast<float>(rng.uniform(-0.6, 0.6)), glm::vec3(1, 0, 0));
        return r;
    };
    for (int k = 0; k < 12; ++k) {
        const float z = static_cast<float>(rng.uniform(-40.0, -5.0));
        const float at_x = static_cast<float>(rng.uniform(0.5, -0.5) * z);
        const float at_y = static_cast<float>(rng.uniform(0.3, -0.3) * z);
        const glm::vec3 at(at_x, at_y, z);
        const float half_x = static_cast<float>(rng.uniform(2.0, 15.0));
        const float half_y = static_cast<float>(rng.uniform(2.0, 15.0));
        const float half_z = static_cast<float>(rng.uniform(0.2, 6.0));
        const glm::vec3 half(half_x, half_y, half_z);
        s.occluders.push_back({half, glm::translate(glm::mat4(1.0f), at) * rotation()});
    }
    for (int k = 0; k < objects; ++k) {
        const float z = static_cast<float>(rng.uniform(-80.0, -10.0));
        const float at_x = static_cast<float>(rng.uniform(0.6, -0.6) * z);
        const float at_y = static_cast<float>(rng.uniform(0.35, -0.35) * z);
        const glm::vec3 at(at_x, at_y, z);
        const float e = static_cast<float>(rng.uniform(0.2, 2.0));
        s.boxes.push_back({glm::vec3(e, e * static_cast<float>(rng.uniform(0.5, 2.0)), e),
                           glm::translate(glm::mat4(1.0f), at) * rotation()});
    }
    return s;
}

// Boxes peeking around the edges of walls: each box sits just behind a random wall (0.05 to 2
// units), near one of its side or top edges, so many are barely visible or barely hidden. The
// hard case for conservativeness.
inline OcclusionScene peeking_scene(std::uint64_t seed, int objects) {
    SplitMix64 rng(seed);
    OcclusionScene s;
    s.camera.eye = glm::dvec3(0.0, 2.0, 0.0);
    s.camera.target = glm::dvec3(0.0, 2.0, -1.0);
    s.camera.near = 0.3;
    s.camera.far = 150.0;
    struct Wall {
        glm::vec3 half;
        glm::mat4 transform;
    };
    std::vector<Wall> walls;
    for (int k = 0; k < 8; ++k) {
        const float z = static_cast<float>(rng.uniform(-40.0, -6.0));
        const float at_x = static_cast<float>(rng.uniform(0.5, -0.5) * z);
        const float at_y = static_cast<float>(rng.uniform(0.2, -0.2) * z);
        const glm::vec3 at(at_x, at_y, z);
        const float half_x = static_cast<float>(rng.uniform(1.0, 6.0));
        const float half_y = static_cast<float>(rng.uniform(1.0, 5.0));
        const glm::vec3 half(half_x, half_y, 0.25f);
        const float yaw = static_cast<float>(rng.uniform(-0.7, 0.7));
        walls.push_back({half, place(at, yaw)});
        s.occluders.push_back({half, place(at, yaw)});
    }
    for (int k = 0; k < objects; ++k) {
        const Wall& w = walls[static_cast<std::size_t>(rng.uniform(0.0, 8.0))];
        // A point on the wall's back face near one of its edges, in the wall's frame.
        const float u = static_cast<float>(rng.uniform(-1.0, 1.0));
        const float v = static_cast<float>(rng.uniform(-1.0, 1.0));
        glm::vec3 p(u * w.half.x, v * w.half.y, -w.half.z);
        const float edge = static_cast<float>(rng.uniform(-0.6, 0.6));
        if (rng.unit() < 0.5)
            p.x = (p.x < 0 ? -w.half.x : w.half.x) + edge;
        else
            p.y = (p.y < 0 ? -w.half.y : w.half.y) + edge;
        const float e = static_cast<float>(rng.uniform(0.05, 0.6));
        p.z -= e + static_cast<float>(rng.uniform(0.05, 2.0));
        const glm::vec3 world(w.transform * glm::vec4(p, 1.0f));
        s.boxes.push_back({glm::vec3(e), place(world, static_cast<float>(rng.uniform(0.0, 3.0)))});
    }
    return s;
}

}  // namespace zraster::test
