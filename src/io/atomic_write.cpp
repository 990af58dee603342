#include "io/atomic_write.hpp"

#include <zraster/error.hpp>

#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace zraster::io {

namespace {

std::string errno_message(int error) {
    return std::generic_category().message(error);
}

// Unique per process and per call, so concurrent writers of the same path do not collide.
std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path temp = path;
    temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return temp;
}

// Writes everything or returns the errno of the failure (0 on success).
int write_all(int fd, std::span<const std::uint8_t> bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        bytes = bytes.subspan(static_cast<std::size_t>(n));
    }
    return 0;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
    const std::filesystem::path temp = temporary_path_for(path);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) throw InputError(path.string(), "cannot write: " + errno_message(errno));

    // No fsync: atomicity here protects against our own failures and concurrent readers, not
    // against power loss, and syncing every image would slow down batch renders a lot.
    int error = write_all(fd, bytes);
    if (::close(fd) != 0 && error == 0) error = errno;
    std::error_code ec;
    if (error == 0) {
        std::filesystem::rename(temp, path, ec);
        if (ec) error = ec.value();
    }
    if (error != 0) {
        std::filesystem::remove(temp, ec);
        throw InputError(path.string(), "cannot write: " + errno_message(error));
    }
}

}  // namespace zraster::io
