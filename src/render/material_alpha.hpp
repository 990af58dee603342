// What a material's alpha does in a frame (Material::alpha_mode, RenderOptions::alpha_mode): an
// instance is drawn opaque, alpha-tested or blended, and each fragment's alpha.
#pragma once
#include <zraster/material.hpp>
#include <zraster/render.hpp>

#include "shade/surface_shading.hpp"

#include <algorithm>
#include <span>

namespace zraster::detail {

// The instance's mode this frame: Opaque unless its alpha can be below 1 (or, for Mask, below
// the cutoff) somewhere. `textured`: the mesh has texture coordinates and textures are on, so
// the material's textures count. `least_vertex_alpha`: the least alpha of the mesh's vertex
// colors (1 without colors); vertex alpha counts where it is below 1.
AlphaMode effective_alpha_mode(const Material& material, bool textured, float least_vertex_alpha,
                               const RenderOptions& options);

// The least alpha of a mesh's vertex colors (1 without colors).
inline float least_vertex_alpha(std::span<const glm::vec4> colors) {
    float least = 1.0f;
    for (const glm::vec4& c : colors) least = std::min(least, c.w);
    return least;
}

// Alpha from the material's factors and the texture samples at a fragment (where they count):
// opacity x base-color alpha x opacity texture's red.
inline float material_alpha(const Material& material, float base_color_alpha, float opacity_red) {
    return material.opacity * base_color_alpha * opacity_red;
}

// Where an instance's alpha varies over its surface this frame.
struct AlphaVariation {
    bool textures = false;  // the material's alpha textures (uvs, textures on)
    bool vertices = false;  // the mesh's vertex alpha (some below 1)
    bool any() const { return textures || vertices; }
};

// The fragment's alpha at weights b of its triangle's corners: material_alpha() of its texture
// samples (taken as the base color's are), times the interpolated vertex alpha. The one copy of
// the arithmetic for every path (renderer, A-buffer, MSAA, classic algorithms, SVG), so their
// alphas agree bit for bit wherever they take them at the same point.
template <class Neighbours>
float surface_alpha(const ShadingFrame& frame, const Material& material,
                    const VertexAttributes& attributes, const ShadingCorners& corners,
                    const glm::vec3& b, const Neighbours& neighbours, AlphaVariation varies) {
    float base_alpha = 1.0f, opacity_red = 1.0f;
    if (varies.textures) {
        const TextureLookup at = texture_lookup(frame, attributes, corners, b, neighbours);
        if (material.base_color_texture)
            base_alpha = sample(frame, *material.base_color_texture, at).w;
        if (material.opacity_texture) opacity_red = sample(frame, *material.opacity_texture, at).x;
    }
    const float alpha = material_alpha(material, base_alpha, opacity_red);
    if (!varies.vertices) return alpha;
    return alpha * interpolate(attributes.color, corners.vertex, b).w;
}

}  // namespace zraster::detail
