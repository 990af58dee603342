// The file's bytes and their line-aligned chunks (see obj_scan.hpp).
#include "io/obj_scan.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace zraster::io::obj {

namespace {

std::string error_text(int error) {
    return std::generic_category().message(error);
}

}  // namespace

FileBytes::FileBytes(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw InputError(path.string(), "cannot read: " + error_text(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        const int error = errno;
        ::close(fd);
        throw InputError(path.string(), "cannot read: " + error_text(error));
    }
    size_ = static_cast<std::size_t>(info.st_size);
    if (!map(fd)) read_all(fd, path);
    ::close(fd);
}

FileBytes::~FileBytes() {
    if (map_ != nullptr) ::munmap(map_, map_size_);
}

// The file over the start of a zeroed anonymous mapping one page longer: the bytes after the file
// read as zeros, also when its size is a multiple of the page size.
bool FileBytes::map(int fd) {
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    map_size_ = (size_ + page - 1) / page * page + page;
    void* area = ::mmap(nullptr, map_size_, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (area == MAP_FAILED) return false;
    if (size_ > 0 && ::mmap(area, size_, PROT_READ, MAP_PRIVATE | MAP_FIXED | MAP_POPULATE, fd,
                            0) == MAP_FAILED) {
        ::munmap(area, map_size_);
        return false;
    }
    map_ = area;
    return true;
}

void FileBytes::read_all(int fd, const std::filesystem::path& path) {
    copy_.assign(size_ + kPadding, '\0');
    std::size_t done = 0;
    while (done < size_) {
        const ssize_t n = ::read(fd, copy_.data() + done, size_ - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : EIO;
            ::close(fd);
            throw InputError(path.string(), "cannot read: " + error_text(error));
        }
        done += static_cast<std::size_t>(n);
    }
}

std::vector<ByteRange> line_aligned_chunks(const char* data, std::size_t size) {
    const std::size_t target =
        std::clamp<std::size_t>(size / 256, std::size_t{256} << 10, std::size_t{16} << 20);
    std::vector<ByteRange> chunks;
    std::size_t at = 0;
    while (at < size) {
        std::size_t end = std::min(size, at + target);
        if (end < size) {
            const void* newline = std::memchr(data + end, '\n', size - end);
            end = newline != nullptr
                      ? static_cast<std::size_t>(static_cast<const char*>(newline) - data) + 1
                      : size;
        }
        chunks.push_back(ByteRange{data + at, data + end});
        at = end;
    }
    return chunks;
}

}  // namespace zraster::io::obj
