// See input_stream.hpp.
#include "input_stream.hpp"

#include <zraster/error.hpp>

#include <ext/stdio_filebuf.h>

#include <cerrno>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace zraster::cli {
namespace {

// An istream that owns its buffer (the buffer owns the descriptor).
class FdStream : public std::istream {
  public:
    explicit FdStream(int fd) : std::istream(nullptr), buffer_(fd, std::ios::in) {
        rdbuf(&buffer_);
    }

  private:
    __gnu_cxx::stdio_filebuf<char> buffer_;
};

}  // namespace

std::unique_ptr<std::istream> open_input_stream(const std::filesystem::path& path,
                                                const std::string& what) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(what, "is a folder, not a file");
    // O_NONBLOCK for the open only: a FIFO without a writer opens at once (a blocking open
    // would wait for one); reads then block as usual, and see the end once no writer is left.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw InputError(what, "cannot open: " + std::generic_category().message(errno));
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return std::make_unique<FdStream>(fd);
}

}  // namespace zraster::cli
