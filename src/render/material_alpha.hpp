// What a material's alpha does in a frame (Material::alpha_mode, RenderOptions::alpha_mode): an
// instance is drawn opaque, alpha-tested or blended, and each fragment's alpha.
#pragma once
#include <zraster/material.hpp>
#include <zraster/render.hpp>

namespace zraster::detail {

// The instance's mode this frame: Opaque unless its alpha can be below 1 (or, for Mask, below
// the cutoff) somewhere. `textured`: the mesh has texture coordinates and textures are on, so
// the material's textures count.
AlphaMode effective_alpha_mode(const Material& material, bool textured,
                               const RenderOptions& options);

// Alpha from the material's factors and the texture samples at a fragment (where they count):
// opacity x base-color alpha x opacity texture's red.
inline float material_alpha(const Material& material, float base_color_alpha, float opacity_red) {
    return material.opacity * base_color_alpha * opacity_red;
}

}  // namespace zraster::detail
