// Materials' sides (Material::double_sided, glTF doubleSided; RenderOptions::material_sides):
// which faces of an instance are culled and which are lit two-sided.
//
// A double-sided material's triangles are never culled and their back faces are lit with the
// flipped normal, whatever RenderOptions::cull and two_sided_lighting say; every other triangle
// follows them. Culling is then decided per instance by the front end, and setup_triangle, which
// everything after the front end calls (binning, tiles, shading's texture derivatives), is told
// to cull nothing in such a frame: it only ever sees triangles the front end kept, and its setups
// are the same bits whatever its cull mode for a triangle it keeps.
#pragma once
#include <zraster/material.hpp>
#include <zraster/render.hpp>

namespace zraster::detail {

// Whether the material's sides count this frame.
inline bool double_sided(const Material& material, const RenderOptions& options) {
    return options.material_sides && material.double_sided;
}

// The faces culled of an instance of the material.
inline CullMode instance_cull(const Material& material, const RenderOptions& options) {
    return double_sided(material, options) ? CullMode::None : options.cull;
}

// Whether an instance's back faces are lit with the flipped normal.
inline bool instance_two_sided_lighting(const Material& material, const RenderOptions& options) {
    return options.two_sided_lighting || double_sided(material, options);
}

}  // namespace zraster::detail
