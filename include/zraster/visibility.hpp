// Visible-surface determination besides the z-buffer: the classic algorithms of the 1970s survey
// (Sutherland, Sproull & Schumacker 1974, "A characterization of ten hidden-surface algorithms").
//
//   - Painter's algorithm with Newell, Newell & Sancha's overlap tests (1972): a depth order of
//     screen polygons, splitting them where no order exists (cyclic overlap, interpenetration).
//   - BSP tree (Fuchs, Kedem & Naylor 1980): a world-space partition built once for a static
//     scene; an in-order walk gives a back-to-front order for any viewpoint.
//   - Warnock's area subdivision (1969): recursive screen subdivision until each region is simple.
//
// All of them start from the same geometry as the z-buffer renderer (same camera, same
// homogeneous clipping, same back-face culling, same snapping and top-left fill rule), so their
// primitive-id images agree with render()'s except where visibility is decided differently (ties,
// and pixels whose centers lie within rounding of an intersection or split line).
#pragma once
#include <zraster/export.hpp>
#include <zraster/render.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace zraster {

// ---------------------------------------------------------------------------------------------
// Common input: polygons after clipping and projection.

struct PolygonVertex {
    // x, y in pixels, y down, pixel centers at +0.5: the position the rasterizer snaps `clip` to
    // (to_screen), i.e. snapped / kSubpixelScale. z = window depth in [0, 1] (double), always 0 at
    // near and 1 at far (for a reversed-Z camera it is 1 - the stored depth), so every algorithm
    // can treat larger z as farther.
    glm::dvec3 window{0.0};
    // x, y on the rasterizer's fixed-point grid (1/kSubpixelScale pixel): the exact coordinates
    // coverage is decided on.
    std::array<std::int64_t, 2> snapped{};
    glm::vec4 clip{0.0f};   // clip-space position: what setup_triangle rasterizes
    glm::dvec3 world{0.0};  // world-space position
    // Barycentric weights of this point in its source scene triangle (vertex order of the mesh's
    // indices): any vertex attribute is sum(weights[i] * attribute[i]). A weight is exactly 0
    // on the source triangle's edge opposite that corner, through clipping and splitting, so an
    // edge of the polygon lies on an edge of the mesh iff both its ends have a zero weight in
    // common.
    glm::vec3 weights{0.0f};
};

// A convex polygon: a scene triangle after homogeneous clipping (or a piece of one after a split).
struct ScreenPolygon {
    std::vector<PolygonVertex> vertices;  // >= 3, convex, in the source triangle's winding
    // World-space plane of the source triangle: unit normal n and d with dot(n, p) + d = 0,
    // oriented so that the viewer is on the positive side (dot(n, p) + d > 0 between the polygon
    // and the eye). "P is behind Q's plane" is then: every vertex of P has distance <= 0.
    glm::dvec4 plane{0.0};
    std::int32_t instance = -1;   // index into Scene::instances
    std::int32_t primitive = -1;  // triangle index within its mesh
    glm::vec3 color{0.0f};        // flat-shaded color (0..1, before quantization)
    glm::vec3 normal{0.0f};       // world-space face normal as shaded (flipped for back faces)
    bool front_facing = true;
};

// The camera a frame uses: options.camera, else fit_camera() over the scene (as render() does).
ZRASTER_API Camera effective_camera(const Scene& scene, const RenderOptions& options);

// Runs the renderer's vertex stage math on every triangle of every instance: object -> clip space
// by Camera::view_projection, trivial reject by clip_outcode, clip_triangle against the near/far,
// guard-band and user planes, back-face culling per options.cull / options.front_face (decided on
// the snapped polygon, like setup_triangle; none for a double-sided material under
// options.material_sides). Triangles of zero snapped area or covering no pixel
// center are dropped. Each polygon is flat shaded once (evaluate_lighting at the triangle's
// centroid with its face normal, the material's base color, no texture): exactly the color
// render() gives with ShadingMode::Flat and textures off. Result in submission order.
// keep_subpixel: keep polygons that cover no pixel center but may cover points between them
// (those whose snapped bounding box meets the viewport): what the A-buffer's subsamples need;
// the list-priority algorithms and Warnock sample pixel centers only and leave it off.
// Throws InputError for an image size out of range or too many user clip planes, and
// LimitExceeded ("max_projected_polygons") as soon as more polygons than
// projected_polygon_budget(options.limits) are kept. options.progress hears of the triangles
// done (stage "projecting triangles").
ZRASTER_API std::vector<ScreenPolygon> project_scene(const Scene& scene,
                                                     const RenderOptions& options,
                                                     bool keep_subpixel = false);

