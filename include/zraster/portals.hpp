// Cell graphs for portal culling, after Luebke & Georges 1995, "Portals and Mirrors: Simple,
// Fast Evaluation of Potentially Visible Sets", and precomputed potentially visible sets (PVS).
//
// A scene's space is cut into convex cells (rooms, doorway tunnels) joined by portals (convex
// polygons: doorways, windows). Each cell lists the scene instances that lie in it. The contract
// that makes culling exact: everything a cell's boundary holds outside its portals is covered by
// opaque geometry (walls, floors), so that a ray leaving a cell anywhere but through a portal is
// stopped. docs/portals.md has the walk, the file format and the guarantees.
#pragma once
#include <zraster/bounds.hpp>
#include <zraster/export.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace zraster {

// A convex volume: the points p with dot(n, p) + d >= 0 for every plane (n, d) (n pointing
// inward), and its corners (found from the planes).
struct CellVolume {
    std::vector<glm::dvec4> planes;
    std::vector<glm::dvec3> corners;
    glm::dvec3 lo{0.0}, hi{0.0};  // the corners' bounding box
};

// The box [lo, hi] as a volume (lo < hi on every axis).
ZRASTER_API CellVolume box_volume(const glm::dvec3& lo, const glm::dvec3& hi);
// The intersection of the half-spaces; throws InputError("", cause) when it is empty, flat or
// unbounded, or when a plane's normal is zero or not finite.
ZRASTER_API CellVolume convex_volume(std::span<const glm::dvec4> planes);

struct Cell {
    std::string name;
    CellVolume volume;
    std::vector<std::uint32_t> instances;  // indices into the scene's instances
};

// A convex planar polygon joining two cells, its corners in order (either winding).
struct Portal {
    std::array<std::uint32_t, 2> cells{};
    std::vector<glm::dvec3> corners;
};

// Bounds on what a cell graph may hold (a file past them is refused) and on the run-time walk.
struct CellGraphLimits {
    std::size_t max_cells = 1'000'000;
    std::size_t max_portals = 4'000'000;
    std::size_t max_portal_corners = 64;
    std::size_t max_cell_planes = 64;
    // The walk enters a cell once per portal sequence that reaches it (Luebke & Georges revisit
    // cells): past this many entries in a frame, or this many portals deep, it stops and the
    // frame is drawn without portal culling (RenderStats says so).
    std::size_t max_walk_visits = 65'536;
    std::size_t max_walk_depth = 256;
};

struct CellGraph {
    std::vector<Cell> cells;
    std::vector<Portal> portals;
    CellGraphLimits limits;

    // Derived by validate_cell_graph: the portals of each cell, and the cells of each instance.
    std::vector<std::vector<std::uint32_t>> cell_portals;
    std::vector<std::vector<std::uint32_t>> instance_cells;

    // Optional precomputed potentially visible sets (compute_pvs): pvs[c] lists, sorted, the
    // cells that may be seen from anywhere in cell c (c included). When present, the renderer
    // skips every instance none of whose cells is in the camera cell's set, and its portal walk
    // enters only those cells. Empty: none.
    std::vector<std::vector<std::uint32_t>> pvs;
};

// Distances below this (world units, relative to the graph's extent: tolerance_scale) count as
// zero in the checks: planarity, a point in a cell, an instance touching a cell.
inline constexpr double kCellTolerance = 1e-6;
// kCellTolerance times the largest coordinate magnitude of the cells' corners (at least 1).
ZRASTER_API double cell_tolerance(const CellGraph& graph);

// Checks the graph against the scene it belongs to and derives cell_portals and instance_cells.
// `instance_boxes` are the scene instances' world bounds, `instance_names` their names (for
// messages; may be empty). Refused, with an InputError(source, cause) naming the element as the
// cells.json file does ("portals[2]: ...", "cells[1] 'hall': ..."):
//  - counts past graph.limits; a cell or portal naming a missing instance or cell; a portal
//    joining a cell to itself; a portal of fewer than 3 corners, not planar, not convex, of no
//    area, or not on the boundary of both its cells; non-finite numbers;
//  - an instance in no cell, and an instance whose world box touches a cell that does not list
//    it (culling is exact only if every cell an instance reaches lists it).
ZRASTER_API void validate_cell_graph(CellGraph& graph, std::span<const Bounds3f> instance_boxes,
                                     std::span<const std::string> instance_names,
                                     const std::string& source);

// The first cell whose volume holds p (within cell_tolerance), or -1.
ZRASTER_API std::int64_t find_cell(const CellGraph& graph, const glm::dvec3& p);

// Potentially visible sets by portal sequences (compute_pvs): for each cell S, every cell C that
// a line from a point of S can reach by passing through a sequence of portals. A sequence
// S -p1-> C1 -p2-> ... -pk-> Ck is followed while a stabbing line may exist: each next portal is
// clipped to the far side of p1's and the last portal's planes and to the separating planes of
// p1 and the last portal (planes through an edge of one and a corner of the other with the two
// on opposite sides: a line through both stays on the last portal's side of them beyond it).
// Clipping only removes points no such line passes, and the planes are moved outward by
// `slack`, so the sets are conservative: they never miss a visible cell (and may hold cells no
// line reaches). Past max_steps_per_cell portal steps from one cell, that cell's set becomes
// every cell its portals connect it to (conservative too) and bounded[cell] is set.
struct PvsOptions {
    double slack = 1e-3;  // world units
    std::size_t max_steps_per_cell = 200'000;
};
struct PotentiallyVisibleSets {
    std::vector<std::vector<std::uint32_t>> visible;  // per cell, sorted, itself included
    std::vector<std::uint8_t> bounded;                // per cell: 1 when the step bound was hit
    std::uint64_t steps = 0;                          // portal steps over all cells
};
// `graph` must have been validated (validate_cell_graph).
ZRASTER_API PotentiallyVisibleSets compute_pvs(const CellGraph& graph,
                                               const PvsOptions& options = {});

}  // namespace zraster
