// Fragment shading in the renderer: a pixel's barycentrics mapped to its source triangle and
// shaded by the shading core (shade/surface_shading.hpp). Used by the deferred pass (once per
// visible pixel), the forward path (once per fragment that passes the depth test) and the blend
// pass.
#pragma once
#include "render/frame.hpp"
#include "shade/surface_shading.hpp"

namespace zraster::detail {

using ShadedFragment = SurfaceShade;

// What the shader needs about one triangle, computed once and reused for its pixels.
struct ShadingTriangle {
    const Chunk* chunk = nullptr;
    const TriangleRef* ref = nullptr;
    ShadingCorners corners;  // its vertices, facing and flat lighting
    TriangleSetup setup;     // valid when has_setup (textured instances need derivatives)
    bool has_setup = false;
};

// The frame's vertex attributes and lighting as the shading core takes them.
VertexAttributes vertex_attributes(const Frame& frame);
// For the triangles of `fi` (two-sided lighting per its material's sides).
ShadingFrame shading_frame(const Frame& frame, const FrameInstance& fi);

// Barycentric weights of the ORIGINAL triangle's vertices from those of a (clipped) piece.
inline glm::vec3 original_barycentrics(const ShadingTriangle& t, glm::vec3 b) {
    if (t.ref->piece == TriangleRef::kNotClipped) return b;
    const auto& w = t.chunk->pieces[t.ref->piece].weights;
    return b.x * w[0] + b.y * w[1] + b.z * w[2];
}

void prepare_shading_triangle(const Frame& frame, const Chunk& chunk, const TriangleRef& ref,
                              ShadingTriangle& out);

// b1, b2: barycentric weights of the piece's corners 1 and 2 at pixel (px, py).
ShadedFragment shade_fragment(const Frame& frame, const ShadingTriangle& triangle, float b1,
                              float b2, int px, int py, bool want_normal);

// The corners' world positions and normals of a triangle the SIMD Phong shader draws (tag:
// its Phong constants + 1 and kShadeFlip for a back face lit two-sided; 0, nothing else set,
// for the scalar shader's): the values shade_fragment() interpolates.
void corner_attributes(const Frame& frame, const TriangleRef& ref, CornerAttributes& corners);

// The fragment's alpha (material_alpha.hpp) at pixel (px, py), its textures sampled as the base
// color is.
float fragment_alpha(const Frame& frame, const ShadingTriangle& triangle, float b1, float b2,
                     int px, int py);

}  // namespace zraster::detail
