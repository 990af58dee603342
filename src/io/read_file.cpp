#include "io/read_file.hpp"

#include "memory/huge_pages.hpp"

#include <zraster/error.hpp>

#include <cerrno>
#include <fstream>
#include <system_error>

namespace zraster::io {

std::vector<std::uint8_t> read_file_bytes(const std::filesystem::path& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throw InputError(path.string(), "file not found");
    if (!std::filesystem::is_regular_file(status))
        throw InputError(path.string(), "not a regular file");

    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path.string(), "cannot read: " + std::generic_category().message(errno));
    std::vector<std::uint8_t> bytes;
    // The size as stat()ed now (the file may still change: reading goes on to the end anyway).
    const auto expected = std::filesystem::file_size(path, ec);
    if (!ec) memory::reserve_on_huge_pages(bytes, static_cast<std::size_t>(expected));
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
        bytes.insert(bytes.end(), buffer, buffer + in.gcount());
    if (in.bad()) throw InputError(path.string(), "cannot read: I/O error");
    return bytes;
}

}  // namespace zraster::io
