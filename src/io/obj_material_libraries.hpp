// What Assimp's OBJ importer does not tell: whether the material libraries an OBJ names exist
// (it only logs a missing one and invents placeholder materials for the `usemtl` names).
#pragma once
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace zraster::io {

struct ObjMaterialLibraries {
    std::vector<std::string> warnings;        // missing libraries, substitutes
    std::set<std::string> defined_materials;  // `newmtl` names of the libraries found
};

// Scans the OBJ's `mtllib` lines and the libraries they name, resolving them as Assimp 5.2 does:
// the rest of the line relative to the OBJ's directory, else "<obj name>.mtl" beside it.
ObjMaterialLibraries scan_obj_material_libraries(const std::filesystem::path& obj_path);

}  // namespace zraster::io
