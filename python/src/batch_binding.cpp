// The pieces of `zraster batch` that zraster.batch (python/zraster/batch.py) runs: the command's
// flags from keywords, its plan (settings, output folder, inputs, shard, log), one input's job
// and the progress line, exactly as the command has them (tools/zraster/batch_*.hpp). Python
// schedules the jobs: on threads of this process, or on the workers of a Dask cluster.
#include <zraster/error.hpp>
#include <zraster/render.hpp>

#include <tbb/task_arena.h>
#include <CLI/CLI.hpp>

#include <unistd.h>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "batch_command.hpp"
#include "batch_log.hpp"
#include "batch_plan.hpp"
#include "batch_progress.hpp"
#include "binding.hpp"
#include "options.hpp"

namespace zraster::python {
namespace {

// The options of `zraster batch` that render_files() takes as keywords: all but the inputs and
// the output folder (its arguments) and help.
bool is_batch_keyword(const CLI::Option* option) {
    if (option->get_lnames().empty()) return false;  // the positional inputs
    const std::string& name = option->get_lnames().front();
    return name != "help" && name != "output-dir";
}

// `zraster batch`'s flag parser, as the command builds it.
struct BatchParser {
    CLI::App app;
    CLI::App* batch = nullptr;
    cli::BatchArguments arguments;
    BatchParser() {
        cli::add_batch_command(app, arguments);
        batch = app.get_subcommand("batch");
    }
};

// `argv` (the command's arguments after "batch") parsed. Throws InputError naming the keyword
// (render_files()) or, when not `keyword_names`, the flag as the command does.
cli::BatchArguments parse_batch_arguments(const std::vector<std::string>& argv,
                                          bool keyword_names = false) {
    BatchParser parser;
    std::vector<std::string> reversed(argv.rbegin(), argv.rend());  // CLI11 takes it reversed
    reversed.push_back("batch");
    try {
        parser.app.parse(reversed);
    } catch (const CLI::ParseError& e) {
        if (keyword_names) throw keyword_error(e);
        throw InputError("", e.what());
    }
    return parser.arguments;
}

// An InputError's source as render_files() names it: a flag as its keyword, -o as out_dir.
std::string as_keyword(const std::string& source) {
    if (source.starts_with("--")) return with_keyword_names(source);
    if (source == "-o" || source.starts_with("-o ")) return "out_dir" + source.substr(2);
    return source;
}

// A job's Renderer: one per thread that runs jobs, reusing its memory from file to file, as each
// of the command's job threads has.
Renderer& thread_renderer() {
    thread_local Renderer renderer;
    return renderer;
}

// An arena of `threads` for this thread's jobs, as each of the command's job threads has (see
// cli::run_batch_jobs): made again only when a batch asks for another count.
tbb::task_arena& thread_arena(int threads) {
    thread_local std::unique_ptr<tbb::task_arena> arena;
    if (!arena || arena->max_concurrency() != threads)
        arena = std::make_unique<tbb::task_arena>(threads);
    return *arena;
}

// The settings of every file of a batch, from the command's arguments: what a worker needs to
// run the jobs it is given, each on its share of the threads. Pickled as those arguments.
struct BatchJobs {
    std::vector<std::string> argv;
    int jobs = 1;
    cli::BatchSettings settings;

    BatchJobs(std::vector<std::string> argv_, int jobs_) : argv(std::move(argv_)), jobs(jobs_) {
        settings = cli::batch_settings(parse_batch_arguments(argv), jobs);
        settings.render.threads = cli::batch_job_threads(settings.render.threads, jobs);
    }

    // The record of the input's job as a line of batch.jsonl (without the newline).
    std::string run(const std::string& source, const std::string& stem) const {
        const cli::BatchInput input{source, stem};
        py::gil_scoped_release release;
        cli::BatchRecord record;
        thread_arena(settings.render.threads).execute([&] {
            record = cli::run_batch_job(input, settings, nullptr, &thread_renderer());
        });
        return cli::record_json(record);
    }
};

// Everything the command settles before rendering: see cli::plan_batch.
struct BatchPlan {
    std::vector<std::string> argv;
    cli::BatchPlan plan;
    std::string progress;

