// What Assimp's OBJ importer does not tell: whether the material libraries an OBJ names exist
// (it only logs a missing one and invents placeholder materials for the `usemtl` names).
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <zraster/load.hpp>

#include "io/mtl_dissolve.hpp"
#include "io/reference_policy.hpp"

namespace zraster::io {

struct ObjMaterialLibraries {
    std::vector<std::string> warnings;        // missing libraries, substitutes
    std::set<std::string> defined_materials;  // `newmtl` names of the libraries found
    MtlDissolve dissolve;                     // `d` values a later `Tr` hid from Assimp
    std::vector<std::string> notices;         // statements ignored (`decal`)
};

// The rest of a line after `keyword` and blanks, when the trimmed line starts with it (how
// Assimp's OBJ and MTL readers take a statement's argument).
bool directive(const std::string& line, std::string_view keyword, std::string& argument);

// Where an `mtllib` statement's library is read from, as Assimp 5.2 resolves it (the name
// relative to the OBJ's directory, else "<obj name>.mtl" beside it) within what `policy`
// allows, and the warning to give when it is not the library named (empty when it is).
struct MaterialLibraryChoice {
    std::optional<std::filesystem::path> file;  // none: the default material
    bool substitute = false;                    // file is "<obj name>.mtl"
    std::string warning;
};
MaterialLibraryChoice resolve_material_library(const std::filesystem::path& obj_path,
                                               const std::string& library,
                                               const ReferencePolicy& policy);

// Scans the OBJ's `mtllib` lines and the libraries they name, resolving them as Assimp 5.2 does:
// the rest of the line relative to the OBJ's directory, else "<obj name>.mtl" beside it.
// Libraries `policy` refuses (outside the model's folder, not regular files) are not read, with
// a warning. Each library found is also read for MTL `d` over `Tr` (mtl_dissolve.hpp).
// Throws LimitExceeded past the budgets (check_material_library, check_material_count).
ObjMaterialLibraries scan_obj_material_libraries(const std::filesystem::path& obj_path,
                                                 const ReferencePolicy& policy,
                                                 const LoadOptions& options);

// The largest material library read: MTL files are text of a few KB to MB; 64 MiB (or
// max_file_bytes when smaller). Assimp reads a library whole: a 20 GiB one hung the loader.
std::uintmax_t max_material_library_bytes(const LoadOptions& options);
// Throws LimitExceeded (max_file_bytes) naming the OBJ and the library when `mtl` is larger
// than max_material_library_bytes; before anything reads it.
void check_material_library(const std::filesystem::path& obj_path, const std::filesystem::path& mtl,
                            const LoadOptions& options);
// Makes `policy` note every texture file a library's statements name (map_Kd, map_Ka, bump, ...:
// the statement's last word, beside the library), read by zraster or not: files_read lists them,
// and a command's outputs must not replace a file the model names.
void note_named_textures(const std::filesystem::path& mtl, const ReferencePolicy& policy);

// Throws LimitExceeded (max_materials) when the libraries define more than max_materials
// materials (`newmtl` statements, counted before Assimp reads them).
void check_material_count(const std::filesystem::path& obj_path, std::size_t count,
                          const LoadOptions& options);

}  // namespace zraster::io
