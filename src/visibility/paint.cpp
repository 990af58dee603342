// Filling polygons in a given order with no depth test (canvas.hpp), and paint_polygons.
//
// Coverage is the renderer's own: each convex polygon is fan-triangulated from its first vertex
// (as the renderer triangulates a clipped polygon) and each triangle goes through setup_triangle
// and for_each_covered_pixel, so a polygon that was not split covers exactly the pixels it covers
// in render(). Split pieces share their new vertices bit for bit, so a split line leaves no crack
// and no double coverage; only where a new vertex lies on the polygon's outline can its snapping
// move the outline by up to half a subpixel.
//
// Shading, given the scene, is the renderer's too (SurfaceShader: the shading core at the pixel
// center, from the source triangle's attributes), so an unsplit polygon's pixels get render()'s
// colors bit for bit whichever algorithm decided they are visible.
//
// Alpha (canvas.hpp): Mask pixels tested and Blend pixels composited as render() does, with the
// alpha sampled by SurfaceShader::alpha (render()'s alpha bit for bit at an unsplit polygon's
// pixels). Drawn back to front, "over" in drawing order is the z-buffer's sorted composite.
//
// Cost: O(covered pixels) per polygon (overdraw included: every polygon is filled, hidden or not),
// and with shading one shading evaluation per filled pixel (and one alpha evaluation for a
// textured Mask or Blend material).
#include "visibility/canvas.hpp"

#include <algorithm>

#include "render/blend_kernels.hpp"

namespace zraster {
namespace visibility_detail {

// The scene's shading for the canvas, and the polygons prepared for it.
struct Canvas::Shading {
    FrameContext frame;
    SurfaceShader shader;
    SurfaceShader::Prepared scratch;  // draw(polygon): prepared anew each time
    std::unordered_map<const ScreenPolygon*, SurfaceShader::Prepared> kept;  // by address

