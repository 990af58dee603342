// See batch_log.hpp.
#include "batch_log.hpp"

#include <zraster/error.hpp>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace zraster::cli {
namespace {

// Milliseconds to the microsecond: enough for a log, and short lines.
double rounded(double ms) {
    return std::round(ms * 1000.0) / 1000.0;
}

}  // namespace

const char* status_name(BatchStatus status) {
    switch (status) {
        case BatchStatus::Ok:
            return "ok";
        case BatchStatus::Error:
            return "error";
        case BatchStatus::Skipped:
            return "skipped";
        case BatchStatus::Dropped:
            return "dropped";
    }
    return "error";
}

std::string record_json(const BatchRecord& r) {
    nlohmann::ordered_json line;
    line["input"] = r.input;
    line["status"] = status_name(r.status);
    line["error"] = r.status == BatchStatus::Error ? nlohmann::ordered_json(r.error) : nullptr;
    line["outputs"] = r.outputs;
    line["triangles"] = r.triangles ? nlohmann::ordered_json(*r.triangles) : nullptr;
    line["load_ms"] = rounded(r.load_ms);
    line["render_ms"] = rounded(r.render_ms);
    line["write_ms"] = rounded(r.write_ms);
    line["warnings"] = r.warnings;
    line["reads"] = r.reads;
    return line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

BatchLog::BatchLog(const std::filesystem::path& path, std::shared_ptr<const int> opened)
    : path_(path), opened_(std::move(opened)) {
    if (opened_) {
        fd_ = *opened_;
        return;
    }
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0666);
    if (fd_ < 0)
        throw InputError(path.string(),
                         "cannot open the log: " + std::generic_category().message(errno));
}

BatchLog::~BatchLog() {
    if (fd_ >= 0 && !opened_) ::close(fd_);
}

void BatchLog::append(const BatchRecord& record) {
    const std::string line = record_json(record) + "\n";
    const std::lock_guard lock(mutex_);
    ssize_t written;
    do {
        written = ::write(fd_, line.data(), line.size());
    } while (written < 0 && errno == EINTR);
    if (written != static_cast<ssize_t>(line.size()))
        throw InputError(
            path_.string(),
            "cannot write the log: " + (written < 0 ? std::generic_category().message(errno)
                                                    : std::string("short write (disk full?)")));
}

}  // namespace zraster::cli
