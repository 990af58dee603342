// Assimp materials to zraster materials (without the texture, which texture_loader resolves).
#pragma once
#include <zraster/material.hpp>

#include <optional>
#include <string>

struct aiMaterial;

namespace zraster::io {

std::string material_name(const aiMaterial& material);

// Materials Assimp invents when the file has none ("DefaultMaterial", nameless ones without any
// colour of their own): zraster's default material stands in for them.
bool is_placeholder_material(const aiMaterial& material);

// Base color (glTF base color, else diffuse), specular color times its strength, shininess
// (clamped to [1, 1024]; zero or absent keeps the default) and opacity.
Material convert_material(const aiMaterial& material);

// The base-color texture reference (glTF base color, else diffuse): a path as written in the
// file, or "*N" for an embedded texture.
std::optional<std::string> base_color_texture_reference(const aiMaterial& material);

}  // namespace zraster::io
