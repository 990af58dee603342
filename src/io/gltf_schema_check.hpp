// glTF 2.0 rules Debian's Assimp 5.2.5 does not check, checked before it reads the file: what it
// would otherwise read wrongly without a word (a byteStride shorter than its elements, an
// attribute of the wrong type, a required extension it cannot decode) or report in its own
// terms (a child or scene index out of range).
#pragma once
#include <nlohmann/json.hpp>

#include <filesystem>

namespace zraster::io {

// Throws InputError("malformed glTF file: glTF ...") naming the element and the rule:
// - a buffer view's byteStride outside 4..252 or not a multiple of 4, or shorter than an element
//   of an accessor that reads it;
// - a mesh attribute of another type than the specification's (POSITION and NORMAL VEC3,
//   TEXCOORD_n VEC2, COLOR_n VEC3 or VEC4);
// - a node child that is not a node index; a "scene" past the file's scenes;
// and InputError("... requires the glTF extension X, which zraster does not read") for an
// extensionsRequired entry that changes geometry or is unknown (material extensions, which only
// change shading that zraster approximates anyway, are accepted); and KHR_texture_transform's
// members (gltf_texture_transform.hpp).
void check_gltf_schema(const std::filesystem::path& path, const nlohmann::json& document);

}  // namespace zraster::io
