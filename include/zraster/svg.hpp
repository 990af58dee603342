// Hidden-surface-removed vector drawings: a frame as an SVG 1.1 document of filled polygons,
// painted back to front in the order of the BSP tree or the painter's algorithm
// (src/visibility/svg_writer.cpp).
//
// The polygons are exactly those the BSP / painter's frames fill (render_with_visibility with
// VisibilityAlgorithm::Bsp or Painter): same camera, clipping, culling and snapping. A fill holds
// one color: a flat-shaded face has render()'s flat color (options.shading Unlit: the material's
// base color); a Gouraud, Phong or textured one is shaded by the renderer's shading core at the
// piece's centroid, with the same lights, interpolation and texture filtering. Coordinates are
// window pixels, y down, as SVG's user space; width, height and viewBox are the image size.
//
// Materials' alpha (options.alpha_mode Auto; src/visibility/svg_alpha.hpp): a blended polygon
// is painted with fill-opacity (its material's opacity, or with alpha textures the mean alpha at
// the pixel centers it covers) and no seam stroke; a Mask polygon is kept whole, left out, or
// with alpha textures clipped (clip-path) to the pixel squares whose centers pass the test.
// Such polygons are never merged or grouped with others.
//
// Cracks: anti-aliased SVG renderers leave hairline seams between adjacent filled polygons. Each
// polygon is therefore also stroked with its own fill color (SvgOptions::seam_width, round
// joins); since everything is painted back to front, nearer polygons cover the strokes of
// farther ones.
//
// Edges (SvgOptions::edges): the sides of each outline that lie on edges of the mesh are stroked
// with edge_color (decided exactly from PolygonVertex::weights: BSP and painter's split lines, fan
// diagonals and clipping lines are not drawn): an outline made of mesh edges only is one element
// whose stroke is the edges (it covers the seams too); any other is its fill (with its seam
// stroke) followed by a path of its mesh-edge sides. Hidden edges are covered by nearer polygons
// because of the paint order.
//
// Merging (SvgOptions::merge_coplanar): a polygon with the same 8-bit fill as an outline up to
// merge_lookback places back in the paint order, lying in its plane (with edges on; without edges
// outlines are not drawn and the plane test is skipped), sharing exactly one side with it (same
// snapped end points, no other common vertex), is joined to it into one outline (the union of
// the two vertex loops) when no outline painted in between overlaps it (exact separating-axis
// test on the snapped coordinates): moving it back in the order then paints the same. The search
// goes back from the last outline and stops at the first one that overlaps the polygon.
// Without edges, runs of consecutive paths of one color are further written as one <path> with
// several subpaths (all loops have the same orientation, so the nonzero rule unions them).
#pragma once
#include <zraster/export.hpp>
#include <zraster/render.hpp>
#include <zraster/visibility.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace zraster {

struct SvgOptions {
    enum class Order { Bsp, Painter };
    Order order = Order::Bsp;
    // Stroke the visible mesh edges with edge_color (see above).
    bool edges = false;
    float edge_width = 0.5f;     // pixels
    glm::vec3 edge_color{0.0f};  // 0..1
    bool merge_coplanar = true;
    // How far back in the paint order a polygon may look for an outline to join (1: only the
    // outline just before it). Each step costs an overlap test against that outline's pieces.
    std::size_t merge_lookback = 256;
    int precision = 2;        // decimal places of coordinates, 0..6
    float seam_width = 0.5f;  // pixels; 0: no seam strokes (hairline cracks show)
};

struct SvgStats {
    std::size_t polygons_in = 0;   // polygons in the paint order (clipped and split pieces)
    std::size_t polygons_out = 0;  // after merging
    std::size_t paths = 0;         // <path> elements, edge paths included
    std::size_t edge_paths = 0;    // of which draw edges (an all-edge outline, or edge sides)
    std::size_t bytes = 0;         // size of the document
};

// The polygons in paint order (back to front), before merging: for the BSP order, the tree's
// walk for the frame's eye with each stored polygon projected fan triangle by fan triangle as
// render_bsp draws it; for the painter's order, painter_sort over project_scene. Filled with
// paint_polygons they give render_with_visibility's image for that algorithm. ScreenPolygon::color
// is the fill (above).
ZRASTER_API std::vector<ScreenPolygon> svg_polygons(const Scene& scene,
                                                    const RenderOptions& options,
                                                    SvgOptions::Order order);

// The document. Throws InputError for unusable options (as render_with_visibility, and a
// precision outside 0..6 or a negative or non-finite width).
std::string render_svg(const Scene& scene, const RenderOptions& options,
                       const SvgOptions& svg_options = {}, SvgStats* stats = nullptr);

}  // namespace zraster
