// A oneTBB arena of exactly the requested threads. oneTBB keeps hardware_concurrency - 1 worker
// threads unless a tbb::global_control raises that: an arena of more threads would run with
// fewer, and oneTBB prints "TBB Warning: The number of workers is currently limited ..." on
// stderr. RenderOptions::threads may ask for up to 4 per hardware thread, so the limit is raised
// while the arena lives.
#pragma once
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <memory>

namespace zraster::detail {

class ThreadArena {
  public:
    explicit ThreadArena(int threads)
        : parallelism_(threads > tbb::info::default_concurrency()
                           ? std::make_unique<tbb::global_control>(
                                 tbb::global_control::max_allowed_parallelism,
                                 static_cast<std::size_t>(threads))
                           : nullptr),
          arena_(threads) {}
    tbb::task_arena& arena() { return arena_; }

  private:
    std::unique_ptr<tbb::global_control> parallelism_;  // first: outlives the arena
    tbb::task_arena arena_;
};

}  // namespace zraster::detail
