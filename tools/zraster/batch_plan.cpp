// See batch_plan.hpp.
#include "batch_plan.hpp"

#include <zraster/error.hpp>
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <thread>

#include <fcntl.h>
#include <unistd.h>

#include "batch_limits.hpp"
#include "batch_views.hpp"
#include "command_caps.hpp"
#include "command_line.hpp"

namespace zraster::cli {

int batch_jobs(const BatchArguments& a) {
    return capped_threads(
        "--jobs", a.jobs > 0 ? a.jobs : int(std::max(1u, std::thread::hardware_concurrency())));
}

int batch_job_threads(int threads, int jobs) {
    const int total = threads > 0 ? threads : render_thread_count(0);
    return std::max(1, total / std::max(jobs, 1));
}

namespace {

// --log, or OUTDIR/batch.jsonl.
std::filesystem::path batch_log_path(const BatchArguments& a) {
    return a.log.empty() ? std::filesystem::path(a.out_dir) / "batch.jsonl"
                         : std::filesystem::path(a.log);
}

}  // namespace

BatchSettings batch_settings(const BatchArguments& a, int jobs) {
    if (a.out_dir.empty()) throw InputError("-o", "the output folder is empty");
    const bool views = a.views > 0 || !a.views_json.empty();
    if (a.views > 0 && !a.views_json.empty())
        throw InputError("--views-json", "and --views both give the views: choose one");
    if (views && (!a.render.orbit.empty() || !a.render.eye.empty() || !a.render.target.empty()))
        throw InputError(a.views > 0 ? "--views" : "--views-json",
                         "places the camera of every view: not with --orbit, --eye or --target");
    BatchSettings s;
    s.render = a.render;
    // Checked (and clamped, with its warning) once, not once per file.
    s.render.threads = checked_thread_count("--threads", a.render.threads);
    s.outputs = {a.depth, a.z, a.id, a.range, a.normal, a.points, a.camera_json};
    if (a.views > 0) s.views = orbit_views(a.views, a.elevation, a.render.fovy);
    if (!a.views_json.empty()) s.views = read_views_json(a.views_json);
    s.limits.max_triangles = a.max_triangles;
    s.limits.max_memory = a.max_memory.empty() ? default_max_memory(jobs)
                                               : parse_byte_size("--max-memory", a.max_memory);
    s.load = command_load_options();
    s.load.max_triangles = load_triangle_limit(s.limits);
    s.load.worker_memory_bytes = s.limits.max_memory;
    s.out_dir = a.out_dir;
    s.force = a.force;
    if (!a.force)
        s.history = std::make_shared<const BatchHistory>(BatchHistory::read(batch_log_path(a)));
    return s;
}

namespace {

// --log is appended to: checked as an output is (OutputFiles::check) while the plan is made, so
// that a refused log leaves nothing (plan_batch removes the folders it made). A device or FIFO
// there (/dev/stdout) is written as it is.
void check_log(const BatchArguments& a, OutputFiles& log, BatchPlan& plan) {
    if (a.log.empty()) return;
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(a.log, ec);
    if (std::filesystem::is_fifo(status)) {
        // Without blocking: a FIFO nothing reads fails with ENXIO instead of waiting for ever.
        const int fd = ::open(a.log.c_str(), O_WRONLY | O_APPEND | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0 && errno == ENXIO)
            throw InputError(
                "--log " + a.log,
                "is a FIFO that nothing reads: start its reader first, or give a file");
        if (fd < 0)
            throw InputError("--log " + a.log,
                             "cannot open the log: " + std::generic_category().message(errno));
        ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // lines written whole
        plan.log_fifo = std::shared_ptr<const int>(new int(fd), [](const int* p) {
            ::close(*p);
            delete p;
        });
        return;
    }
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
        !std::filesystem::is_directory(status))
        return;
    log.check(a.log, "--log");
}

// An existing file is appended to only if it is a log (empty, or JSON Lines): anything else there
// (a model's texture, which no plan can know of before the model is read) would be corrupted.
// Checked after the run's inputs, whose message is the more telling.
void check_existing_log(const BatchArguments& a) {
    std::error_code ec;
    if (a.log.empty() || !std::filesystem::is_regular_file(a.log, ec)) return;
    std::ifstream in(a.log, std::ios::binary);
    char first = '{';
    if (in.get(first) && first != '{')
        throw InputError("--log " + a.log,
                         "the file exists and is not a batch log (JSON Lines): the log is "
                         "appended to; choose another path");
}

// The log may not be where an input's output goes (the output would be skipped as up to date,
// or the log replaced): checked against each input's planned outputs as the clash check lists
// them, most names ruled out by the file name alone.
void check_log_against(const std::filesystem::path& log_path, const std::filesystem::path& log,
                       const BatchInput& input, const std::vector<std::filesystem::path>& outputs) {
    std::error_code ec;
    for (const std::filesystem::path& output : outputs)
        if (output.filename() == log.filename() &&
            std::filesystem::weakly_canonical(output, ec) == log && !ec)
            throw InputError("--log " + log_path.string(),
                             "is where " + input.source.string() + "'s output " + output.string() +
                                 " goes: each output needs a path of its own");
}

// The inputs, their outputs checked for clashes, the shard's share of them, the log.
// `paths`: the inputs given and those the --list files name (read before the output folder is
// made: a list a FIFO's writer never ends leaves nothing behind when the run is stopped).
void plan_inputs(const BatchArguments& a, std::vector<std::string> paths, const Shard& shard,
                 BatchPlan& plan) {
    check_batch_settings(plan.settings);
    OutputFiles log;
    check_log(a, log, plan);

    // The log may not be one of the files the run reads.
    log.check_input(a.views_json, "--views-json");
    for (const std::string& list : a.lists) log.check_input(list, "--list");
    if (paths.empty()) throw InputError("batch", "no inputs: give files, folders or --list FILE");
    const std::vector<BatchInput> all = find_inputs(paths, a.out_dir);
    if (all.empty())
        throw InputError("batch", "no mesh files in the inputs given (" + paths.front() +
                                      (paths.size() > 1 ? ", ..." : "") + ")");
    for (const BatchInput& input : all) log.check_input(input.source, "");
    check_existing_log(a);
    plan.log = batch_log_path(a);
    std::error_code ec;
    const std::filesystem::path log_file = std::filesystem::weakly_canonical(plan.log, ec);
    auto writers = std::make_shared<std::map<std::filesystem::path, std::string>>();
    check_output_clashes(all, [&](const BatchInput& input) {
        std::vector<std::filesystem::path> outputs = planned_outputs(input, plan.settings);
        if (!ec) check_log_against(plan.log, log_file, input, outputs);
        for (const std::filesystem::path& output : outputs) {
            std::error_code canonical_ec;
            const std::filesystem::path key =
                std::filesystem::weakly_canonical(output, canonical_ec);
            if (!canonical_ec) writers->emplace(key, input.source.string());
        }
        return outputs;
    });
    plan.settings.planned_writers = std::move(writers);
    std::copy_if(all.begin(), all.end(), std::back_inserter(plan.inputs),
                 [&](const BatchInput& input) { return in_shard(input, shard); });
}

}  // namespace

