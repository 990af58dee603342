// Zip archives Assimp reads (3MF; ZAE, a zipped COLLADA document): it inflates each model member
// whole, at the size the archive declares, and then reads it like any other file. The archive is
// checked first as the files it holds: a 3 MB 3MF whose model inflates to 3 GiB took 3.2 GB; a
// 3MF component naming its own object crashed the importer (it expands components recursively);
// components sharing children took 1.2 KB to 7.8 GB.
#pragma once
#include <zraster/load.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace zraster::io {

// Each build item counts this many placements toward max_instances: the importer adds items in
// time quadratic in their number (measured: 40,000 items 0.37 s, 200,000 8.1 s); 1,000,000 / 10
// = 100,000 items, about 2 s.
inline constexpr std::uint64_t k3mfBuildItemWeight = 10;
// Bytes an object placement takes in the 3MF importer and the conversion (as a COLLADA node's).
inline constexpr std::uint64_t k3mfBytesPerPlacement = 1300;

// For a zip archive (by content): LimitExceeded max_geometry_bytes when its members inflate to
// more than max_geometry_bytes; then each 3MF model member (*.model) is checked by
// check_3mf_model and each COLLADA member (*.dae) as a .dae file is. Does nothing for other files.
void check_zip_archive(const std::filesystem::path& path, const LoadOptions& options);

// A 3MF model document: InputError for an object that contains itself through its components, or
// components nested past 1,000 levels; LimitExceeded max_instances for a build placing more meshes
// than max_instances or of more than max_instances / k3mfBuildItemWeight items, max_geometry_bytes
// for more placements than max_geometry_bytes holds at k3mfBytesPerPlacement. `member` names the
// document in messages.
void check_3mf_model(std::string_view document, const std::string& file, const std::string& member,
                     const LoadOptions& options);

}  // namespace zraster::io
