// Debug views: pictures of what the pipeline did instead of the shaded image, for the command
// (--view NAME), the viewer (key d) and the library (RenderOptions::view). Each replaces the
// color target; depth, normals and ids are produced as usual. With DebugView::None (the default)
// the renderer does none of the bookkeeping and the images are those of a build without views.
#pragma once
#include <zraster/export.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace zraster {

enum class DebugView {
    None,
    Depth,      // linearized eye depth, color-mapped near (bright) to far (dark)
    Normals,    // world-space shading normal, n * 0.5 + 0.5
    Overdraw,   // fragments depth-tested per pixel, heat map
    HiZ,        // 8x8 blocks skipped by hierarchical z (triangle x block counts)
    Tiles,      // triangles binned per tile
    Ids,        // instance and triangle false colors
    Backfaces,  // back-facing visible surfaces tinted
    Clipped,    // visible triangles that went through the homogeneous clipper
    ZFight,     // pixels whose visible surface differs from an exact-depth reference
    Mip,        // texture mip level sampled
};

// Every view in key order (None first): what the viewer's d key cycles through.
ZRASTER_API std::span<const DebugView> debug_views();
// "none", "depth", "normals", "overdraw", "hiz", "tiles", "ids", "backfaces", "clipped",
// "zfight", "mip".
ZRASTER_API std::string_view debug_view_name(DebugView view);
// The view of a name above ("lod" is accepted for "mip"); nullopt for anything else.
ZRASTER_API std::optional<DebugView> parse_debug_view(std::string_view name);
// "none, depth, normals, ...": the names, for messages listing them.
ZRASTER_API std::string debug_view_names();

// The values at the ends of a frame's color scale (RenderStats::view_scale), for its legend:
// depth: eye distances (near, far); overdraw, hiz, tiles: counts (1, largest); zfight: the
// pixels marked (high); mip: levels (0, finest-to-coarsest span). Zero for the other views.
struct DebugViewScale {
    double low = 0.0, high = 0.0;
};

// The color scale the views map numbers to: t in [0, 1] from dark blue through purple and
// orange to yellow (matplotlib's "plasma", five stops), RGB 0..255. Black is kept for "none".
ZRASTER_API std::array<std::uint8_t, 3> debug_view_scale_color(double t);

// One line saying what a view's colors mean, with its scale's values: what the command prints
// and draws beside the color bar, and the viewer shows in its HUD.
ZRASTER_API std::string debug_view_legend(DebugView view, const DebugViewScale& scale);
// Whether the view maps a number to debug_view_scale_color (a color bar explains it).
ZRASTER_API bool debug_view_has_scale(DebugView view);

}  // namespace zraster
