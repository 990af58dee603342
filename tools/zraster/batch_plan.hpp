// What `zraster batch` settles before rendering anything: the settings every file is rendered
// with, the output folder, the inputs (found, checked for name clashes, sharded) and the log.
// The command runs the plan on its own threads; the Python module (zraster.batch) runs the same
// plan's jobs on its threads or on a Dask cluster.
#pragma once
#include <filesystem>
#include <istream>
#include <memory>
#include <vector>

#include "batch_command.hpp"
#include "batch_inputs.hpp"
#include "batch_job.hpp"

namespace zraster::cli {

// Files rendered at once: --jobs, or one per hardware thread when it is 0.
int batch_jobs(const BatchArguments& arguments);

// The threads each of `jobs` files at once is loaded, rendered and written on: `threads`
// (--threads; 0: every hardware thread) divided among the jobs, at least one. With one thread per
// job, no oneTBB worker wakes up (and spins) for the short parallel loops of a small file.
int batch_job_threads(int threads, int jobs);

// The settings of every job, from the flags. `jobs` shares the default --max-memory among the
// files rendered at once. Throws InputError naming the flag for a value or combination no file
// could be rendered with (also check_batch_settings's checks, which need the output folder).
BatchSettings batch_settings(const BatchArguments& arguments, int jobs);

struct BatchPlan {
    BatchSettings settings;
    std::vector<BatchInput> inputs;  // this shard's, in order
    std::filesystem::path log;       // --log, or OUTDIR/batch.jsonl
    // --log a FIFO: opened while planning (a FIFO nothing reads is refused then, not waited on
    // for ever), kept open for the log (BatchLog adopts it), so that a reader such as `cat`
    // never sees the writer come and go.
    std::shared_ptr<const int> log_fifo;
    int jobs = 1;
};

// Creates the output folder, checks the settings (check_batch_settings), finds the inputs of
// the arguments and their --list files (`-`: `standard_input`), refuses name clashes, and keeps
// the --shard's inputs. Throws InputError naming the cause; nothing is rendered or written but
// the folder.
BatchPlan plan_batch(const BatchArguments& arguments, std::istream& standard_input);

}  // namespace zraster::cli
