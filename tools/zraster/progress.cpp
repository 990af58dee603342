// See progress.hpp.
#include "progress.hpp"

#include <fmt/format.h>

#include <chrono>
#include <mutex>
#include <string>

#include <unistd.h>

namespace zraster::cli {
namespace {

class StderrProgress final : public ProgressReporter {
  public:
    void report(const char* stage, double fraction) override {
        if (!terminal_) return;
        const std::lock_guard lock(mutex_);
        const Clock::time_point now = Clock::now();
        if (now - start_ < kQuiet) return;
        if (stage_ == stage && now - last_ < kEvery) return;
        stage_ = stage;
        last_ = now;
        fmt::print(stderr, "zraster: {}: {:.0f}% ({:.0f} s)\n", stage, 100.0 * fraction,
                   std::chrono::duration<double>(now - start_).count());
    }

  private:
    using Clock = std::chrono::steady_clock;
    static constexpr std::chrono::seconds kQuiet{2}, kEvery{2};
    // Only for a person watching: on a pipe or a file (a service, a script, a log) a refusal
    // stays the one line it is.
    const bool terminal_ = ::isatty(STDERR_FILENO) == 1;
    std::mutex mutex_;
    const Clock::time_point start_ = Clock::now();
    Clock::time_point last_;
    std::string stage_;
};

}  // namespace

ProgressReporter* stderr_progress() {
    static StderrProgress progress;
    return &progress;
}

}  // namespace zraster::cli
