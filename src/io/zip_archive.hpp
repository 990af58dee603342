// The members of a zip archive (3MF, ZAE): Assimp reads their models from zip archives with
// minizip, allocating each member's declared size and reading it whole, so the checks made before
// it reads a file need the same view. A thin wrapper over minizip (the library Assimp uses).
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace zraster::io {

struct ZipMember {
    std::string name;
    std::uint64_t size = 0;  // uncompressed, as the archive declares it
};

// The archive's members, or nothing when `path` is not a zip archive minizip can open.
std::optional<std::vector<ZipMember>> zip_members(const std::filesystem::path& path);

// The member's bytes (at most `max_bytes`: a member declaring less than it inflates to is cut
// there); nothing when it cannot be read.
std::optional<std::string> read_zip_member(const std::filesystem::path& path,
                                           const std::string& name, std::uint64_t max_bytes);

}  // namespace zraster::io
