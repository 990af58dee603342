// glTF material members of the wrong JSON type. Assimp's glTF2 importer skips such a member
// without a word and uses the specification's default: "alphaMode": 7 draws opaque, like an
// alphaMode string outside OPAQUE, MASK and BLEND, which warns (assimp_material.cpp). These
// warn the same way, saying the value used.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace zraster::io {

// One warning per member of the wrong type ("material 'red': alphaCutoff \"x\" is not a
// number, using 0.5 (glTF's default)"; "material 3" when unnamed): alphaMode (a string),
// alphaCutoff (a number), doubleSided (true or false), pbrMetallicRoughness.baseColorFactor,
// metallicFactor and roughnessFactor (4 numbers, a number, a number), emissiveFactor (3 numbers).
// None for a file that is not glTF (gltf_document.hpp) or does not parse.
std::vector<std::string> gltf_material_type_warnings(const std::filesystem::path& path);

}  // namespace zraster::io
