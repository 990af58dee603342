// `zraster batch`: the flags, the checks before any work, and the summary.
#include "batch_command.hpp"

#include <zraster/error.hpp>

#include <fmt/format.h>

#include <chrono>
#include <csignal>
#include <iostream>

#include <malloc.h>
#include <unistd.h>

#include "batch_log.hpp"
#include "batch_plan.hpp"
#include "batch_progress.hpp"
#include "batch_run.hpp"
#include "batch_signals.hpp"
#include "command_line.hpp"
#include "depth_camera_outputs.hpp"

namespace zraster::cli {
namespace {

// One file after another of similar sizes: glibc would give the memory each one frees back to the
// kernel (unmapping blocks over its mmap threshold, trimming its heaps), and the next file would
// fault it in again page by page: 250 page faults a file at 256x256, a fifth of the time. Kept,
// the process stays at what its largest files needed at once (blocks of 64 MiB and more still go
// back, and heaps are trimmed past 512 MiB of free memory).
void keep_freed_memory() {
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

std::string signal_name(int sig) {
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "signal " + std::to_string(sig);
}

}  // namespace

void add_batch_command(CLI::App& app, BatchArguments& a) {
    CLI::App* cmd = app.add_subcommand(
        "batch",
        "Render every mesh file of folders and lists as `zraster render` would, with a JSON Lines "
        "log; resumable, shardable (docs/batch.md)");
    add_render_arguments(*cmd, a.render);
    // Many inputs instead of render's one scene.
    cmd->remove_option(cmd->get_option("scene"));
    add_frame_arguments(*cmd, a.render);
    add_depth_camera_model_options(*cmd, a.render.depth_camera);
    cmd->add_option("inputs", a.inputs,
                    "Mesh files, and folders searched recursively for every format the loader "
                    "reads");
    cmd->add_option("--list", a.lists,
                    "A file of input paths, one per line ('-': standard input); repeatable");
    cmd->add_option("-o,--output-dir", a.out_dir,
                    "Output folder (created): a file found in a folder argument keeps its path "
                    "under it, a file argument its name; the extension is replaced")
        ->required();
    cmd->add_option("--log", a.log, "JSON Lines log, appended to (default OUTDIR/batch.jsonl)");
    const auto format = CLI::IsMember({"npy", "png"});
    cmd->add_option("--depth", a.depth, "Also write STEM_depth.npy|png (as --depth-out)")
        ->check(format);
    cmd->add_option("--z", a.z, "Also write STEM_z.npy|png (as --z-out)")->check(format);
    cmd->add_flag("--range", a.range, "Also write STEM_range.npy (as --range-out)");
    cmd->add_flag("--normal", a.normal, "Also write STEM_normal.png (as --normal-out)");
    cmd->add_option("--id", a.id, "Also write STEM_id.npy|png (as --id-out)")->check(format);
    cmd->add_flag("--points", a.points, "Also write STEM_points.ply (as --points-out)");
    cmd->add_flag("--camera-json", a.camera_json, "Also write STEM_camera.json (as --camera-json)");
    CLI::Option* views =
        cmd->add_option("--views", a.views,
                        "N views on an orbit around each object (suffixes _v00, _v01, ...): "
                        "--orbit 360*i/N,ELEVATION,1/sin(fovy/2)")
            ->check(CLI::Range(1, 1000));
    cmd->add_option("--elevation", a.elevation, "Elevation of the --views orbit, degrees")
        ->capture_default_str()
        ->needs(views);
    cmd->add_option("--views-json", a.views_json,
                    "Cameras to render each file from (suffixes _v00, ...): a JSON array of "
                    "{eye, target, up, fovy, near, far}, {orbit, ...} or what --camera-json "
                    "writes");
    cmd->add_option("--jobs", a.jobs, "Files rendered at once (0: one per hardware thread)")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_option("--max-triangles", a.max_triangles,
                    "Refuse files of more triangles than this (over their instances)")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40))
        ->capture_default_str();
    cmd->add_option("--max-memory", a.max_memory,
                    "Refuse files whose rendering needs more memory than this, estimated (e.g. "
                    "2G; default: 3/4 of the memory shared among --jobs)");
    cmd->add_flag("--force", a.force, "Render inputs whose outputs are already up to date too");
    cmd->add_option("--shard", a.shard,
                    "K/N: render only the inputs whose output path hashes (FNV-1a 64) to K "
                    "modulo N");
    cmd->add_option("--progress", a.progress,
                    "auto (a live line on a terminal, else plain lines), bar, plain, none")
        ->check(CLI::IsMember({"auto", "bar", "plain", "none"}))
        ->capture_default_str();
}

int run_batch(const BatchArguments& a) {
    const auto start = std::chrono::steady_clock::now();
    const BatchPlan plan = plan_batch(a, std::cin);
    const std::vector<BatchInput>& inputs = plan.inputs;
    const BatchSettings& settings = plan.settings;
    const int jobs = plan.jobs;

    BatchLog log(plan.log, plan.log_fifo);
    StopOnSignals signals;
    BatchProgress progress(progress_mode(a.progress, ::isatty(STDERR_FILENO) == 1), inputs.size());
    keep_freed_memory();
    BatchTotals totals;
    try {
        totals = run_batch_jobs(inputs, settings, jobs, log, progress, signals.stop());
    } catch (const InputError& e) {
        // The log could not be written (docs/batch.md, "Exit status"): the inputs finished
        // before stay written, each all or nothing.
        fmt::print(stderr,
                   "zraster: {} (the batch stopped; the outputs of the inputs finished before "
                   "stay, the same command again does the rest)\n",
                   e.what());
        return kExitBadInput;
    }
    // Wall time from the start: finding the inputs and checking their names included.
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::size_t done = totals.ok + totals.failed + totals.skipped;
    fmt::print(stderr, "zraster batch: {} ok, {} failed, {} skipped in {:.2f} s ({:.1f} files/s)",
               totals.ok, totals.failed, totals.skipped, seconds,
               seconds > 0.0 ? double(done) / seconds : 0.0);
    if (signals.signal() != 0)
        fmt::print(stderr, "; stopped by {}: {} not done, the same command again finishes them",
                   signal_name(signals.signal()), totals.not_done);
    fmt::print(stderr, "; log {}\n", log.path().string());
    if (signals.signal() != 0) return 128 + signals.signal();
    return totals.failed > 0 ? kExitSomeFilesFailed : kExitOk;
}

}  // namespace zraster::cli
