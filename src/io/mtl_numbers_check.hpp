// The numbers of an MTL material library (Kd 0.5 0.5 0.5, Ns 32, d 0.5, ...). Assimp's MTL reader
// takes the numeric prefix of a word ("0.5abc" as 0.5, "1e5x" as 1e5) without a word; a value
// that is not a number is refused as in the OBJ file itself (obj_number_token.hpp).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace zraster::io {

// Throws InputError("OBJ: material library LIBRARY: line N: 'WORD' is not a number") for the
// first word of a numeric statement (Ka, Kd, Ks, Ke, Tf, Ns, Ni, d, Tr, illum, and the PBR ones:
// Pr, Pm, Ps, Pc, Pcr, aniso, anisor) that is not a number. The OBJ file is the error's file, as
// for the model's other errors (and through the worker process, which names the model); LIBRARY
// is relative to the OBJ's folder. A comment (a word starting with '#') ends the statement.
// (`Ka spectral file` and `Ka xyz x y z`, which Assimp refuses in its own words, are refused
// here by their first word.)
// A library with `decal` statements (which Assimp would misread: mtl_for_assimp.hpp) appends one
// warning to *warnings, "material library LIBRARY: line N: decal maps are not supported; ignored".
void check_mtl_numbers(const std::filesystem::path& obj, const std::filesystem::path& library,
                       std::vector<std::string>* warnings = nullptr);

}  // namespace zraster::io
