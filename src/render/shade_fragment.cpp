#include "render/shade_fragment.hpp"

#include <cmath>

#include "render/material_alpha.hpp"

namespace zraster::detail {
namespace {

glm::vec3 unit_or_up(glm::vec3 n) {
    const float len = glm::length(n);
    return len > 0.0f ? n / len : glm::vec3(0, 1, 0);
}

// A fragment's texture coordinates and, for trilinear filtering, their screen derivatives.
struct TextureLookup {
    glm::vec2 uv{0.0f}, duv_dx{0.0f}, duv_dy{0.0f};
};

TextureLookup texture_lookup(const Frame& frame, const ShadingTriangle& t, int px, int py,
                             const glm::vec3& b) {
    const std::vector<glm::vec2>& uvs = frame.vertices.uv;
    TextureLookup out;
    out.uv = interpolate(uvs, t.ref->vertex, b);
    if (frame.options->texture_filter == TextureFilter::Trilinear && t.has_setup) {
        // Derivatives by evaluating the same interpolation one pixel over (exact, no quads).
        const Interpolation interpolation = frame.options->interpolation;
        out.duv_dx = interpolate(uvs, t.ref->vertex,
                                 original_barycentrics(
                                     t, barycentrics(t.setup, px + 1, py, interpolation))) -
                     out.uv;
        out.duv_dy = interpolate(uvs, t.ref->vertex,
                                 original_barycentrics(
                                     t, barycentrics(t.setup, px, py + 1, interpolation))) -
                     out.uv;
        if (!std::isfinite(out.duv_dx.x + out.duv_dx.y + out.duv_dy.x + out.duv_dy.y))
            out.duv_dx = out.duv_dy = {};
    }
    return out;
}

glm::vec4 sample(const Frame& frame, const Texture& texture, const TextureLookup& at) {
    return texture.sample(at.uv, at.duv_dx, at.duv_dy, frame.options->texture_filter);
}

glm::vec3 base_color(const Frame& frame, const FrameInstance& fi, const ShadingTriangle& t, int px,
                     int py, const glm::vec3& b) {
    const Material& material = *fi.material;
    if (!fi.textured) return material.base_color;
    return material.base_color * glm::vec3(sample(frame, *material.base_color_texture,
                                                  texture_lookup(frame, t, px, py, b)));
}

}  // namespace

void prepare_shading_triangle(const Frame& frame, const Chunk& chunk, const TriangleRef& ref,
                              ShadingTriangle& out) {
    out.chunk = &chunk;
    out.ref = &ref;
    const FrameInstance& fi = frame.instances[ref.instance];
    out.has_setup = false;
    if ((fi.textured || fi.alpha_textured) &&
        frame.options->texture_filter == TextureFilter::Trilinear) {
        const std::array<ScreenVertex, 3> v{frame.screen_vertex(chunk, ref, 0),
                                            frame.screen_vertex(chunk, ref, 1),
                                            frame.screen_vertex(chunk, ref, 2)};
        out.has_setup = setup_triangle(v, frame.setup_settings, out.setup) == SetupResult::Visible;
    }
    if (fi.shading == ShadingMode::Flat) {
        const glm::vec3& a = frame.vertices.world[ref.vertex[0]];
        const glm::vec3& b = frame.vertices.world[ref.vertex[1]];
        const glm::vec3& c = frame.vertices.world[ref.vertex[2]];
        glm::vec3 n = unit_or_up(glm::cross(b - a, c - a));
        if (!ref.front_facing && frame.options->two_sided_lighting) n = -n;
        out.flat = evaluate_lighting(frame.options->lighting, *fi.material, (a + b + c) / 3.0f, n,
                                     frame.eye, frame.view_axis);
    }
}

ShadedFragment shade_fragment(const Frame& frame, const ShadingTriangle& t, float b1, float b2,
                              int px, int py, bool want_normal) {
    const FrameInstance& fi = frame.instances[t.ref->instance];
    const RenderOptions& options = *frame.options;
    const glm::vec3 b = original_barycentrics(t, {1.0f - b1 - b2, b1, b2});
    const bool flip = !t.ref->front_facing && options.two_sided_lighting;
    const auto& idx = t.ref->vertex;

    ShadedFragment out;
    const glm::vec3 base = base_color(frame, fi, t, px, py, b);
    switch (fi.shading) {
        case ShadingMode::Unlit:
            out.color = base;
            break;
        case ShadingMode::Flat:
            out.color = combine(t.flat, base);
            break;
        case ShadingMode::Gouraud: {
            const auto& g = frame.vertices.gouraud;
            LightTerms terms;
            terms.diffuse =
                g[idx[0]].diffuse * b.x + g[idx[1]].diffuse * b.y + g[idx[2]].diffuse * b.z;
            terms.specular =
                g[idx[0]].specular * b.x + g[idx[1]].specular * b.y + g[idx[2]].specular * b.z;
            out.color = combine(terms, base);
            break;
        }
        case ShadingMode::Phong: {
            glm::vec3 n = unit_normal(interpolate(frame.vertices.normal, idx, b));  // as the kernel
            if (flip) n = -n;
            const glm::vec3 p = interpolate(frame.vertices.world, idx, b);
            out.color = combine(
                evaluate_lighting(options.lighting, *fi.material, p, n, frame.eye, frame.view_axis),
                base);
            out.normal = n;
            return out;
        }
    }
    if (want_normal) {
        const glm::vec3 n = unit_or_up(interpolate(frame.vertices.normal, idx, b));
        out.normal = flip ? -n : n;
    }
    return out;
}

float fragment_alpha(const Frame& frame, const ShadingTriangle& t, float b1, float b2, int px,
                     int py) {
    const FrameInstance& fi = frame.instances[t.ref->instance];
    const Material& material = *fi.material;
    float base_alpha = 1.0f, opacity_red = 1.0f;
    if (fi.alpha_textured) {
        const glm::vec3 b = original_barycentrics(t, {1.0f - b1 - b2, b1, b2});
        const TextureLookup at = texture_lookup(frame, t, px, py, b);
        if (material.base_color_texture)
            base_alpha = sample(frame, *material.base_color_texture, at).w;
        if (material.opacity_texture) opacity_red = sample(frame, *material.opacity_texture, at).x;
    }
    return material_alpha(material, base_alpha, opacity_red);
}

// The corners' world positions and normals of a triangle the SIMD Phong shader draws, for
// interpolation in the visibility kernel: the same values shade_fragment() interpolates.
void corner_attributes(const Frame& frame, const TriangleRef& ref, CornerAttributes& corners) {
    const FrameInstance& fi = frame.instances[ref.instance];
    corners.tag = 0;  // the scalar shader's
    if (fi.phong_kernel < 0) return;
    const bool flip = !ref.front_facing && frame.options->two_sided_lighting;
    corners.tag = std::uint32_t(fi.phong_kernel + 1) | (flip ? kShadeFlip : 0u);
    for (std::size_t k = 0; k < 3; ++k) {
        corners.world[k] = frame.vertices.world[ref.vertex[k]];
        corners.normal[k] = frame.vertices.normal[ref.vertex[k]];
    }
}

}  // namespace zraster::detail
