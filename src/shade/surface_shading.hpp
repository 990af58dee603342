// The shading core: a surface point's color and shading normal from its instance's material and
// shading mode, the lighting, and its triangle's per-vertex attributes weighted by the point's
// barycentrics. The renderer's deferred and forward passes, the A-buffer, MSAA and the classic
// visibility algorithms all shade through these functions, so their images agree bit for bit
// wherever they shade the same point: there is one copy of the arithmetic. (The SIMD Phong
// shader, phong_kernel.hpp, is the vector twin of the Phong case; a test compares them.)
#pragma once
#include <zraster/lighting.hpp>
#include <zraster/material.hpp>
#include <zraster/texture.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "shade/phong_kernel.hpp"

namespace zraster::detail {

// The per-vertex attributes of a frame in world space, indexed by the frame's vertex numbers.
struct VertexAttributes {
    std::span<const glm::vec3> world;
    std::span<const glm::vec3> normal;    // unit
    std::span<const glm::vec2> uv;        // (0, 0) where a mesh has none
    std::span<const LightTerms> gouraud;  // Gouraud instances' vertices (others unread)
    std::span<const glm::vec4> color;     // vertex colors (only vertex-colored instances read)
};

// A vertex's world position and unit world normal ((0, 1, 0) for a zero normal): the one
// definition the vertex stage's SIMD and scalar paths and the classic algorithms share,
// operation for operation.
inline void world_attributes(const glm::mat4& model, const glm::mat3& normal_matrix,
                             const glm::vec3& position, const glm::vec3& object_normal,
                             glm::vec3& world, glm::vec3& normal) {
    world = glm::vec3(model * glm::vec4(position, 1.0f));
    const glm::vec3 n = normal_matrix * object_normal;
    const float len = glm::length(n);
    normal = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
}

// What shading needs of the frame as a whole.
struct ShadingFrame {
    const LightingModel* lighting = nullptr;
    glm::vec3 eye{0.0f}, view_axis{0.0f, 0.0f, 1.0f};
    TextureFilter filter = TextureFilter::Trilinear;
    bool two_sided_lighting = true;
};

// What shading needs of one instance.
struct SurfaceMaterial {
    const Material* material = nullptr;
    ShadingMode shading = ShadingMode::Phong;
    bool textured = false;        // base color from its texture (the mesh has uvs, textures on)
    bool vertex_colored = false;  // base color times the interpolated vertex color
};

// One triangle as shading sees it.
struct ShadingCorners {
    std::array<std::uint32_t, 3> vertex{};  // into VertexAttributes
    bool front_facing = true;
    LightTerms flat;  // flat shading: flat_terms(), lit once per triangle
};

struct SurfaceShade {
    glm::vec3 color{0.0f};
    glm::vec3 normal{0.0f};  // world space, facing the viewer side when two-sided lighting is on
};

// Barycentric weights one pixel over in x and in y, for texture derivatives (trilinear
// filtering). Callers supply them lazily: only textured points read them.
struct NeighbourWeights {
    glm::vec3 dx{0.0f}, dy{0.0f};
};

template <class T>
T interpolate(std::span<const T> values, const std::array<std::uint32_t, 3>& v,
              const glm::vec3& b) {
    return values[v[0]] * b.x + values[v[1]] * b.y + values[v[2]] * b.z;
}

inline glm::vec3 unit_or_up(glm::vec3 n) {
    const float len = glm::length(n);
    return len > 0.0f ? n / len : glm::vec3(0, 1, 0);
}

// Flat shading of a triangle with world corners a, b, c: lit once at its centroid with its face
// normal (negated for a back face lit two-sided).
inline LightTerms flat_terms(const ShadingFrame& frame, const Material& material,
                             const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                             bool front_facing) {
    glm::vec3 n = unit_or_up(glm::cross(b - a, c - a));
    if (!front_facing && frame.two_sided_lighting) n = -n;
    return evaluate_lighting(*frame.lighting, material, (a + b + c) / 3.0f, n, frame.eye,
                             frame.view_axis);
}

// A point's texture coordinates and, for trilinear filtering, their screen derivatives.
struct TextureLookup {
    glm::vec2 uv{0.0f}, duv_dx{0.0f}, duv_dy{0.0f};
};

// neighbours() -> std::optional<NeighbourWeights>: the weights one pixel over (nullopt: no
// derivatives, the finest level).
template <class Neighbours>
TextureLookup texture_lookup(const ShadingFrame& frame, const VertexAttributes& attributes,
                             const ShadingCorners& corners, const glm::vec3& b,
                             const Neighbours& neighbours) {
    TextureLookup out;
    out.uv = interpolate(attributes.uv, corners.vertex, b);
    if (frame.filter != TextureFilter::Trilinear) return out;
    const std::optional<NeighbourWeights> over = neighbours();
    if (!over) return out;
    // Derivatives by evaluating the same interpolation one pixel over (exact, no quads).
    out.duv_dx = interpolate(attributes.uv, corners.vertex, over->dx) - out.uv;
    out.duv_dy = interpolate(attributes.uv, corners.vertex, over->dy) - out.uv;
    if (!std::isfinite(out.duv_dx.x + out.duv_dx.y + out.duv_dy.x + out.duv_dy.y))
        out.duv_dx = out.duv_dy = {};
    return out;
}

inline glm::vec4 sample(const ShadingFrame& frame, const Texture& texture,
                        const TextureLookup& at) {
    return texture.sample(at.uv, at.duv_dx, at.duv_dy, frame.filter);
}

// The color and shading normal at the point of weights b (of the triangle's corners).
template <class Neighbours>
SurfaceShade shade_surface(const ShadingFrame& frame, const SurfaceMaterial& surface,
                           const VertexAttributes& attributes, const ShadingCorners& corners,
                           const glm::vec3& b, const Neighbours& neighbours, bool want_normal) {
    const Material& material = *surface.material;
    const auto& idx = corners.vertex;
    const bool flip = !corners.front_facing && frame.two_sided_lighting;
    glm::vec3 base = material.base_color;
    if (surface.textured)
        base = material.base_color *
               glm::vec3(sample(frame, *material.base_color_texture,
                                texture_lookup(frame, attributes, corners, b, neighbours)));
    if (surface.vertex_colored) base *= glm::vec3(interpolate(attributes.color, idx, b));
    SurfaceShade out;
    switch (surface.shading) {
        case ShadingMode::Unlit:
            out.color = base;
            break;
        case ShadingMode::Flat:
            out.color = combine(corners.flat, base);
            break;
        case ShadingMode::Gouraud: {
            const std::span<const LightTerms> g = attributes.gouraud;
            LightTerms terms;
            terms.diffuse =
                g[idx[0]].diffuse * b.x + g[idx[1]].diffuse * b.y + g[idx[2]].diffuse * b.z;
            terms.specular =
                g[idx[0]].specular * b.x + g[idx[1]].specular * b.y + g[idx[2]].specular * b.z;
            out.color = combine(terms, base);
            break;
        }
        case ShadingMode::Phong: {
            // Normalized as the SIMD Phong shader normalizes.
            glm::vec3 n = unit_normal(interpolate(attributes.normal, idx, b));
            if (flip) n = -n;
            const glm::vec3 p = interpolate(attributes.world, idx, b);
            out.color = combine(
                evaluate_lighting(*frame.lighting, material, p, n, frame.eye, frame.view_axis),
                base);
            out.normal = n;
            return out;
        }
    }
    if (want_normal) {
        const glm::vec3 n = unit_or_up(interpolate(attributes.normal, idx, b));
        out.normal = flip ? -n : n;
    }
    return out;
}

}  // namespace zraster::detail
