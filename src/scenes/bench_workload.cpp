// The benchmark workload of docs/bench-scenes.md: shadings and render state (see the header).
#include <zraster/bench_workload.hpp>
#include <zraster/error.hpp>

#include <algorithm>
#include <thread>

namespace zraster {

BenchMode parse_bench_mode(const std::string& option, const std::string& text) {
    if (text == "depth") return BenchMode::Depth;
    if (text == "flat") return BenchMode::Flat;
    if (text == "phong") return BenchMode::Phong;
    throw InputError(option, "expected depth, flat or phong, got '" + text + "'");
}

const char* bench_mode_name(BenchMode mode) {
    switch (mode) {
        case BenchMode::Depth:
            return "depth";
        case BenchMode::Flat:
            return "flat";
        case BenchMode::Phong:
            return "phong";
    }
    return "?";
}

void apply_bench_shading(Scene& scene, BenchMode mode) {
    Material material;  // the defaults are the benchmark's phong material
    if (mode == BenchMode::Flat) material.base_color = {0.9f, 0.6f, 0.3f};
    for (Material& m : scene.materials) m = material;
    for (Instance& instance : scene.instances) instance.shading.reset();
}

RenderOptions bench_render_options(BenchMode mode, int width, int height, int threads, bool cull) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.threads = threads;
    o.shading = mode == BenchMode::Flat ? ShadingMode::Unlit : ShadingMode::Phong;
    o.lighting = LightingModel{};  // Blinn-Phong, local viewer, light (-1/3, 2/3, 2/3)
    o.two_sided_lighting = true;
    o.textures = false;
    o.cull = cull ? CullMode::Back : CullMode::None;
    o.front_face = FrontFace::CounterClockwise;
    o.depth_format = DepthFormat::D32F;  // glbench's default DEPTH_COMPONENT32F
    o.depth_compare = CompareFunc::Less;
    o.depth_test = true;
    o.depth_write = true;
    o.background = {0.2f, 0.2f, 0.2f};
    o.color_target = mode != BenchMode::Depth;
    // The scene does not change from frame to frame, as glbench's static vertex buffers do not.
    o.static_meshes = true;
    return o;
}

int effective_thread_count(int threads) {
    return threads > 0 ? threads
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace zraster
