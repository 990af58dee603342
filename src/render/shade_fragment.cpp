#include "render/shade_fragment.hpp"

namespace zraster::detail {
namespace {

glm::vec3 base_color(const Frame& frame, const FrameInstance& fi, const RasterTriangle& t,
                     int px, int py, const glm::vec3& b) {
    const Material& material = *fi.material;
    if (!fi.textured) return material.base_color;
    const Interpolation interpolation = frame.options->interpolation;
    const glm::vec2 uv = interpolate(frame.vertices.uv, t.vertex, b);
    glm::vec2 duv_dx(0.0f), duv_dy(0.0f);
    if (frame.options->texture_filter == TextureFilter::Trilinear) {
        // Derivatives by evaluating the same interpolation one pixel over (exact, no quads).
        duv_dx = interpolate(frame.vertices.uv, t.vertex,
                             original_barycentrics(t, px + 1, py, interpolation)) - uv;
        duv_dy = interpolate(frame.vertices.uv, t.vertex,
                             original_barycentrics(t, px, py + 1, interpolation)) - uv;
        if (!std::isfinite(duv_dx.x + duv_dx.y + duv_dy.x + duv_dy.y)) duv_dx = duv_dy = {};
    }
    const glm::vec4 texel =
        material.base_color_texture->sample(uv, duv_dx, duv_dy, frame.options->texture_filter);
    return material.base_color * glm::vec3(texel);
}

}  // namespace

ShadedFragment shade_fragment(const Frame& frame, const RasterTriangle& t, int px, int py,
                              bool want_normal) {
    const FrameInstance& fi = frame.instances[t.instance];
    const RenderOptions& options = *frame.options;
    const glm::vec3 b = original_barycentrics(t, px, py, options.interpolation);
    const bool flip = !t.setup.front_facing && options.two_sided_lighting;

    ShadedFragment out{};
    const glm::vec3 base = base_color(frame, fi, t, px, py, b);
    switch (fi.shading) {
        case ShadingMode::Unlit: out.color = base; break;
        case ShadingMode::Flat: out.color = combine(t.flat, base); break;
        case ShadingMode::Gouraud: {
            LightTerms terms;
            terms.diffuse = frame.vertices.gouraud[t.vertex[0]].diffuse * b.x +
                            frame.vertices.gouraud[t.vertex[1]].diffuse * b.y +
                            frame.vertices.gouraud[t.vertex[2]].diffuse * b.z;
            terms.specular = frame.vertices.gouraud[t.vertex[0]].specular * b.x +
                             frame.vertices.gouraud[t.vertex[1]].specular * b.y +
                             frame.vertices.gouraud[t.vertex[2]].specular * b.z;
            out.color = combine(terms, base);
            break;
        }
        case ShadingMode::Phong: {
            glm::vec3 n = interpolate(frame.vertices.normal, t.vertex, b);
            const float len = glm::length(n);
            n = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
            if (flip) n = -n;
            const glm::vec3 p = interpolate(frame.vertices.world, t.vertex, b);
            out.color = combine(
                evaluate_lighting(options.lighting, *fi.material, p, n, frame.eye, frame.view_axis),
                base);
            out.normal = n;
            return out;
        }
    }
    if (want_normal) {
        glm::vec3 n = interpolate(frame.vertices.normal, t.vertex, b);
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0, 1, 0);
        out.normal = flip ? -n : n;
    }
    return out;
}

}  // namespace zraster::detail
