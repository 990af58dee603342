#include "io/input_file_check.hpp"

#include <zraster/error.hpp>

#include <cerrno>
#include <fstream>
#include <system_error>

namespace zraster::io {

std::uintmax_t check_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes,
                                const char* limit) {
    const std::string name = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) {
        // status() follows links: a loop of them, or one to nothing, is not "not found".
        if (ec == std::errc::too_many_symbolic_link_levels)
            throw InputError(name, "is a loop of symbolic links");
        if (std::filesystem::is_symlink(std::filesystem::symlink_status(path, ec)))
            throw InputError(name, "is a symbolic link to a file that does not exist");
        throw InputError(name, "file not found");
    }
    if (!std::filesystem::is_regular_file(status)) throw InputError(name, "not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(name, "cannot read: " + ec.message());
    if (size == 0) throw InputError(name, "empty file");
    if (size > max_bytes) {
        const std::string cause = "file too large (" + std::to_string(size) + " bytes, limit " +
                                  std::to_string(max_bytes) + ")";
        if (limit != nullptr) throw LimitExceeded(name, limit, cause);
        throw InputError(name, cause);
    }
    // Assimp only says it cannot open the file; find out why first.
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw InputError(name, "cannot read: " + std::generic_category().message(errno));
    return size;
}

}  // namespace zraster::io
