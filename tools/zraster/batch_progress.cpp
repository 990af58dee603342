// See batch_progress.hpp.
#include "batch_progress.hpp"

#include <fmt/format.h>

#include <cmath>

#include <sys/ioctl.h>
#include <unistd.h>

namespace zraster::cli {
namespace {

// A live line redrawn at most 10 times a second; a plain line every 5 seconds.
constexpr std::chrono::milliseconds kBarEvery{100};
constexpr std::chrono::seconds kPlainEvery{5};

std::string duration(double seconds) {
    const long s = std::lround(seconds);
    if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60);
    return fmt::format("{}:{:02}", s / 60, s % 60);
}

std::size_t terminal_width(std::FILE* out) {
    winsize size{};
    if (::ioctl(::fileno(out), TIOCGWINSZ, &size) == 0 && size.ws_col > 20) return size.ws_col;
    return 80;
}

}  // namespace

ProgressMode progress_mode(const std::string& name, bool terminal) {
    if (name == "bar") return ProgressMode::Bar;
    if (name == "plain") return ProgressMode::Plain;
    if (name == "none") return ProgressMode::None;
    return terminal ? ProgressMode::Bar : ProgressMode::Plain;
}

BatchProgress::BatchProgress(ProgressMode mode, std::size_t total, std::FILE* out)
    : mode_(mode), total_(total), out_(out) {}

void BatchProgress::started(const std::string& input) {
    if (mode_ != ProgressMode::Bar) return;
    const std::lock_guard lock(mutex_);
    current_ = input;
    show(Clock::now());
}

void BatchProgress::finished(const BatchRecord& record) {
    if (mode_ == ProgressMode::None) return;
    const std::lock_guard lock(mutex_);
    ++done_;
    if (record.status == BatchStatus::Error) ++failed_;
    show(Clock::now());
}

void BatchProgress::show(Clock::time_point now) {
    const bool bar = mode_ == ProgressMode::Bar;
    const bool last = done_ == total_;
    if (bar ? !last && now - last_shown_ < kBarEvery
            : last || now - (line_shown_ ? last_shown_ : start_) < kPlainEvery)
        return;
    last_shown_ = now;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0.0 ? double(done_) / seconds : 0.0;
    const std::string eta =
        rate > 0.0 ? duration(double(total_ - done_) / rate) : std::string("-:--");
    std::string line = fmt::format("{}/{} files, {} failed, {:.1f} files/s, ETA {}", done_, total_,
                                   failed_, rate, eta);
    if (bar) {
        if (!last && !current_.empty()) line += "  " + current_;
        const std::size_t width = terminal_width(out_) - 1;
        if (line.size() > width) line = line.substr(0, width);
        fmt::print(out_, "\r\033[K{}", line);
    } else {
        fmt::print(out_, "zraster batch: {}\n", line);
    }
    std::fflush(out_);
    line_shown_ = true;
}

void BatchProgress::close() {
    const std::lock_guard lock(mutex_);
    if (mode_ == ProgressMode::Bar && line_shown_) {
        fmt::print(out_, "\r\033[K");
        std::fflush(out_);
    }
}

}  // namespace zraster::cli
