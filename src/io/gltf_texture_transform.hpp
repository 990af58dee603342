// glTF's KHR_texture_transform: an offset, a rotation and a scale of a texture's coordinates.
// Debian's Assimp 5.2.5 reads the extension's members unchecked (a "scale" of one number failed
// a rapidjson assertion: the importer aborted) and zraster drew base color textures without the
// transform. The members are checked before Assimp reads the file, and the base color texture's
// transform is applied to the coordinates of the meshes whose material has one.
#pragma once
#include <glm/vec2.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace zraster::io {

// Throws InputError(file, "malformed glTF file: ...") for a KHR_texture_transform anywhere in
// the document whose offset or scale is not 2 numbers, rotation not a number, or texCoord not a
// whole number of 0 or more.
void check_gltf_texture_transforms(const nlohmann::json& document, const std::string& file);

struct TextureTransform {
    float offset[2] = {0.0f, 0.0f};
    float rotation = 0.0f;  // radians, counter-clockwise
    float scale[2] = {1.0f, 1.0f};
};

// Per glTF material (by index), its base color texture's transform, if any; empty for a file
// that is not glTF or has none.
std::vector<std::optional<TextureTransform>> gltf_base_color_transforms(
    const std::filesystem::path& path);

// Applies `t` to texture coordinates (glTF's and zraster's convention alike: v = 0 at the
// image's first row).
void apply_texture_transform(const TextureTransform& t, std::vector<glm::vec2>& uvs);

}  // namespace zraster::io
