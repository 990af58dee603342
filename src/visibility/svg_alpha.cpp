// See svg_alpha.hpp.
//
// Cost: nothing for scenes without transparent materials; else one alpha evaluation per pixel
// center covered by a polygon whose alpha is textured (as a raster frame of those polygons).
#include "visibility/svg_alpha.hpp"

#include <zraster/raster.hpp>

#include <algorithm>

#include "visibility/frame_context.hpp"
#include "visibility/surface_shader.hpp"

namespace zraster::visibility_detail {
namespace {

float clamp_unit(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // (NaN: 0), as render()'s blend pass
}

// The pixel centers the polygon covers (its fan triangles through setup_triangle, as the canvas
// fills them), with the alpha there.
struct PixelAlpha {
    int y, x;
    float alpha;
    bool operator<(const PixelAlpha& o) const { return y != o.y ? y < o.y : x < o.x; }
};

void pixel_alphas(const FrameContext& frame, const SurfaceShader& shader,
                  const SurfaceShader::Prepared& prepared, const ScreenPolygon& polygon,
                  std::vector<PixelAlpha>& out) {
    out.clear();
    const auto& v = polygon.vertices;
    const Viewport& viewport = frame.setup_settings.viewport;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
        TriangleSetup setup;
        if (setup_triangle({v[0].clip, v[k].clip, v[k + 1].clip}, frame.setup_settings, setup) !=
            SetupResult::Visible)
            continue;
        for_each_covered_pixel(setup, 0, 0, viewport.width, viewport.height, [&](int px, int py) {
            out.push_back({py, px, shader.alpha(prepared, px, py, true, 0.0, 0.0)});
        });
    }
}

glm::dvec2 centroid_of(const ScreenPolygon& polygon) {
    glm::dvec2 c{0.0};
    for (const PolygonVertex& v : polygon.vertices) c += glm::dvec2(v.window);
    return c / double(polygon.vertices.size());
}

}  // namespace

std::vector<SvgPolygonAlpha> svg_polygon_alphas(const Scene& scene, const RenderOptions& options,
                                                std::span<const ScreenPolygon> polygons) {
    std::vector<SvgPolygonAlpha> out(polygons.size());
    if (!scene_has_alpha(scene, options)) return out;
    const FrameContext frame = make_frame_context(scene, options);
    const SurfaceShader shader(frame);
    SurfaceShader::Prepared prepared;
    std::vector<PixelAlpha> pixels;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        const ScreenPolygon& polygon = polygons[i];
        SvgPolygonAlpha& a = out[i];
        const AlphaMode mode = shader.alpha_mode(polygon.instance);
        if (mode == AlphaMode::Opaque) continue;
        // One alpha for the whole polygon: kept or dropped (Mask), or its opacity (Blend).
        const auto whole = [&](float alpha) {
            if (mode == AlphaMode::Mask)
                a.shown = shader.passes_alpha_test(polygon.instance, alpha);
            else
                a.opacity = clamp_unit(alpha);
            a.shown = a.shown && a.opacity > 0.0f;
        };
        if (!shader.alpha_varies(polygon.instance)) {
            whole(shader.constant_alpha(polygon.instance));
            continue;
        }
        shader.prepare(polygon, prepared);
        pixel_alphas(frame, shader, prepared, polygon, pixels);
        if (pixels.empty()) {  // covers no pixel center: its alpha at the centroid
            const glm::dvec2 c = centroid_of(polygon);
            whole(shader.alpha(prepared, 0, 0, false, c.x, c.y));
            continue;
        }
        if (mode == AlphaMode::Blend) {
            double sum = 0.0;
            for (const PixelAlpha& p : pixels) sum += clamp_unit(p.alpha);
            a.opacity = float(sum / double(pixels.size()));
            a.shown = a.opacity > 0.0f;
            continue;
        }
        std::sort(pixels.begin(), pixels.end());
        std::size_t passed = 0;
        for (const PixelAlpha& p : pixels) {
            if (!shader.passes_alpha_test(polygon.instance, p.alpha)) continue;
            ++passed;
            if (!a.kept_runs.empty() && a.kept_runs.back()[0] == p.y &&
                a.kept_runs.back()[2] == p.x)
                ++a.kept_runs.back()[2];
            else
                a.kept_runs.push_back({p.y, p.x, p.x + 1});
        }
        if (passed == pixels.size()) a.kept_runs.clear();  // kept everywhere: a plain fill
        a.shown = passed > 0;
    }
    return out;
}

}  // namespace zraster::visibility_detail
