// `zraster explain zbuffer`: the color and depth buffers after every k-th triangle.
#include <zraster/render.hpp>

#include <fmt/format.h>

#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

// The scene with only its first `count` triangles, in submission order (instance by instance).
// The instances drawn whole keep their shared meshes; only the last one cut short gets a copy
// (a copy per instance made 65,536 copies of one mesh for building:256x256).
Scene first_triangles(const Scene& scene, std::size_t count) {
    Scene out = scene;
    out.instances.clear();
    for (const Instance& instance : scene.instances) {
        if (count == 0) break;
        Instance copy = instance;
        const std::size_t triangles = scene.meshes[instance.mesh].triangle_count();
        if (count < triangles) {
            Mesh mesh = scene.meshes[instance.mesh];
            mesh.indices.resize(count * 3);
            copy.mesh = std::uint32_t(out.meshes.size());
            out.meshes.push_back(std::move(mesh));
        }
        count -= std::min(count, triangles);
        out.instances.push_back(std::move(copy));
    }
    // A cell graph (building:RxC) is for every instance: the frames short of some have none.
    if (out.instances.size() != scene.instances.size()) out.cells = nullptr;
    return out;
}

}  // namespace

void explain_zbuffer(const ExplainInput& in, ExplainOutput& out) {
    const std::size_t total = in.scene.triangle_count();
    const float clear = depth_clear_value(in.options);
    const std::vector<std::size_t> counts = frame_counts(total, in.step);
    // Each frame is the color and the depth buffer side by side.
    check_explain_pixels(
        counts.size(), (2 * std::uint64_t(in.options.width) + 4) * std::uint64_t(in.options.height),
        in.max_pixels, fmt::format("explain zbuffer's {} frames", counts.size()),
        "or raise --step");
    std::vector<RgbaImage> frames;
    Renderer renderer;
    for (const std::size_t n : counts) {
        if (in.options.progress != nullptr)
            in.options.progress->report("explain zbuffer: drawing the frames",
                                        double(frames.size()) / double(counts.size()));
        const RenderResult& r = renderer.render(first_triangles(in.scene, n), in.options);
        frames.push_back(captioned(
            side_by_side(color_image(r.targets), depth_image(r.targets, clear)),
            fmt::format("after {} of {} triangles: {} drawn, {} depth-tested fragments passed", n,
                        total, r.stats.triangles_rasterized, r.stats.fragments_passed)));
    }
    for (std::size_t i = 0; i < frames.size(); ++i) {
        if (in.options.progress != nullptr)
            in.options.progress->report("explain zbuffer: encoding the pictures",
                                        double(i) / double(frames.size()));
        out.still(fmt::format("zbuffer-{:02}", i + 1), frames[i],
                  fmt::format("frame {} of {}: color (left) and depth buffer (right)", i + 1,
                              frames.size()));
    }
    if (in.options.progress != nullptr)
        in.options.progress->report("explain zbuffer: encoding the animation", 0.0);
    out.animation("zbuffer-animation", frames, 700, "the frames above in sequence");
}

}  // namespace zraster::cli
