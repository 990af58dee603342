// `zraster explain zbuffer`: the color and depth buffers after every k-th triangle.
#include <zraster/render.hpp>

#include <fmt/format.h>

#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

// The scene with only its first `count` triangles, in submission order (instance by instance).
Scene first_triangles(const Scene& scene, std::size_t count) {
    Scene out = scene;
    out.instances.clear();
    out.meshes.clear();
    for (const Instance& instance : scene.instances) {
        if (count == 0) break;
        Mesh mesh = scene.meshes[instance.mesh];
        const std::size_t keep = std::min(count, mesh.triangle_count());
        mesh.indices.resize(keep * 3);
        count -= keep;
        Instance copy = instance;
        copy.mesh = std::uint32_t(out.meshes.size());
        out.meshes.push_back(std::move(mesh));
        out.instances.push_back(std::move(copy));
    }
    return out;
}

}  // namespace

void explain_zbuffer(const ExplainInput& in, ExplainOutput& out) {
    const std::size_t total = in.scene.triangle_count();
    const float clear = depth_clear_value(in.options);
    std::vector<RgbaImage> frames;
    Renderer renderer;
    for (const std::size_t n : frame_counts(total, in.step)) {
        const RenderResult& r = renderer.render(first_triangles(in.scene, n), in.options);
        frames.push_back(captioned(
            side_by_side(color_image(r.targets), depth_image(r.targets, clear)),
            fmt::format("after {} of {} triangles: {} drawn, {} depth-tested fragments passed", n,
                        total, r.stats.triangles_rasterized, r.stats.fragments_passed)));
    }
    for (std::size_t i = 0; i < frames.size(); ++i)
        out.still(fmt::format("zbuffer-{:02}", i + 1), frames[i],
                  fmt::format("frame {} of {}: color (left) and depth buffer (right)", i + 1,
                              frames.size()));
    out.animation("zbuffer-animation", frames, 700, "the frames above in sequence");
}

}  // namespace zraster::cli
