// The jobs of `zraster batch`: its inputs rendered `jobs` at a time on threads of this process
// (each file on its share of the threads), each record logged and shown as
// its input ends.
#pragma once
#include <atomic>
#include <cstddef>
#include <vector>

#include "batch_inputs.hpp"
#include "batch_job.hpp"
#include "batch_log.hpp"
#include "batch_progress.hpp"

namespace zraster::cli {

struct BatchTotals {
    std::size_t ok = 0, failed = 0, skipped = 0;
    std::size_t not_done = 0;  // dropped or never started: stopped by `stop`
    double seconds = 0.0;
};

// Runs run_batch_job on every input, in order, at most `jobs` at once; appends each record to
// `log` (dropped inputs are not logged). When `stop` becomes true, no further input starts. A
// failure to write the log stops the batch and is rethrown once the jobs in flight have ended.
BatchTotals run_batch_jobs(const std::vector<BatchInput>& inputs, const BatchSettings& settings,
                           int jobs, BatchLog& log, BatchProgress& progress,
                           std::atomic<bool>& stop);

}  // namespace zraster::cli
