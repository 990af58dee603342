// `zraster bench`: times render() on one scene, framed and shaded as the llvmpipe reference
// harness does (../shared/docs/BENCH-SCENES.md), so the numbers compare with glbench's.
#pragma once
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <CLI/CLI.hpp>

#include <string>

namespace zraster::cli {

struct BenchArguments {
    std::string scene;
    std::string mode = "phong";
    std::string size = "1920x1080";
    int frames = 20;
    int warmup = 2;
    int threads = 0;
    bool no_cull = false;
    bool no_hierarchical_z = false;
    bool no_cluster_culling = false;
    bool check_meshes = false;
    bool front_to_back = false;
    bool no_avx512 = false;
    std::string strategy = "auto";
    bool verbose = false;
    std::string out;
};

// The three shadings of BENCH-SCENES.md ("Render state and shading").
enum class BenchMode { Depth, Flat, Phong };

// "depth" | "flat" | "phong"; throws InputError naming `option` otherwise.
BenchMode parse_bench_mode(const std::string& option, const std::string& text);
const char* bench_mode_name(BenchMode mode);

// Replaces every material by the benchmark's (default Material for phong, base color
// (0.9, 0.6, 0.3) for flat) and drops per-instance shading overrides, so a mesh file's own
// materials cannot change the workload.
void apply_bench_shading(Scene& scene, BenchMode mode);

// The benchmark render state: LESS, clear 1, back faces culled (CCW front) unless !cull,
// background 0.2, two-sided Blinn-Phong with a local viewer; depth mode has no color target.
// The camera is left unset (fit_camera framing).
RenderOptions bench_render_options(BenchMode mode, int width, int height, int threads, bool cull);

// Threads render() actually uses for `threads` (0 = all hardware threads).
int effective_thread_count(int threads);

void add_bench_command(CLI::App& app, BenchArguments& arguments);
int run_bench(const BenchArguments& arguments);

}  // namespace zraster::cli