    Shading(const Scene& scene, const RenderOptions& options)
        : frame(make_frame_context(scene, options)), shader(frame) {}
};

namespace {

// An 8-bit channel as render()'s blend pass reads it (render/blend_kernels.hpp).
float unorm8_to_float(std::uint8_t v) {
    return detail::blend_channel(v, 0);
}

float unit_clamp_alpha(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // (NaN: 0), as render()'s blend pass
}

}  // namespace

Canvas::Canvas(const RenderOptions& options, const Camera& camera, const Scene* shade_from)
    : options_(options) {
    setup_.viewport = {options.width, options.height};
    setup_.depth_range = camera.clip_depth_range();
    // (Polygons come culled from projection, per instance; see scene_cull.)
    setup_.cull = shade_from != nullptr ? scene_cull(*shade_from, options) : options.cull;
    setup_.front_face = options.front_face;

    targets_ = blank_targets(options);
    const std::uint8_t bg[4] = {to_unorm8(options.background.x), to_unorm8(options.background.y),
                                to_unorm8(options.background.z), 255};
    for (std::size_t i = 0; i < targets_.color.size(); i += 4)
        std::copy(bg, bg + 4, &targets_.color[i]);
    const bool alpha = shade_from != nullptr && scene_has_alpha(*shade_from, options);
    if (shade_from != nullptr && (options.color_target || options.normal_target || alpha))
        shading_ = std::make_unique<Shading>(*shade_from, options);
    if (alpha) blended_pixels_.assign(std::size_t(options.width) * std::size_t(options.height), 0);
    if (alpha && options.color_target) {
        over_.resize(targets_.color.size() / 4);
        for (std::size_t p = 0; p < over_.size(); ++p)
            for (int c = 0; c < 3; ++c) over_[p][c] = unorm8_to_float(bg[c]);
    }
}

Canvas::~Canvas() = default;

void Canvas::prepare(const ScreenPolygon& polygon, std::vector<TriangleSetup>& fans) const {
    fans.clear();
    const auto& v = polygon.vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
        TriangleSetup setup;
        if (setup_triangle({v[0].clip, v[k].clip, v[k + 1].clip}, setup_, setup) ==
            SetupResult::Visible)
            fans.push_back(setup);
    }
}

void Canvas::fill(const ScreenPolygon& polygon, std::span<const TriangleSetup> fans,
                  const SurfaceShader::Prepared* shading, int x0, int y0, int x1, int y1) {
    const int width = options_.width;
    std::uint8_t rgba[4] = {0, 0, 0, 255};
    if (options_.color_target)
        for (int c = 0; c < 3; ++c) rgba[c] = to_unorm8(polygon.color[c]);
    // The material's alpha: constant over the polygon, or sampled per pixel.
    const AlphaMode mode = alpha_mode(polygon);
    const SurfaceShader* shader = shading_ ? &shading_->shader : nullptr;
    const bool varies =
        mode != AlphaMode::Opaque && shading != nullptr && shader->alpha_varies(polygon.instance);
    float constant = 1.0f;
    if (mode != AlphaMode::Opaque && !varies) {
        constant = shader->constant_alpha(polygon.instance);
        if (mode == AlphaMode::Blend) constant = unit_clamp_alpha(constant);
    }
    for (const TriangleSetup& t : fans) {
        for_each_covered_pixel(t, x0, y0, x1, y1, [&](int px, int py) {
            const std::size_t p = std::size_t(py) * std::size_t(width) + std::size_t(px);
            float alpha = constant;
            if (varies) alpha = shader->alpha(*shading, px, py, true, 0.0, 0.0);
            if (mode == AlphaMode::Mask && !shader->passes_alpha_test(polygon.instance, alpha)) {
                ++alpha_discarded_;
                return;
            }
            if (mode == AlphaMode::Blend) {
                alpha = unit_clamp_alpha(alpha);
                if (alpha == 0.0f) return;
                ++fragments_;
                ++blended_;
                pixels_blended_ += blended_pixels_[p] == 0;
                blended_pixels_[p] = 1;
                if (!options_.color_target || shading == nullptr) return;
                // render()'s blend pass: the shaded color quantized, composited in float.
                const Shaded shaded = shader->shade(*shading, px, py, true, 0.0, 0.0, false);
                glm::vec3& c = over_[p];
                const float keep = 1.0f - alpha;
                for (int k = 0; k < 3; ++k) {
                    const float color = unorm8_to_float(to_unorm8(shaded.color[k]));
                    c[k] = color * alpha + c[k] * keep;
                    targets_.color[p * 4 + std::size_t(k)] = detail::blend_unorm8(c[k]);
                }
                return;
            }
            ++fragments_;
            targets_.depth[p] = depth_at(t, px, py);
            glm::vec3 normal = polygon.normal;
            if (shading != nullptr) {
                const Shaded shaded =
                    shader->shade(*shading, px, py, true, 0.0, 0.0, options_.normal_target);
                for (int c = 0; c < 3; ++c) rgba[c] = to_unorm8(shaded.color[c]);
                normal = shaded.normal;
            }
            if (options_.color_target) {
                std::copy(rgba, rgba + 4, &targets_.color[p * 4]);
                if (!over_.empty())
                    for (int c = 0; c < 3; ++c) over_[p][c] = unorm8_to_float(rgba[c]);
            }
            if (options_.id_targets) {
                targets_.instance_id[p] = polygon.instance;
                targets_.primitive_id[p] = polygon.primitive;
            }
            if (options_.normal_target) targets_.normal[p] = normal;
        });
    }
}

const SurfaceShader::Prepared& Canvas::kept(const ScreenPolygon& polygon) {
    auto [at, added] = shading_->kept.try_emplace(&polygon);
    if (added) shading_->shader.prepare(polygon, at->second);
    return at->second;
}

void Canvas::draw(const ScreenPolygon& polygon, std::span<const TriangleSetup> fans, int x0, int y0,
                  int x1, int y1) {
    fill(polygon, fans, shading_ ? &kept(polygon) : nullptr, x0, y0, x1, y1);
}

void Canvas::draw(const ScreenPolygon& polygon) {
    prepare(polygon, scratch_);
    const SurfaceShader::Prepared* prepared = nullptr;
    if (shading_) {
        shading_->shader.prepare(polygon, shading_->scratch);
        prepared = &shading_->scratch;
    }
    fill(polygon, scratch_, prepared, 0, 0, options_.width, options_.height);
}

AlphaMode Canvas::alpha_mode(const ScreenPolygon& polygon) const {
    return shading_ ? shading_->shader.alpha_mode(polygon.instance) : AlphaMode::Opaque;
}

bool Canvas::hides_at(const ScreenPolygon& polygon, int px, int py) {
    switch (alpha_mode(polygon)) {
        case AlphaMode::Opaque:
            return true;
        case AlphaMode::Blend:
            return false;
        case AlphaMode::Mask:
            break;
    }
    const SurfaceShader& shader = shading_->shader;
    const float alpha = shader.alpha_varies(polygon.instance)
                            ? shader.alpha(kept(polygon), px, py, true, 0.0, 0.0)
                            : shader.constant_alpha(polygon.instance);
    return shader.passes_alpha_test(polygon.instance, alpha);
}

void Canvas::count_fragments(RenderStats& stats) const {
    stats.fragments_shaded = fragments_;
    stats.fragments_alpha_discarded = alpha_discarded_;
    stats.fragments_blended = blended_;
    stats.pixels_blended = pixels_blended_;
}

RenderTargets Canvas::take() {
    return std::move(targets_);
}

}  // namespace visibility_detail

RenderTargets paint_polygons(std::span<const ScreenPolygon> back_to_front,
                             const RenderOptions& options, const Camera& camera,
                             const Scene* shade_from) {
    visibility_detail::Canvas canvas(options, camera, shade_from);
    for (const ScreenPolygon& polygon : back_to_front) canvas.draw(polygon);
    return canvas.take();
}

}  // namespace zraster
