// load_scene with the warnings it reports, for the loader tests that look at both.
#pragma once
#include <zraster/load.hpp>

#include "io/loaded_scene.hpp"

#include <filesystem>

namespace zraster::test {

inline io::LoadedScene load_with_warnings(const std::filesystem::path& path,
                                          const LoadOptions& options = {}) {
    io::LoadedScene out;
    out.scene = load_scene(path, options, &out.warnings);
    return out;
}

}  // namespace zraster::test
