// The progress of `zraster batch` on stderr (--progress): on a terminal one live line (done/total,
// files per second, time left, the file being rendered), otherwise a plain line every few
// seconds, or nothing.
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>

#include "batch_record.hpp"

namespace zraster::cli {

enum class ProgressMode { Bar, Plain, None };

// "bar", "plain", "none", or "auto": a bar when `terminal` (stderr is one), else plain lines.
ProgressMode progress_mode(const std::string& name, bool terminal);

class BatchProgress {
  public:
    BatchProgress(ProgressMode mode, std::size_t total, std::FILE* out = stderr);

    // Thread-safe: jobs call them as files start and end.
    void started(const std::string& input);
    void finished(const BatchRecord& record);
    // Clears the live line, before the summary is printed below it.
    void close();

  private:
    using Clock = std::chrono::steady_clock;
    void show(Clock::time_point now);  // mutex_ held

    ProgressMode mode_;
    std::size_t total_, done_ = 0, failed_ = 0;
    std::FILE* out_;
    std::string current_;
    const Clock::time_point start_ = Clock::now();
    Clock::time_point last_shown_{};
    bool line_shown_ = false;
    std::mutex mutex_;
};

}  // namespace zraster::cli
