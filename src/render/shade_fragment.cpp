#include "render/shade_fragment.hpp"

#include <cmath>
#include <optional>

#include "render/material_alpha.hpp"

namespace zraster::detail {
namespace {

SurfaceMaterial surface_of(const FrameInstance& fi) {
    return {fi.material, fi.shading, fi.textured, fi.vertex_colored};
}

// The source triangle's weights one pixel over (texture derivatives), where it has a setup.
struct RendererNeighbours {
    const Frame& frame;
    const ShadingTriangle& t;
    int px, py;
    std::optional<NeighbourWeights> operator()() const {
        if (!t.has_setup) return std::nullopt;
        const Interpolation interpolation = frame.options->interpolation;
        return NeighbourWeights{
            original_barycentrics(t, barycentrics(t.setup, px + 1, py, interpolation)),
            original_barycentrics(t, barycentrics(t.setup, px, py + 1, interpolation))};
    }
};

}  // namespace

VertexAttributes vertex_attributes(const Frame& frame) {
    const FrameVertices& v = frame.vertices;
    return {v.world, v.normal, v.uv, v.gouraud, v.color};
}

ShadingFrame shading_frame(const Frame& frame, const FrameInstance& fi) {
    const RenderOptions& options = *frame.options;
    return {&options.lighting, frame.eye, frame.view_axis, options.texture_filter,
            fi.two_sided_lighting};
}

void prepare_shading_triangle(const Frame& frame, const Chunk& chunk, const TriangleRef& ref,
                              ShadingTriangle& out) {
    out.chunk = &chunk;
    out.ref = &ref;
    out.corners.vertex = ref.vertex;
    out.corners.front_facing = ref.front_facing;
    const FrameInstance& fi = frame.instances[ref.instance];
    out.has_setup = false;
    if ((fi.textured || fi.alpha_varies.textures) &&
        frame.options->texture_filter == TextureFilter::Trilinear) {
        const std::array<ScreenVertex, 3> v{frame.screen_vertex(chunk, ref, 0),
                                            frame.screen_vertex(chunk, ref, 1),
                                            frame.screen_vertex(chunk, ref, 2)};
        out.has_setup = setup_triangle(v, frame.setup_settings, out.setup) == SetupResult::Visible;
    }
    if (fi.shading == ShadingMode::Flat) {
        const std::vector<glm::vec3>& world = frame.vertices.world;
        out.corners.flat = flat_terms(shading_frame(frame, fi), *fi.material, world[ref.vertex[0]],
                                      world[ref.vertex[1]], world[ref.vertex[2]], ref.front_facing);
    }
}

ShadedFragment shade_fragment(const Frame& frame, const ShadingTriangle& t, float b1, float b2,
                              int px, int py, bool want_normal) {
    const FrameInstance& fi = frame.instances[t.ref->instance];
    const glm::vec3 b = original_barycentrics(t, {1.0f - b1 - b2, b1, b2});
    return shade_surface(shading_frame(frame, fi), surface_of(fi), vertex_attributes(frame),
                         t.corners, b, RendererNeighbours{frame, t, px, py}, want_normal);
}

float fragment_alpha(const Frame& frame, const ShadingTriangle& t, float b1, float b2, int px,
                     int py) {
    const FrameInstance& fi = frame.instances[t.ref->instance];
    if (!fi.alpha_varies.any()) return material_alpha(*fi.material, 1.0f, 1.0f);
    const glm::vec3 b = original_barycentrics(t, {1.0f - b1 - b2, b1, b2});
    return surface_alpha(shading_frame(frame, fi), *fi.material, vertex_attributes(frame),
                         t.corners, b, RendererNeighbours{frame, t, px, py}, fi.alpha_varies);
}

// The corners' world positions and normals of a triangle the SIMD Phong shader draws, for
// interpolation in the visibility kernel: the same values shade_fragment() interpolates.
void corner_attributes(const Frame& frame, const TriangleRef& ref, CornerAttributes& corners) {
    const FrameInstance& fi = frame.instances[ref.instance];
    corners.tag = 0;  // the scalar shader's
    if (fi.phong_kernel < 0) return;
    const bool flip = !ref.front_facing && fi.two_sided_lighting;
    corners.tag = std::uint32_t(fi.phong_kernel + 1) | (flip ? kShadeFlip : 0u);
    for (std::size_t k = 0; k < 3; ++k) {
        corners.world[k] = frame.vertices.world[ref.vertex[k]];
        corners.normal[k] = frame.vertices.normal[ref.vertex[k]];
    }
}

}  // namespace zraster::detail
