// The JSON text of a glTF file, for the checks and conversions that read the document again
// after Assimp (vertex color alpha, material member types).
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace zraster::io {

// A GLB's JSON chunk, or a file of JSON whole (Assimp reads a glTF under any name: a file whose
// first non-blank character is '{' is taken as one); empty for anything else.
std::string gltf_document(const std::filesystem::path& path);

// Components of an accessor element of glTF `type` ("VEC3": 3, "MAT4": 16); 0 for a type glTF
// does not define.
inline std::uint64_t gltf_type_components(std::string_view type) {
    return type == "SCALAR"                   ? 1
           : type == "VEC2"                   ? 2
           : type == "VEC3"                   ? 3
           : type == "VEC4" || type == "MAT2" ? 4
           : type == "MAT3"                   ? 9
           : type == "MAT4"                   ? 16
                                              : 0;
}

}  // namespace zraster::io
