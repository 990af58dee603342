// glTF image URIs Assimp drops without a word: an empty one, a data: URI that is not
// "data:<type>;base64,<data>" (it decodes base64 only), and one of no data. The texture is then
// missing, as a file that is not found is, and warned about the same way.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace zraster::io {

// One warning per such image ("image 0's uri '' is empty: its texture is not used"); none for a
// file that is not glTF or does not parse.
std::vector<std::string> gltf_image_uri_warnings(const std::filesystem::path& path);

}  // namespace zraster::io
