#include "io/load_worker.hpp"

#include <zraster/error.hpp>

#include "io/assimp_errors.hpp"
#include "io/obj_parser.hpp"
#include "io/worker_message.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <new>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
#define ZRASTER_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define ZRASTER_SANITIZED 1
#endif
#ifdef ZRASTER_SANITIZED
#include <sanitizer/common_interface_defs.h>
#endif

namespace zraster::io {

namespace {

// Exit statuses of the child besides 0 (a message was sent).
constexpr int kChildOutOfMemory = 3;
constexpr int kChildWriteFailed = 4;

WorkerTestHook g_test_hook = nullptr;

// The child's out-of-memory path must not allocate: the message is built before the limits.
int g_child_fd = -1;
const std::string* g_out_of_memory_message = nullptr;

bool write_all(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

void child_out_of_memory() {
    if (g_out_of_memory_message != nullptr)
        (void)write_all(g_child_fd, g_out_of_memory_message->data(),
                        g_out_of_memory_message->size());
    ::_exit(kChildOutOfMemory);
}

// The child's current address space (the parent's, copied): the memory limit comes on top.
std::uintmax_t current_address_space() {
    std::ifstream statm("/proc/self/statm");
    std::uintmax_t pages = 0;
    if (!(statm >> pages)) return 0;
    return pages * std::uintmax_t(::sysconf(_SC_PAGESIZE));
}

void set_limit(int resource, std::uintmax_t value) {
    rlimit current{};
    if (::getrlimit(resource, &current) != 0) return;
    rlimit limit{};
    limit.rlim_cur = std::min<std::uintmax_t>(value, current.rlim_max);
    limit.rlim_max = current.rlim_max;
    (void)::setrlimit(resource, &limit);
}

// Runs in the forked child; never returns. Only this thread exists here.
[[noreturn]] void child_main(int fd, const std::filesystem::path& path,
                             const ObjMaterialLibraries* obj_libraries,
                             const LoadOptions& options) {
    // A crash must end the child with its signal, whatever handlers the caller (or a fuzzer, or
    // a sanitizer runtime) installed; the parent reports it.
    for (const int sig : {SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT, SIGPIPE, SIGXCPU, SIGTERM,
                          SIGINT, SIGALRM, SIGUSR1, SIGUSR2})
        (void)std::signal(sig, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    (void)::sigprocmask(SIG_SETMASK, &none, nullptr);
#ifndef ZRASTER_SANITIZED
    // Assimp prints to the standard streams (its assertions' "ai_assert failure in ..."): the
    // parent says what happened, in one line. (Sanitized builds keep them: their reports.)
    if (const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC); null >= 0) {
        (void)::dup2(null, STDOUT_FILENO);
        (void)::dup2(null, STDERR_FILENO);
        ::close(null);
    }
#endif
#ifdef ZRASTER_SANITIZED
    // libFuzzer's death callback would save the input as a finding from the child.
    __sanitizer_set_death_callback(nullptr);
#endif
    g_child_fd = fd;
    static const std::string out_of_memory =
        encode_error_message(WorkerMessageKind::OutOfMemory, "");
    g_out_of_memory_message = &out_of_memory;

    set_limit(RLIMIT_CORE, 0);
    const double timeout = std::max(0.0, options.worker_timeout_seconds);
    set_limit(RLIMIT_CPU, std::uintmax_t(std::ceil(std::min(timeout, 1e9))) + 1);
    if (options.worker_memory_bytes != 0) {
        const std::uintmax_t base = current_address_space();
        if (base != 0) set_limit(RLIMIT_AS, base + options.worker_memory_bytes);
    }
    std::set_new_handler(child_out_of_memory);

    if (g_test_hook != nullptr) g_test_hook();
    std::string message;
    try {
        message = encode_scene_message(import_with_assimp(path, options, true, obj_libraries));
    } catch (const ImporterOutOfMemory&) {
        child_out_of_memory();  // the parent names the budget
    } catch (const LimitExceeded& e) {
        message = encode_limit_message(e.limit(), e.cause());
    } catch (const InputError& e) {
        message = encode_error_message(WorkerMessageKind::InputError, e.cause());
    } catch (const std::bad_alloc&) {
        child_out_of_memory();
    } catch (const std::exception& e) {
        message = encode_error_message(WorkerMessageKind::InternalError, e.what());
    } catch (...) {
        message = encode_error_message(WorkerMessageKind::InternalError, "unknown exception");
    }
    ::_exit(write_all(fd, message.data(), message.size()) ? 0 : kChildWriteFailed);
}

std::string signal_name(int sig) {
    const char* abbreviation = ::sigabbrev_np(sig);
    return "signal " + std::to_string(sig) +
           (abbreviation != nullptr ? std::string(", SIG") + abbreviation : std::string());
}

std::string seconds_text(double s) {
    char text[32];
    std::snprintf(text, sizeof text, s >= 100 ? "%.0f" : "%.3g", s);
    return text;
}

std::string mebibytes_text(std::uint64_t bytes) {
    return std::to_string((bytes + (std::uint64_t{1} << 20) - 1) >> 20) + " MiB";
}

// The importer ran out of its memory: the budget it was given, named by the option that sets
// it (max_geometry_bytes when derived from the budgets).
[[noreturn]] void throw_out_of_memory(const std::string& file, const std::filesystem::path& path,
                                      std::size_t memory, const LoadOptions& options) {
    const std::string format = format_name(path);
    if (memory == 0)
        throw InputError(file,
                         "the importer ran out of memory reading it (no limit was set): it "
                         "expands in a part of the " +
                             format + " format zraster does not count before reading");
    if (options.worker_memory_bytes == LoadOptions::kWorkerMemoryFromBudgets)
        throw LimitExceeded(file, "max_geometry_bytes",
                            "the importer ran out of its " + mebibytes_text(memory) +
                                " (256 MiB, 4 times the file's size, max_geometry_bytes and twice "
                                "max_texture_bytes) reading it: it "
                                "expands in a part of the " +
                                format + " format zraster does not count before reading");
    throw LimitExceeded(file, "worker_memory_bytes",
                        "the importer ran out of its " + mebibytes_text(memory) +
                            " (worker_memory_bytes) reading it: it expands in a part of the " +
                            format + " format zraster does not count before reading");
}

LimitExceeded out_of_time(const std::string& file, double timeout, const LoadOptions& options) {
    const bool derived = options.worker_timeout_seconds == LoadOptions::kWorkerTimeoutFromFile;
    return LimitExceeded(file, "worker_timeout_seconds",
                         "the importer took longer than " + seconds_text(timeout) + " s" +
                             (derived ? " (30 s and 1 s per MiB of the file)" : "") +
                             " and was stopped");
}

// The child's process: killed and reaped unless it was reaped normally.
class Child {
  public:
    explicit Child(pid_t pid) : pid_(pid) {}
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;
    ~Child() {
        if (pid_ > 0) {
            (void)::kill(pid_, SIGKILL);
            int status = 0;
            while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
            }
        }
    }
    // The status if the child has ended, else nullopt.
    std::optional<int> try_wait() {
        if (pid_ < 0) return status_;
        for (;;) {
            int status = 0;
            const pid_t r = ::waitpid(pid_, &status, WNOHANG);
            if (r == pid_ || (r < 0 && errno == ECHILD)) {
                status_ = r == pid_ ? status : 0;
                pid_ = -1;
                return status_;
            }
            if (r < 0 && errno == EINTR) continue;
            if (r < 0) throw std::system_error(errno, std::generic_category(), "waitpid");
            return std::nullopt;
        }
    }
    // Waits until the deadline; the status, or nullopt on timeout. A caller that set SIGCHLD to
    // SIG_IGN has its children reaped by the kernel: ECHILD, taken as a normal exit (the message
    // decides).
    std::optional<int> wait_until(std::chrono::steady_clock::time_point deadline) {
        auto pause = std::chrono::microseconds(200);
        for (;;) {
            if (const std::optional<int> status = try_wait()) return status;
            if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
            std::this_thread::sleep_for(pause);
            pause = std::min(pause * 2, std::chrono::microseconds(20'000));
        }
    }

  private:
    pid_t pid_;
    int status_ = 0;
};

class Fd {
  public:
    explicit Fd(int fd) : fd_(fd) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd_ >= 0) ::close(fd_);
    }
    int get() const { return fd_; }

  private:
    int fd_;
};

}  // namespace

void set_worker_test_hook(WorkerTestHook hook) {
    g_test_hook = hook;
}

LoadedScene load_in_worker(const std::filesystem::path& path, const LoadOptions& options,
                           const ObjMaterialLibraries* obj_libraries) {
    const std::string file = path.string();
    // Our own checks (fuzzed, in this process): the common refusals need no child.
    precheck_assimp_input(path, options);
    // The budgets for this file (the prechecks confirmed it is a regular file).
    std::error_code size_error;
    const std::uint64_t file_bytes = std::filesystem::file_size(path, size_error);
    LoadOptions child_options = options;
    child_options.worker_timeout_seconds = worker_timeout_for(size_error ? 0 : file_bytes, options);
    child_options.worker_memory_bytes = worker_memory_for(size_error ? 0 : file_bytes, options);

    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw std::system_error(errno, std::generic_category(), "pipe for the importer process");
    Fd read_end(fds[0]);
    std::fflush(nullptr);  // nothing buffered twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int error = errno;
        ::close(fds[1]);
        throw std::system_error(error, std::generic_category(), "fork for the importer process");
    }
    if (pid == 0) {
        ::close(fds[0]);
        child_main(fds[1], path, obj_libraries, child_options);
    }
    ::close(fds[1]);
    Child child(pid);

