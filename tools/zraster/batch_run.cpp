// See batch_run.hpp.
#include "batch_run.hpp"

#include "batch_plan.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

namespace zraster::cli {

BatchTotals run_batch_jobs(const std::vector<BatchInput>& inputs, const BatchSettings& settings,
                           int jobs, BatchLog& log, BatchProgress& progress,
                           std::atomic<bool>& stop) {
    const auto start = std::chrono::steady_clock::now();
    BatchTotals totals;
    std::mutex totals_mutex;
    std::exception_ptr log_failure;
    std::atomic<std::size_t> next{0};
    const std::size_t threads =
        std::min<std::size_t>(std::size_t(std::max(jobs, 1)), inputs.size());
    BatchSettings job_settings = settings;
    job_settings.render.threads = batch_job_threads(settings.render.threads, int(threads));
    // oneTBB keeps hardware_concurrency - 1 workers unless told otherwise: more threads asked for
    // (up to 4 per hardware thread) would run with fewer, and oneTBB says so on stderr.
    const std::size_t all_threads = threads * std::size_t(std::max(job_settings.render.threads, 1));
    std::optional<tbb::global_control> parallelism;
    if (all_threads > std::size_t(tbb::info::default_concurrency()))
        parallelism.emplace(tbb::global_control::max_allowed_parallelism, all_threads);
    const auto work = [&] {
        Renderer renderer;  // its memory and thread arena serve every file of this thread
        // This thread's files run in an arena of its share of the threads (batch_job_threads).
        tbb::task_arena arena(job_settings.render.threads);
        for (;;) {
            if (stop.load()) return;
            const std::size_t i = next.fetch_add(1);
            if (i >= inputs.size()) return;
            progress.started(inputs[i].source.string());
            BatchRecord record;
            arena.execute(
                [&] { record = run_batch_job(inputs[i], job_settings, &stop, &renderer); });
            if (record.status == BatchStatus::Dropped) continue;
            try {
                log.append(record);
            } catch (...) {
                const std::lock_guard lock(totals_mutex);
                if (!log_failure) log_failure = std::current_exception();
                stop.store(true);
                return;
            }
            {
                const std::lock_guard lock(totals_mutex);
                std::size_t& count = record.status == BatchStatus::Ok        ? totals.ok
                                     : record.status == BatchStatus::Skipped ? totals.skipped
                                                                             : totals.failed;
                ++count;
            }
            progress.finished(record);
        }
    };
    std::vector<std::thread> pool;
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (std::thread& thread : pool) thread.join();
    progress.close();
    if (log_failure) std::rethrow_exception(log_failure);
    totals.not_done = inputs.size() - totals.ok - totals.failed - totals.skipped;
    totals.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return totals;
}

}  // namespace zraster::cli