// Draws polygons in the given order with NO depth test (the last one drawn wins), with the
// renderer's coverage rule: each polygon is fan-triangulated from its first vertex and every
// triangle goes through setup_triangle (options.cull, options.front_face) and
// for_each_covered_pixel. Produces the targets options asks for: color, depth (the drawn
// polygon's depth), id targets, normal. Coverage counts are not produced. Colors and normals:
// with shade_from (the scene the polygons were projected from) each pixel is shaded as render()
// shades it (options.shading, lighting, textures, interpolation; the same shading code), so an
// unsplit polygon's pixels get render()'s colors bit for bit; without, each polygon's flat color
// and face normal. Materials' alpha (with shade_from, options.alpha_mode Auto): a Mask polygon's
// pixels whose alpha (sampled as render() samples it) is under the cutoff are left alone; a Blend
// polygon's pixels are composited over what is there as render()'s blend pass composites, and
// write no depth, ids or normals. In back-to-front order that is render()'s image.
ZRASTER_API RenderTargets paint_polygons(std::span<const ScreenPolygon> back_to_front,
                                         const RenderOptions& options, const Camera& camera,
                                         const Scene* shade_from = nullptr);

// ---------------------------------------------------------------------------------------------
// Painter's algorithm (src/visibility/painter.cpp).

// Told of the sort's decisions, for pictures of it (zraster explain painter). Every callback is
// optional; with PainterOptions::observer null (the default) nothing is called.
struct PainterObserver {
    // The overlap tests failed and `moved` goes ahead of `of` (counted in PainterStats::swaps).
    std::function<void(const ScreenPolygon& moved, const ScreenPolygon& of)> swapped;
    // `polygon` is about to be split by `plane` (interpenetration, or to break a cycle).
    std::function<void(const ScreenPolygon& polygon, const glm::dvec4& plane)> split;
};

struct PainterOptions {
    // Plane-side tests count a vertex as on the plane within this fraction of the polygons'
    // world-space extent (absorbs float rounding of the input; it is not a tuning knob).
    double plane_epsilon = 1e-6;
    // Safety net: past this many splits, remaining conflicts are left unresolved (counted) rather
    // than split further. 0: 16 * polygons + 1024.
    std::size_t max_splits = 0;
    // Past this many comparisons the sort throws LimitExceeded ("max_painter_comparisons").
    // 0: painter_comparison_budget(RenderLimits{}, polygons).
    std::uint64_t max_comparisons = 0;
    ProgressReporter* progress = nullptr;       // stage "painter's algorithm"; not owned
    const PainterObserver* observer = nullptr;  // not owned
};

struct PainterStats {
    std::uint64_t comparisons = 0;   // (P, Q) pairs examined
    std::uint64_t swaps = 0;         // Q moved ahead of P
    std::uint64_t splits = 0;        // polygons split by another's plane
    std::uint64_t cycle_splits = 0;  // of which: forced by a cycle (Q already moved once)
    std::uint64_t unresolved = 0;    // conflicts left as they were after max_splits
    // Which test settled each comparison that did not need a swap or split:
    // [0] depth extents, [1] x extents, [2] y extents, [3] P behind Q's plane,
    // [4] Q in front of P's plane, [5] projections disjoint.
    std::array<std::uint64_t, 6> resolved_by{};
};

struct PainterResult {
    std::vector<ScreenPolygon> order;  // back to front; may contain split pieces
    PainterStats stats;
};

// Newell, Newell & Sancha: sort by farthest depth, then settle every pair whose depth ranges
// overlap with the tests in order (depth extents, x extents, y extents, P entirely behind Q's
// plane, Q entirely in front of P's plane, exact projection overlap). A Q that P may hide and that
// can go first is moved ahead of P and marked; a marked Q that must move again means a cycle, and
// two polygons that each cross the other's plane interpenetrate: both are resolved by splitting
// one polygon by the other's plane.
// `viewport` is the one the polygons were projected for: split vertices are projected into it
// exactly as the rasterizer will project them.
ZRASTER_API PainterResult painter_sort(std::vector<ScreenPolygon> polygons,
                                       const Viewport& viewport,
                                       const PainterOptions& options = {});

// The naive order the classic algorithm starts from: farthest depth first, nothing resolved.
// Wrong for cyclic overlap and interpenetration (kept for comparison).
ZRASTER_API std::vector<ScreenPolygon> sort_by_farthest_depth(std::vector<ScreenPolygon> polygons);

// ---------------------------------------------------------------------------------------------
// BSP tree (src/visibility/bsp_tree.cpp).

struct BspVertex {
    glm::dvec3 world{0.0};
    // Object-space position: frames project it with the instance's model-view-projection matrix
    // exactly as render() does, so unsplit triangles rasterize bit-identically.
    glm::vec3 object{0.0f};
    glm::vec3 weights{0.0f};  // in the source triangle, as PolygonVertex::weights
};