    const double timeout = std::clamp(child_options.worker_timeout_seconds, 0.0, 1e7);
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(timeout));
    const auto timed_out = [&] { return out_of_time(file, timeout, options); };
    const std::size_t memory = child_options.worker_memory_bytes;
    const std::uint64_t max_payload = memory != 0 ? std::uint64_t(memory) : std::uint64_t(1) << 62;
    std::vector<std::uint8_t> message;
    std::uint64_t expected = 0;  // total bytes, once the header is in
    std::vector<std::uint8_t> buffer(1 << 16);
    // Appends what read() gave; false at end of file.
    const auto take = [&](ssize_t n) {
        message.insert(message.end(), buffer.begin(), buffer.begin() + n);
        if (expected == 0 && message.size() >= kWorkerHeaderBytes) {
            const std::uint64_t payload = worker_payload_bytes(message, file);
            if (payload > max_payload)
                throw InputError(file, "the importer's result (" + std::to_string(payload) +
                                           " bytes) is larger than the limit (" +
                                           std::to_string(max_payload) + " bytes)");
            expected = kWorkerHeaderBytes + payload;
            message.reserve(std::size_t(expected));
        }
        if (expected != 0 && message.size() > expected)
            throw InputError(file,
                             "the importer process sent an invalid result: more bytes "
                             "than its header announced");
    };
    // Reading stops at end of file, at a complete message, or when the child has ended (a child
    // another thread of the caller forked at the same moment may hold a copy of the write end, so
    // end of file alone could come late): what is left in the pipe is then drained.
    std::optional<int> status;
    for (;;) {
        if (expected != 0 && message.size() == expected) break;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) throw timed_out();
        pollfd p{read_end.get(), POLLIN, 0};
        const int ready = ::poll(&p, 1, int(std::min<std::int64_t>(left.count() + 1, 50)));
        if (ready < 0) {
            if (errno == EINTR) continue;
            throw std::system_error(errno, std::generic_category(), "poll");
        }
        if (ready == 0) {
            status = child.try_wait();
            if (!status) continue;
            (void)::fcntl(read_end.get(), F_SETFL, O_NONBLOCK);
            for (;;) {
                const ssize_t n = ::read(read_end.get(), buffer.data(), buffer.size());
                if (n < 0 && errno == EINTR) continue;
                if (n <= 0) break;
                take(n);
            }
            break;
        }
        const ssize_t n = ::read(read_end.get(), buffer.data(), buffer.size());
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            throw std::system_error(errno, std::generic_category(), "read from the importer");
        }
        if (n == 0) break;
        take(n);
    }

    if (!status) status = child.wait_until(deadline);
    if (!status) throw timed_out();
    if (WIFSIGNALED(*status)) {
        const int sig = WTERMSIG(*status);
        if (sig == SIGXCPU) throw out_of_time(file, timeout, options);
        if (sig == SIGKILL)
            throw InputError(file,
                             "the importer was killed (" + signal_name(sig) + "; out of memory?)");
        throw InputError(file, "the importer crashed (" + signal_name(sig) + ")");
    }
    if (WIFEXITED(*status) && WEXITSTATUS(*status) == kChildOutOfMemory)
        throw_out_of_memory(file, path, memory, options);
    if (WIFEXITED(*status) && WEXITSTATUS(*status) != 0)
        throw InputError(
            file, "the importer failed (exit status " + std::to_string(WEXITSTATUS(*status)) + ")");
    if (message.empty()) throw InputError(file, "the importer exited without a result");
    return decode_worker_message(message, file, options);
}

}  // namespace zraster::io

namespace zraster {

double worker_timeout_for(std::uint64_t file_bytes, const LoadOptions& options) {
    if (options.worker_timeout_seconds != LoadOptions::kWorkerTimeoutFromFile)
        return options.worker_timeout_seconds;
    return 30.0 + double(file_bytes) / double(1 << 20);
}

std::size_t worker_memory_for(std::uint64_t file_bytes, const LoadOptions& options) {
    if (options.worker_memory_bytes != LoadOptions::kWorkerMemoryFromBudgets)
        return options.worker_memory_bytes;
    // Saturating: 256 MiB + 4 * file_bytes + max_geometry_bytes + 2 * max_texture_bytes (the
    // textures kept, within their budget, and one decoded before it is reduced: 40 textures of
    // 4096x4096 stopped the worker at 1.25 GiB, in its budget for geometry).
    const std::uint64_t most = std::uint64_t{1} << 62;
    const std::uint64_t bytes = std::min(file_bytes, most / 8) * 4 + (std::uint64_t{256} << 20) +
                                std::min<std::uint64_t>(options.max_geometry_bytes, most / 4) +
                                std::min<std::uint64_t>(options.max_texture_bytes, most / 4) * 2;
    return std::size_t(std::min(bytes, most));
}

}  // namespace zraster
