// `zraster bench`: times render() on one scene, framed and shaded as the llvmpipe reference
// harness does (docs/bench-scenes.md), so the numbers compare with glbench's.
#pragma once
#include <zraster/bench_workload.hpp>
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
    std::string max_frame_bytes_text = "4G";  // RenderLimits::max_frame_bytes, as a size
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

void add_bench_command(CLI::App& app, BenchArguments& arguments);
int run_bench(const BenchArguments& arguments);

}  // namespace zraster::cli
