// Materials' alpha in SVG output: what each polygon of the paint order becomes (svg.hpp).
//
// An SVG fill holds one color and one opacity, while a textured material's alpha varies over the
// polygon. What the writer does, per the polygon's mode this frame (effective_alpha_mode):
//   - Opaque: a plain fill.
//   - Blend: fill-opacity = the alpha, clamped to [0, 1]: the material's opacity when it has no
//     alpha texture, else the mean of the alpha render() samples at the pixel centers the polygon
//     covers (at its centroid when it covers none). Painted back to front, the blend is the
//     raster paths' wherever the alpha is constant. A polygon whose alpha is 0 is left out.
//   - Mask without alpha textures: kept whole (opaque) or left out whole, by the cutoff.
//   - Mask with alpha textures: the alpha test at the pixel centers the polygon covers, as
//     render() makes it; kept everywhere: a plain fill; nowhere: left out; else the fill is
//     clipped (clip-path) to the pixel squares whose centers pass, as runs of pixels per row: the
//     cut-out is the raster paths' at pixel resolution, with pixel-stair edges where it cuts.
#pragma once
#include <zraster/render.hpp>
#include <zraster/visibility.hpp>

#include <array>
#include <span>
#include <vector>

namespace zraster::visibility_detail {

struct SvgPolygonAlpha {
    bool shown = true;     // false: left out
    float opacity = 1.0f;  // fill-opacity (1: opaque)
    // Mask with alpha textures, cut somewhere: the kept pixels as runs {y, x0, x1} (pixels
    // [x0, x1) of row y), rows in order; empty: not clipped.
    std::vector<std::array<int, 3>> kept_runs;
    bool plain() const { return opacity == 1.0f && kept_runs.empty(); }
};

// One entry per polygon (the paint order of svg_polygons, projected from `scene`).
std::vector<SvgPolygonAlpha> svg_polygon_alphas(const Scene& scene, const RenderOptions& options,
                                                std::span<const ScreenPolygon> polygons);

}  // namespace zraster::visibility_detail
