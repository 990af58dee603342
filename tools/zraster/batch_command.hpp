// `zraster batch INPUT... -o OUTDIR`: every mesh file of a collection rendered as `zraster render`
// renders one, with a JSON Lines log, progress, resumable runs and shards (docs/batch.md).
#pragma once
#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "render_arguments.hpp"

namespace zraster::cli {

struct BatchArguments {
    RenderArguments render;  // every `zraster render` flag but the scene and the output paths
    std::vector<std::string> inputs, lists;
    std::string out_dir, log;
    std::string depth, z, id;  // output formats ("npy" | "png"); empty: not written
    bool range = false, normal = false, points = false, camera_json = false;
    int views = 0;
    double elevation = 20.0;
    std::string views_json;
    int jobs = 0;
    std::uint64_t max_triangles = 50'000'000;
    std::string max_memory;  // empty: default_max_memory(jobs)
    bool force = false;
    std::string shard;
    std::string progress = "auto";
};

void add_batch_command(CLI::App& app, BatchArguments& arguments);

// Exit status: 0 every input ok or skipped, 3 some failed (the others rendered), 2 bad usage
// (nothing rendered), 1 internal error (the log could not be written); after SIGINT or SIGTERM
// 128 + the signal's number (the shell's convention), the log holding the inputs finished.
int run_batch(const BatchArguments& arguments);

}  // namespace zraster::cli