    BatchPlan(std::vector<std::string> argv_, bool keyword_names) : argv(std::move(argv_)) {
        const cli::BatchArguments arguments = parse_batch_arguments(argv, keyword_names);
        try {
            plan = cli::plan_batch(arguments, std::cin);
        } catch (const InputError& e) {
            if (!keyword_names) throw;
            throw InputError(as_keyword(e.file()), with_keyword_names(e.cause()));
        }
        progress = arguments.progress;
    }

    py::list inputs() const {
        py::list out;
        for (const cli::BatchInput& input : plan.inputs)
            out.append(py::make_tuple(input.source.string(), input.stem));
        return out;
    }
};

struct BatchProgress {
    cli::BatchProgress progress;
    BatchProgress(const std::string& mode, std::size_t total)
        : progress(cli::progress_mode(mode, ::isatty(STDERR_FILENO) == 1), total) {}
};

cli::BatchStatus status_of(const std::string& name) {
    if (name == "ok") return cli::BatchStatus::Ok;
    if (name == "skipped") return cli::BatchStatus::Skipped;
    if (name == "error") return cli::BatchStatus::Error;
    throw py::value_error("status: expected 'ok', 'skipped' or 'error', got '" + name + "'");
}

std::string batch_help() {
    BatchParser parser;
    return parser.batch->help("python3 -m zraster.batch");
}

}  // namespace

void bind_batch(py::module_& m) {
    m.def(
        "_batch_flags",
        [](const py::kwargs& keywords) {
            BatchParser parser;
            return flag_arguments(
                keywords, *parser.batch, is_batch_keyword,
                [](const std::string& keyword) {
                    return "render_files() got an unexpected keyword argument '" + keyword + "'";
                },
                nullptr);
        },
        "The flags of `zraster batch` the keywords give (render_files()'s options).");
    m.def("_batch_help", &batch_help, "`zraster batch`'s options, as --help shows them.");
    m.def(
        "_batch_error_record",
        [](const std::string& input, const std::string& cause) {
            cli::BatchRecord record;
            record.input = input;
            record.status = cli::BatchStatus::Error;
            record.error = InputError(input, cause).what();
            return cli::record_json(record);
        },
        py::arg("input"), py::arg("cause"),
        "The batch.jsonl line of an input that failed outside its job (its worker died).");

    py::class_<BatchPlan>(m, "_BatchPlan",
                          "The checks, output folder, inputs and log of a batch, from the "
                          "arguments of `zraster batch` (cli::plan_batch).")
        .def(py::init<std::vector<std::string>, bool>(), py::arg("argv"), py::arg("keyword_names"))
        .def_readonly("argv", &BatchPlan::argv)
        .def_property_readonly("inputs", &BatchPlan::inputs,
                               "[(source, stem)]: this shard's inputs, in order")
        .def_property_readonly("log", [](const BatchPlan& p) { return p.plan.log.string(); })
        .def_property_readonly("jobs", [](const BatchPlan& p) { return p.plan.jobs; })
        .def_readonly("progress", &BatchPlan::progress);

    py::class_<BatchJobs>(m, "_BatchJobs",
                          "The settings every input of a batch is rendered with; run() renders "
                          "one input as the command does. Pickled as its arguments.")
        .def(py::init<std::vector<std::string>, int>(), py::arg("argv"), py::arg("jobs"))
        .def("run", &BatchJobs::run, py::arg("source"), py::arg("stem"),
             "Renders one input (never raises for the file's own problems); returns its "
             "record as a line of batch.jsonl.")
        .def(py::pickle([](const BatchJobs& j) { return py::make_tuple(j.argv, j.jobs); },
                        [](const py::tuple& t) {
                            return BatchJobs(t[0].cast<std::vector<std::string>>(),
                                             t[1].cast<int>());
                        }));

    py::class_<BatchProgress>(m, "_BatchProgress", "The command's progress line on stderr.")
        .def(py::init<const std::string&, std::size_t>(), py::arg("mode"), py::arg("total"))
        .def("started",
             [](BatchProgress& p, const std::string& input) { p.progress.started(input); })
        .def("finished",
             [](BatchProgress& p, const std::string& input, const std::string& status) {
                 cli::BatchRecord record;
                 record.input = input;
                 record.status = status_of(status);
                 p.progress.finished(record);
             })
        .def("close", [](BatchProgress& p) { p.progress.close(); });
}

}  // namespace zraster::python
