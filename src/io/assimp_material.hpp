// Assimp materials to zraster materials (without the textures, which texture_loader resolves).
#pragma once
#include <zraster/material.hpp>

#include <optional>
#include <string>
#include <vector>

struct aiMaterial;

namespace zraster::io {

std::string material_name(const aiMaterial& material);

// Materials Assimp invents when the file has none ("DefaultMaterial", nameless ones without any
// colour of their own): zraster's default material stands in for them.
bool is_placeholder_material(const aiMaterial& material);

// The material of the mesh Assimp's SkeletonMeshBuilder draws for a file that has nodes but no
// mesh (ASE, BVH, MD5 animations): a pyramid per node, not the file's geometry. Random bytes
// named .ase load as one.
bool is_skeleton_placeholder_material(const aiMaterial& material);

// Base color (glTF base color, else diffuse), specular color times its strength, shininess
// (clamped to [1, 1024]; zero or absent keeps the default) and alpha (docs/materials.md): glTF's
// alphaMode, alphaCutoff and baseColorFactor alpha; for other formats Assimp's opacity, blended.
// A nameless material is called `fallback_name`. An unknown alphaMode or an alphaCutoff outside
// [0, 1] is a warning (appended to `warnings`), not an error.
Material convert_material(const aiMaterial& material, const std::string& fallback_name,
                          std::vector<std::string>& warnings);

// The base-color texture reference (glTF base color, else diffuse): a path as written in the
// file, or "*N" for an embedded texture.
std::optional<std::string> base_color_texture_reference(const aiMaterial& material);

// The opacity texture reference (MTL map_d, Assimp's aiTextureType_OPACITY), as above.
std::optional<std::string> opacity_texture_reference(const aiMaterial& material);

}  // namespace zraster::io
