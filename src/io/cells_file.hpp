// `*.cells.json` files (docs/portals.md): mesh files placed as instances, cells and portals.
#pragma once
#include <zraster/load.hpp>
#include <zraster/scene.hpp>

#include "io/loaded_scene.hpp"

#include <filesystem>

namespace zraster::io {

// Whether the file name ends in ".cells.json" (any case).
bool is_cells_file(const std::filesystem::path& path);

// The scene a cells.json file describes, its cell graph validated (validate_cell_graph). Every
// mistake is an InputError naming this file, the JSON element ("cells[2].instances[0]") and the
// cause; the mesh files are loaded with `options` (a mesh file's own errors name it).
LoadedScene load_cells_file(const std::filesystem::path& path, const LoadOptions& options);

}  // namespace zraster::io
