// Shading of project_scene's polygons at any point, the way render() shades a pixel: the
// instance's shading mode (unlit, flat, Gouraud, Phong), the lighting model, textures with the
// renderer's filter and level of detail, perspective-correct (or screen-linear, per
// options.interpolation) attributes. What the A-buffer shades its fragments with.
//
// At a pixel center covered by one of the polygon's fan triangles the result is render()'s for
// that pixel bit for bit: the same fan (the renderer triangulates a clipped polygon from its first
// vertex too), the same setup_triangle planes, the same barycentrics, the same per-vertex
// attributes (detail::world_attributes) and the same shading core (shade/surface_shading.hpp).
// Anywhere else (the centroid of a partial A-buffer fragment) the barycentrics come from the
// fan's window positions in double.
//
// Cost: O(vertices) once per frame for the per-vertex attributes (world position, normal, uv,
// Gouraud lighting), O(fan triangles) setups per polygon, one lighting evaluation per shade.
#pragma once
#include <zraster/raster.hpp>

#include <cstdint>
#include <vector>

#include "render/material_alpha.hpp"
#include "shade/surface_shading.hpp"
#include "visibility/frame_context.hpp"

namespace zraster::visibility_detail {

using Shaded = detail::SurfaceShade;

class SurfaceShader {
  public:
    // What shading needs about one polygon, computed once.
    struct Prepared {
        // The polygon shaded from: the one given, or for a piece of a scene triangle (split by
        // the painter's algorithm or the BSP tree) the whole triangle as project_scene projects
        // it (`source`), so that its pixels get the barycentrics render() computes for them.
        const ScreenPolygon* polygon = nullptr;
        ScreenPolygon source;
        std::vector<ScreenVertex> screen;     // the polygon's vertices through to_screen
        std::vector<TriangleSetup> fans;      // setup_triangle of fan (0, k, k + 1), with planes
        std::vector<std::uint32_t> fan_k;     // k of each entry of fans
        std::vector<std::uint8_t> fan_valid;  // setup_triangle accepted it (else only `screen`)
        // The source triangle's vertices (the shader's arrays), facing and flat lighting.
        detail::ShadingCorners corners;
        std::uint32_t instance = 0;
    };

    // `frame` must outlive the shader. Computes the per-vertex attributes of every instance.
    explicit SurfaceShader(const FrameContext& frame);

    void prepare(const ScreenPolygon& polygon, Prepared& out) const;

    // At the center of pixel (px, py) (the renderer's result there), or with center = false at
    // the window point (x, y) (pixels, y down) inside the polygon.
    Shaded shade(const Prepared& p, int px, int py, bool center, double x, double y,
                 bool want_normal) const;

    // What the instance's material alpha does this frame (effective_alpha_mode: Opaque unless
    // its alpha can fall below 1, or below the cutoff for Mask).
    AlphaMode alpha_mode(std::int32_t instance) const {
        return instances_[std::size_t(instance)].alpha;
    }
    // Whether its alpha varies over the surface (textures' or vertex alpha), else it is
    // constant_alpha().
    bool alpha_varies(std::int32_t instance) const {
        return instances_[std::size_t(instance)].alpha_varies.any();
    }
    // The alpha of an instance whose alpha does not vary: the material's opacity.
    float constant_alpha(std::int32_t instance) const;
    // The fragment's alpha (render/material_alpha.hpp: opacity x base-color texture alpha x
    // opacity texture red x vertex alpha, unclamped) at the point shade() would shade: its
    // textures sampled as the base color is, with the same coordinates and derivatives, so at a
    // pixel center the z-buffer draws it is render()'s alpha there bit for bit.
    float alpha(const Prepared& p, int px, int py, bool center, double x, double y) const;
    // Whether a fragment of alpha `a` of this instance survives the alpha test (Mask: a >= the
    // cutoff, NaN fails, as the z-buffer tests; other modes: always).
    bool passes_alpha_test(std::int32_t instance, float a) const;

  private:
    struct InstanceInfo {
        const Material* material = nullptr;
        ShadingMode shading = ShadingMode::Phong;
        bool textured = false;
        bool vertex_colored = false;  // the mesh has vertex colors
        AlphaMode alpha = AlphaMode::Opaque;
        detail::AlphaVariation alpha_varies;  // from textures (uvs, textures on), vertex alpha
        bool two_sided_lighting = true;       // render/material_sides.hpp
        std::uint32_t first_vertex = 0;
    };
    // The source triangle's weights at the point shade() takes and one pixel over; false when
    // the polygon has no fan to take them from.
    bool weights_at(const Prepared& p, int px, int py, bool center, double x, double y,
                    glm::vec3& b, detail::NeighbourWeights& over) const;
    glm::vec3 original_weights(const Prepared& p, std::size_t fan, const glm::vec3& b) const;
    // The frame's shading with the instance's two-sided lighting.
    detail::ShadingFrame shading_of(const InstanceInfo& info) const {
        detail::ShadingFrame s = shading_;
        s.two_sided_lighting = info.two_sided_lighting;
        return s;
    }
    // Barycentrics (of the fan's corners) at window point (x, y) from the window positions.
    glm::vec3 fan_barycentrics(const Prepared& p, std::size_t fan, double x, double y) const;

    const FrameContext& frame_;
    detail::ShadingFrame shading_;
    std::vector<InstanceInfo> instances_;
    std::vector<glm::vec3> world_, normal_;
    std::vector<glm::vec2> uv_;
    std::vector<LightTerms> gouraud_;  // Gouraud instances only (else empty entries)
    std::vector<glm::vec4> color_;     // vertex-colored instances only (else empty entries)
};

// Whether any instance's material alpha counts this frame (as SurfaceShader decides it): when
// none does, the algorithms draw as if every surface were opaque.
bool scene_has_alpha(const Scene& scene, const RenderOptions& options);

}  // namespace zraster::visibility_detail
