#include "io/zip_archive.hpp"

#include <unzip.h>

#include <memory>

namespace zraster::io {

namespace {

struct CloseZip {
    void operator()(void* zip) const { unzClose(zip); }
};
using Zip = std::unique_ptr<void, CloseZip>;

Zip open_zip(const std::filesystem::path& path) {
    return Zip(unzOpen64(path.c_str()));
}

}  // namespace

std::optional<std::vector<ZipMember>> zip_members(const std::filesystem::path& path) {
    const Zip zip = open_zip(path);
    if (!zip) return std::nullopt;
    std::vector<ZipMember> members;
    for (int at = unzGoToFirstFile(zip.get()); at == UNZ_OK; at = unzGoToNextFile(zip.get())) {
        unz_file_info64 info{};
        char name[4096];
        if (unzGetCurrentFileInfo64(zip.get(), &info, name, sizeof name, nullptr, 0, nullptr, 0) !=
            UNZ_OK)
            return std::nullopt;
        members.push_back({name, info.uncompressed_size});
    }
    return members;
}

std::optional<std::string> read_zip_member(const std::filesystem::path& path,
                                           const std::string& name, std::uint64_t max_bytes) {
    const Zip zip = open_zip(path);
    if (!zip || unzLocateFile(zip.get(), name.c_str(), 1) != UNZ_OK ||
        unzOpenCurrentFile(zip.get()) != UNZ_OK)
        return std::nullopt;
    std::string bytes;
    char chunk[1 << 16];
    for (;;) {
        const int got = unzReadCurrentFile(zip.get(), chunk, sizeof chunk);
        if (got < 0) {
            unzCloseCurrentFile(zip.get());
            return std::nullopt;
        }
        if (got == 0) break;
        const std::uint64_t room = max_bytes - bytes.size();
        bytes.append(chunk, static_cast<std::size_t>(std::min<std::uint64_t>(room, got)));
        if (bytes.size() >= max_bytes) break;
    }
    unzCloseCurrentFile(zip.get());
    return bytes;
}

}  // namespace zraster::io
