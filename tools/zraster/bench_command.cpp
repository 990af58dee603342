// `zraster bench`: renders the same frame repeatedly and prints timing statistics, with the
// scene, camera and shading of docs/bench-scenes.md.
#include "bench_command.hpp"

#include <zraster/camera.hpp>
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>
#include <zraster/output_files.hpp>
#include <zraster/scenes.hpp>

#include <fmt/format.h>
#include <hwy/targets.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>
#include <vector>

#include "command_caps.hpp"
#include "command_line.hpp"
#include "output_maps.hpp"

namespace zraster::cli {

void add_bench_command(CLI::App& app, BenchArguments& a) {
    CLI::App* cmd = app.add_subcommand(
        "bench", "Time repeated frames of a scene as the llvmpipe reference harness renders it");
    cmd->add_option("scene", a.scene, "Mesh file, or sphere:N, city:N[:SEED], soup:N[:SEED]")
        ->required();
    cmd->add_option("--mode", a.mode, "depth|flat|phong")
        ->check(CLI::IsMember({"depth", "flat", "phong"}))
        ->capture_default_str();
    cmd->add_option("--size", a.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    cmd->add_option("--frames", a.frames, "Timed frames")->capture_default_str();
    cmd->add_option("--warmup", a.warmup, "Untimed frames before them")->capture_default_str();
    cmd->add_option("--threads", a.threads, "Worker threads (0: all cores)")->capture_default_str();
    cmd->add_option("--max-frame-bytes", a.max_frame_bytes_text,
                    "Refuse scenes whose frame needs more working memory than this (e.g. 8G)")
        ->capture_default_str();
    cmd->add_flag("--no-cull", a.no_cull, "Disable back-face culling");
    cmd->add_flag("--no-hierarchical-z", a.no_hierarchical_z,
                  "Disable hierarchical z (same image, to measure what it saves)");
    cmd->add_flag("--no-cluster-culling", a.no_cluster_culling,
                  "Disable back-face culling of triangle clusters (same image, to measure what "
                  "it saves)");
    cmd->add_flag("--check-meshes", a.check_meshes,
                  "Check every frame that the meshes did not change (hash them), as a Renderer "
                  "does unless told they are static (same image)");
    cmd->add_flag("--front-to-back", a.front_to_back, "Draw instances nearest first");
    cmd->add_flag("--no-avx512", a.no_avx512,
                  "Run the AVX2 kernels where AVX-512 is available (as a machine without it)");
    cmd->add_option("--shading-strategy", a.strategy, "auto | forward | deferred (same image)")
        ->check(CLI::IsMember({"auto", "forward", "deferred"}))
        ->capture_default_str();
    cmd->add_flag("--verbose", a.verbose, "Print every frame's time and the pipeline statistics");
    cmd->add_option("--out", a.out,
                    "Save the last frame as PNG (color; 16-bit depth, 65535 = far, in depth mode)");
}

namespace {

// Timed and warm-up frames each: a million frames is days of a 1080p scene; more is a mistake.
constexpr int kMaxBenchFrames = 1'000'000;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The saved frame's PNG: 16-bit depth in depth mode, else RGB.
std::vector<std::uint8_t> encode_frame(const RenderTargets& t, BenchMode mode) {
    if (mode == BenchMode::Depth) {
        std::vector<std::uint16_t> gray(t.depth.size());
        for (std::size_t i = 0; i < gray.size(); ++i)
            gray[i] = static_cast<std::uint16_t>(
                std::lround(std::clamp(t.depth[i], 0.0f, 1.0f) * 65535.0f));
        return encode_png16_gray(t.width, t.height, gray);
    }
    std::vector<std::uint8_t> rgb(std::size_t(t.width) * std::size_t(t.height) * 3);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
        std::copy_n(&t.color[i * 4], 3, &rgb[i * 3]);
    return encode_png8(t.width, t.height, 3, rgb);
}

// All the frames' work within 2^34 units (about 20 s): a pixel or a triangle one unit each, and
// 50,000 a frame for its fixed costs (about 30 us: a million 1x1 frames took 30 s). bench prints
// nothing until it is done; 10^6 frames of 4096x4096 ran for hours.
void check_bench_work(const BenchArguments& a, std::uint64_t pixels, std::uint64_t triangles) {
    constexpr std::uint64_t kMaxBenchWork = std::uint64_t{1} << 34;
    constexpr std::uint64_t kFrameWork = 50'000;
    const std::uint64_t frames = std::uint64_t(a.frames) + std::uint64_t(a.warmup);
    const std::uint64_t per_frame = pixels + triangles + kFrameWork;
    if (per_frame > kMaxBenchWork / frames)
        throw InputError("--frames", std::to_string(a.frames) + " frames and " +
                                         std::to_string(a.warmup) + " warmup frames of " + a.size +
                                         " with " + std::to_string(triangles) +
                                         " triangles are more work than bench takes in one run "
                                         "(at most " +
                                         std::to_string(kMaxBenchWork / per_frame) +
                                         " frames of these): fewer frames or a smaller --size");
}

}  // namespace

int run_bench(const BenchArguments& a) {
    const BenchMode mode = parse_bench_mode("--mode", a.mode);
    const glm::ivec2 size = parse_size("--size", a.size, kMaxViewport);
    if (a.frames < 1 || a.frames > kMaxBenchFrames)
        throw InputError("--frames", "must be in 1.." + std::to_string(kMaxBenchFrames) + ", not " +
                                         std::to_string(a.frames));
    if (a.warmup < 0 || a.warmup > kMaxBenchFrames)
        throw InputError("--warmup", "must be in 0.." + std::to_string(kMaxBenchFrames) + ", not " +
                                         std::to_string(a.warmup));
    if (command_caps().max_frames != 0 && a.frames + a.warmup > command_caps().max_frames)
        throw InputError("--frames",
                         "with --warmup " + std::to_string(a.warmup) + ", " +
                             std::to_string(a.frames + a.warmup) + " frames, more than the " +
                             std::to_string(command_caps().max_frames) + " this run allows");
    check_samples_cap("--size", size.x, size.y, 1);
    // The renderer's pixel limit (render's --max-pixels default), named here: bench times frames
    // of an ordinary size and has no flag to raise it.
    const std::uint64_t pixels = std::uint64_t(size.x) * std::uint64_t(size.y);
    if (pixels > RenderLimits{}.max_pixels)
        throw InputError("--size", a.size + " is " + std::to_string(pixels) +
                                       " pixels, more than the renderer's limit of " +
                                       std::to_string(RenderLimits{}.max_pixels) +
                                       " (render --max-pixels raises it; bench does not)");
    const int threads = capped_threads("--threads", checked_thread_count("--threads", a.threads));
    const std::uint64_t max_frame_bytes =
        parse_byte_size("--max-frame-bytes", a.max_frame_bytes_text);
    OutputFiles outputs;  // --out, checked before any work
    check_output(outputs, a.out, {".png"}, "--out");
    outputs.check_input(a.scene, "");
    if (a.no_avx512) hwy::DisableTargets(HWY_AVX2 - 1);  // the targets better than AVX2

    // Loading, shading setup and framing stay outside the timed loop, as in glbench.
    Scene scene = load_scene_or_procedural(a.scene, nullptr, &outputs);
    check_bench_work(a, pixels, scene.triangle_count());
    apply_bench_shading(scene, mode);
    RenderOptions options = bench_render_options(mode, size.x, size.y, threads, !a.no_cull);
    options.hierarchical_z = !a.no_hierarchical_z;
    options.cluster_culling = !a.no_cluster_culling;
    options.static_meshes = !a.check_meshes;
    if (a.front_to_back) options.instance_order = InstanceOrder::FrontToBack;
    options.strategy = shading_strategy(a.strategy);
    // The same fit_camera framing render() does for an unset camera, computed once: refitting
    // every frame would time a scan over all vertices that glbench does not do per frame.
    options.limits.max_frame_bytes = max_frame_bytes;
    check_instanced_vertices(scene, max_frame_bytes);
    options.camera = fit_camera(scene.world_positions());
    const Camera& cam = *options.camera;
    const std::size_t tris = scene.triangle_count();
    if (scene.meshes.size() == 1 && scene.instances.size() == 1)
        fmt::print("scene {}: {} vertices, {} triangles, geometry_hash {:016x}\n", a.scene,
                   scene.vertex_count(), tris, geometry_hash(scene.meshes[0]));
    else
        fmt::print("scene {}: {} instances, {} vertices, {} triangles\n", a.scene,
                   scene.instances.size(), scene.vertex_count(), tris);
    fmt::print(
        "camera eye ({:.9g} {:.9g} {:.9g}) target ({:.9g} {:.9g} {:.9g}) near {:.9g} far "
        "{:.9g}\n",
        float(cam.eye.x), float(cam.eye.y), float(cam.eye.z), float(cam.target.x),
        float(cam.target.y), float(cam.target.z), float(cam.near), float(cam.far));

    using Clock = std::chrono::steady_clock;
    std::vector<double> warm_ms, frame_ms;
    // One Renderer for all frames, as an application keeps one (llvmpipe keeps its context):
    // its arrays and targets are reused, not reallocated and page-faulted in every frame.
    Renderer renderer;
    const RenderResult* last = nullptr;
    for (int f = 0; f < a.warmup + a.frames; ++f) {
        const auto t0 = Clock::now();
        const RenderResult& result = renderer.render(scene, options);
        last = &result;
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        (f < a.warmup ? warm_ms : frame_ms).push_back(ms);
        if (a.verbose)
            fmt::print(
                "{} {}: {:.3f} ms (setup {:.3f}, raster {:.3f}), {} rasterized, {} "
                "fragments passed, {} shaded ({}), {} blocks hidden by hierarchical z, {} "
                "clusters culled, {} vertices skipped; front end: vertices {:.3f}, assembly "
                "{:.3f}, "
                "binning {:.3f}\n",
                f < a.warmup ? "warmup" : "frame", f < a.warmup ? f : f - a.warmup, ms,
                result.stats.setup_ms, result.stats.raster_ms, result.stats.triangles_rasterized,
                result.stats.fragments_passed, result.stats.fragments_shaded,
                result.stats.deferred ? "deferred" : "forward", result.stats.blocks_hidden,
                result.stats.clusters_culled, result.stats.vertices_skipped, result.stats.vertex_ms,
                result.stats.assembly_ms, result.stats.binning_ms);
    }
    if (!a.out.empty()) {
        outputs.add(a.out, encode_frame(last->targets, mode));
        outputs.commit();
    }

    fmt::print(
        "RESULT scene={} mode={} w={} h={} threads={} tris={} ms_median={:.3f} "
        "ms_min={:.3f}\n",
        a.scene, bench_mode_name(mode), size.x, size.y, effective_thread_count(threads), tris,
        median(frame_ms), *std::min_element(frame_ms.begin(), frame_ms.end()));
    return kExitOk;
}

}  // namespace zraster::cli