struct BspPolygon {
    std::vector<BspVertex> vertices;  // >= 3, convex, planar
    glm::dvec4 plane{0.0};            // unit normal along the winding, dot(n, p) + d = 0
    std::int32_t instance = -1;
    std::int32_t primitive = -1;
};

struct BspOptions {
    // Splitter candidates evaluated per node (spread evenly over the node's polygons); the one
    // minimizing splits + balance_weight * |front - back| is used. One split is worth an
    // imbalance of 8 polygons: on bunny-small, spot and a 2000-triangle soup this gave the fewest
    // splits of the weights 0..1 tried, with depths within 2x of the most balanced trees.
    int candidates = 12;
    double balance_weight = 0.125;
    // Deeper trees are refused with an InputError (the walk and the build use explicit stacks,
    // so depth is bounded by memory, not by the call stack).
    std::size_t max_depth = 10'000;
    double plane_epsilon = 1e-6;  // as PainterOptions::plane_epsilon
    // A pool (input and split pieces) growing past this many polygons throws LimitExceeded
    // ("max_bsp_polygons"). 0: bsp_polygon_budget(RenderLimits{}, input polygons).
    std::uint64_t max_polygons = 0;
    // Past this many polygon-plane classifications (scoring included) the build throws
    // LimitExceeded ("max_bsp_classifications"). 0: bsp_classification_budget(RenderLimits{},
    // input polygons).
    std::uint64_t max_classifications = 0;
    ProgressReporter* progress = nullptr;  // stage "BSP tree"; not owned
};

struct BspStats {
    std::size_t input_polygons = 0;
    std::size_t polygons = 0;  // stored, after splitting
    std::size_t nodes = 0;
    std::size_t depth = 0;              // levels: a single node has depth 1
    std::size_t splits = 0;             // polygons split in two
    std::uint64_t classifications = 0;  // polygon-vs-plane tests, scoring included
};

class ZRASTER_API BspTree {
  public:
    struct Node {
        glm::dvec4 plane{0.0};
        std::vector<std::uint32_t> polygons;  // into polygons(), coplanar with `plane`
        std::int32_t front = -1, back = -1;   // child nodes, -1 when empty
    };

    // Throws InputError when the tree would be deeper than options.max_depth.
    static BspTree build(std::vector<BspPolygon> polygons, const BspOptions& options = {});

    // Polygon indices, farthest first, for a viewer at `eye`: a point (w = 1) for perspective,
    // or the direction towards the viewer (w = 0) for an orthographic camera.
    std::vector<std::uint32_t> back_to_front(const glm::dvec4& eye) const;

    // The polygon pool: the input, then split pieces. A polygon that was split stays in the pool
    // but no node refers to it (indices never move).
    const std::vector<BspPolygon>& polygons() const { return polygons_; }
    const std::vector<Node>& nodes() const { return nodes_; }
    const BspStats& stats() const { return stats_; }

  private:
    std::vector<BspPolygon> polygons_;
    std::vector<Node> nodes_;  // nodes_[0] is the root when not empty
    BspStats stats_;
};

// Refuses (LimitExceeded, "max_bsp_polygons") a scene of more triangles than the tree's pool may
// hold (bsp_polygon_budget), before bsp_polygons_from_scene makes them (250 bytes each).
ZRASTER_API void check_bsp_budget(const Scene& scene, const RenderLimits& limits);

// Every triangle of every instance in world space (degenerate ones dropped), in submission order.
ZRASTER_API std::vector<BspPolygon> bsp_polygons_from_scene(const Scene& scene);

// The viewer as BspTree::back_to_front wants it.
ZRASTER_API glm::dvec4 bsp_eye(const Camera& camera);

// Draws a frame of `scene` through a prebuilt tree (built from bsp_polygons_from_scene(scene)):
// the walk's order through paint_polygons, shaded from the scene.
ZRASTER_API RenderResult render_bsp(const BspTree& tree, const Scene& scene,
                                    const RenderOptions& options);

// ---------------------------------------------------------------------------------------------
// Warnock's area subdivision (src/visibility/warnock.cpp).

// Pixels [x0, x1) x [y0, y1).
struct PixelRegion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

enum class RegionRelation {
    Disjoint,      // the polygon covers no pixel center of the region
    Intersecting,  // partly inside
    Contained,     // everything it covers is inside the region, and it does not surround it
    Surrounding,   // it covers every pixel center of the region
};

