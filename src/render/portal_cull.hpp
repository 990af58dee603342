// Portal culling at run time (Luebke & Georges 1995, "Portals and Mirrors: Simple, Fast
// Evaluation of Potentially Visible Sets"): from the eye's cell, the portals are walked depth
// first and the view narrowed at each one, as a convex region of the image plane (normalized
// device coordinates), either to rectangles (their cull boxes) or to the clipped portal
// polygons (the exact variant). An instance is kept when its world box is not outside the
// narrowed view (the region's edges as planes through the eye, with the near and far planes)
// of some entry into one of its cells.
//
// Why it is exact: a pixel's visible point P lies in some cell Ck that lists its instance
// (validate_cell_graph). The segment from the eye to P crosses convex cells, each once, and
// leaves each one through a portal (anywhere else its boundary is opaque and would hide P), so
// the walk enters Ck along that portal sequence with a region holding P's pixel. Regions are
// grown by a pixel (kPortalMarginPixels) around each projected portal, which covers vertex
// snapping (1/256 pixel) and float rounding; a portal within the near distance of the eye
// (standing in a doorway) does not narrow the view at all.
#pragma once
#include <zraster/bounds.hpp>
#include <zraster/camera.hpp>
#include <zraster/portals.hpp>
#include <zraster/render.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zraster::detail {

inline constexpr double kPortalMarginPixels = 1.0;

struct PortalWalkInput {
    const CellGraph* graph = nullptr;
    PortalCull mode = PortalCull::Off;
    Camera camera;
    glm::mat4 view_projection{1.0f};  // the frame's (what the vertex stage transforms with)
    int width = 1, height = 1;
    std::span<const Bounds3f> world_boxes;  // per scene instance
};

// The walk's working memory (kept from frame to frame) and its result.
struct PortalWalk {
    std::vector<std::uint8_t> kept;  // per scene instance: 1 when it may be seen
    PortalOutcome outcome = PortalOutcome::NotRun;
    std::int64_t camera_cell = -1;
    std::uint64_t cells_visited = 0, visits = 0, pvs_cells = 0;
    double ms = 0.0;

    struct Visit {
        std::uint32_t cell = 0, first_plane = 0, plane_count = 0;
    };
    std::vector<Visit> visit_list;
    std::vector<glm::vec4> planes;                 // the visits' planes, world space
    std::vector<std::vector<glm::dvec2>> regions;  // per depth, counter-clockwise
    std::vector<std::uint8_t> on_path, reached, allowed;
    std::vector<glm::dvec3> clipped, scratch3;
    std::vector<glm::dvec2> scratch2;
};

// Decides walk.kept for `input` (outcome Culled); with another outcome every instance is kept.
void walk_portals(const PortalWalkInput& input, PortalWalk& walk);

}  // namespace zraster::detail
