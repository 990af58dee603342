// Debug views: pictures of what the pipeline did instead of the shaded image, for the command
// (--view NAME), the viewer (key d) and the library (RenderOptions::view). Each replaces the
// color target; depth, normals and ids are produced as usual. With DebugView::None (the default)
// the renderer does none of the bookkeeping and the images are those of a build without views.
#pragma once
#include <zraster/export.hpp>

#include <optional>
#include <span>
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

}  // namespace zraster