// Exact, on the snapped coordinates with the rasterizer's top-left rule; the region stands for its
// pixel centers (the only points the rasterizer samples). Disjoint: the polygon and the rectangle
// spanned by the region's pixel centers do not meet. Surrounding: all four corner centers are
// covered (then, by convexity, every center is).
ZRASTER_API RegionRelation classify_polygon(const ScreenPolygon& polygon,
                                            const PixelRegion& region);

struct WarnockStats {
    std::vector<std::uint64_t> regions_per_level;       // regions examined at each level
    std::vector<std::uint64_t> subdivisions_per_level;  // of which subdivided
    std::uint64_t empty_leaves = 0;                     // no polygon
    std::uint64_t single_leaves = 0;                    // one polygon, drawn clipped to the region
    std::uint64_t surrounded_leaves = 0;             // a surrounding polygon in front of all others
    std::uint64_t pixel_leaves = 0;                  // one pixel: nearest polygon at its center
    std::array<std::uint64_t, 4> classifications{};  // by RegionRelation
};

// What Warnock's algorithm decided for a region, for pictures of it (zraster explain warnock).
enum class WarnockRegionOutcome {
    Empty,       // no polygon: background
    Single,      // one polygon, drawn clipped to the region
    Surrounded,  // a surrounding polygon in front of all others
    Pixel,       // one pixel: the nearest polygon at its center
    Subdivided,  // too complex: split into four
};
struct WarnockObserver {
    std::function<void(const PixelRegion& region, std::size_t level, WarnockRegionOutcome)> region;
};

struct WarnockResult {
    RenderTargets targets;
    WarnockStats stats;
    // The fragment counts of RenderStats: fragments_shaded, fragments_alpha_discarded,
    // fragments_blended and pixels_blended (the rest unset).
    RenderStats fragments;
};

// Warnock's algorithm over the whole viewport. Depth comparisons use each polygon's plane in
// window space evaluated at pixel centers; equal depths go to the earlier polygon (as the
// z-buffer's LESS test keeps the first one drawn). Materials' alpha (with shade_from): only an
// opaque polygon can be a region's surrounding one; at a pixel the polygons covering it are
// composited in depth order over the nearest one that hides what is behind (opaque, or Mask
// passing the test there). More classifications than
// warnock_classification_budget(options.limits, ...) throw LimitExceeded
// ("max_warnock_classifications"); options.progress hears of the area done.
// `observer` (optional, not owned) hears of every region's outcome.
// shade_from: as for paint_polygons.
ZRASTER_API WarnockResult warnock_render(std::span<const ScreenPolygon> polygons,
                                         const RenderOptions& options, const Camera& camera,
                                         const WarnockObserver* observer = nullptr,
                                         const Scene* shade_from = nullptr);

// ---------------------------------------------------------------------------------------------
// Budgets (RenderLimits): the limit's value when set, else the automatic one for an input of
// this size (render_with_visibility and the SVG writer apply them).

ZRASTER_API std::uint64_t painter_comparison_budget(const RenderLimits& limits,
                                                    std::size_t polygons);
ZRASTER_API std::uint64_t bsp_polygon_budget(const RenderLimits& limits,
                                             std::size_t input_polygons);
ZRASTER_API std::uint64_t bsp_classification_budget(const RenderLimits& limits,
                                                    std::size_t input_polygons);
ZRASTER_API std::uint64_t projected_polygon_budget(const RenderLimits& limits);
ZRASTER_API std::uint64_t painted_fragment_budget(const RenderLimits& limits, int width,
                                                  int height);
ZRASTER_API std::uint64_t warnock_classification_budget(const RenderLimits& limits,
                                                        std::size_t polygons, int width,
                                                        int height);

// ---------------------------------------------------------------------------------------------

enum class VisibilityAlgorithm { ZBuffer, Painter, Bsp, Warnock };

struct VisibilityStats {
    PainterStats painter;
    BspStats bsp;
    WarnockStats warnock;
    std::size_t polygons = 0;  // after projection (painter, Warnock) or in the tree (BSP)
};

// One frame with the chosen algorithm. ZBuffer is render(); the other three decide visibility
// their own way and shade the visible pixels as render() does (the same options and shading
// code), so the four images differ only where the visible surface does (ties at shared edges,
// pixel centers within rounding of a split line). The other three run on one thread, always
// keep the nearest surface
// (options.depth_compare, depth_test and depth_write do not apply) and produce no coverage
// counts; Bsp builds its tree for this frame (use render_bsp to reuse one). Stats: camera,
// triangles_in and the total time are filled in.
ZRASTER_API RenderResult render_with_visibility(const Scene& scene, const RenderOptions& options,
                                                VisibilityAlgorithm algorithm,
                                                VisibilityStats* stats = nullptr);

}  // namespace zraster