BatchPlan plan_batch(const BatchArguments& a, std::istream& standard_input) {
    BatchPlan plan;
    plan.jobs = batch_jobs(a);
    plan.settings = batch_settings(a, plan.jobs);
    const Shard shard = a.shard.empty() ? Shard{} : parse_shard(a.shard);
    std::vector<std::string> paths = a.inputs;
    for (const std::string& list : a.lists) {
        const std::vector<std::string> listed = read_path_list(list, standard_input);
        paths.insert(paths.end(), listed.begin(), listed.end());
    }
    // The folders this run creates, deepest first: a plan refused below leaves none of them
    // behind (a failed run leaves nothing; fuzz_cli found the output folder left).
    std::vector<std::filesystem::path> created;
    std::error_code ec;
    for (std::filesystem::path p = a.out_dir; !p.empty() && !std::filesystem::exists(p, ec);
         p = p.parent_path()) {
        created.push_back(p);
        if (p == p.parent_path()) break;
    }
    std::filesystem::create_directories(a.out_dir, ec);
    if (ec || !std::filesystem::is_directory(a.out_dir))
        throw InputError("-o " + a.out_dir, "cannot create the output folder" +
                                                (ec ? ": " + ec.message() : std::string()));
    try {
        plan_inputs(a, std::move(paths), shard, plan);
    } catch (...) {
        for (const std::filesystem::path& p : created) std::filesystem::remove(p, ec);
        throw;
    }
    return plan;
}

}  // namespace zraster::cli
