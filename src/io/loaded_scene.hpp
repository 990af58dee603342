// A scene as a reader made it, with the non-fatal problems found on the way: what the readers
// and the worker protocol pass around before load_scene hands the warnings to its caller.
#pragma once
#include <zraster/scene.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace zraster::io {

struct LoadedScene {
    Scene scene;
    std::vector<std::string> warnings;  // one line each, starting with the file name
    // The files besides the model the reader read, canonical (ReferencePolicy::files_read).
    std::vector<std::filesystem::path> files_read;
};

}  // namespace zraster::io
