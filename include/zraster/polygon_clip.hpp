// Polygon clipping with the Sutherland-Hodgman algorithm (Sutherland & Hodgman 1974, "Reentrant
// polygon clipping"): in 2D against a convex window, and in homogeneous clip space against any
// set of planes (there it is a loop over clip_polygon_against_plane of clip.hpp).
//
// The subject polygon may be concave (simple or not); the window must be convex. When a concave
// polygon's intersection with the window has several pieces, Sutherland-Hodgman still returns ONE
// polygon: the pieces are joined by zero-width "bridges" running back and forth along the window
// boundary. Its signed area (shoelace formula) is still exactly the area of the intersection, and
// it rasterizes to the same pixels under any consistent fill rule, since the bridge edges cancel;
// what it is not is a simple polygon, so split it first if that matters (e.g. for outlines).
#pragma once
#include <zraster/clip.hpp>
#include <zraster/export.hpp>
#include <zraster/line_clip.hpp>

#include <glm/glm.hpp>

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace zraster {

// Clips `polygon` (either orientation, output in the same one) against the convex window.
// Vertices on the boundary are inside. Intersections on an axis-aligned window edge get the
// boundary coordinate exactly. Returns an empty vector when fewer than 3 vertices remain (the
// polygon misses the window or only touches it).
// Cost: O(polygon vertices x window edges).
ZRASTER_API std::vector<glm::dvec2> clip_polygon_sutherland_hodgman(
    std::span<const glm::dvec2> polygon, const ConvexWindow& window);

// The six planes of the view volume (keep dot(plane, v) >= 0), in ClipPlaneBit order.
inline std::array<glm::vec4, 6> view_volume_planes(ClipDepthRange range) {
    return {range == ClipDepthRange::ZeroToOne ? glm::vec4(0, 0, 1, 0) : glm::vec4(0, 0, 1, 1),
            glm::vec4(0, 0, -1, 1),
            glm::vec4(1, 0, 0, 1),
            glm::vec4(-1, 0, 0, 1),
            glm::vec4(0, 1, 0, 1),
            glm::vec4(0, -1, 0, 1)};
}

// Clips a polygon in homogeneous coordinates against each plane in turn. ClipVertex::weights are
// carried along linearly, whatever they mean to the caller.
inline std::vector<ClipVertex> clip_polygon_homogeneous(std::span<const ClipVertex> polygon,
                                                        std::span<const glm::vec4> planes) {
    std::vector<ClipVertex> current(polygon.begin(), polygon.end()), next;
    for (const glm::vec4& plane : planes) {
        if (current.empty()) break;
        // One plane turns n vertices into at most 3n/2 when the polygon is concave (I inside
        // vertices plus at most 2 min(I, n - I) crossings), n + 1 when it is convex.
        next.resize(max_clip_output(current.size()));
        next.resize(static_cast<std::size_t>(clip_polygon_against_plane(current, plane, next)));
        std::swap(current, next);
    }
    return current;
}

}  // namespace zraster
