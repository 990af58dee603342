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
// Also one per number outside its glTF range that zraster does not shade with ("material 0:
// metallicFactor -5 is outside glTF's range [0, 1]; not used (zraster does not shade with it)"):
// metallicFactor, emissiveFactor (each of 0..1), KHR_materials_emissive_strength's
// emissiveStrength (0 or more), KHR_materials_ior's ior (1 or more, or 0). (baseColorFactor,
// alphaCutoff and roughnessFactor, which it uses, are clamped with a warning by
// assimp_material.cpp.)
// None for a file that is not glTF (gltf_document.hpp) or does not parse.
std::vector<std::string> gltf_material_type_warnings(const std::filesystem::path& path);

}  // namespace zraster::io
