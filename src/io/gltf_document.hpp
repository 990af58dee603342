// The JSON text of a glTF file, for the checks and conversions that read the document again
// after Assimp (vertex color alpha, material member types).
#pragma once
#include <filesystem>
#include <string>

namespace zraster::io {

// A GLB's JSON chunk, or a file of JSON whole (Assimp reads a glTF under any name: a file whose
// first non-blank character is '{' is taken as one); empty for anything else.
std::string gltf_document(const std::filesystem::path& path);

}  // namespace zraster::io
