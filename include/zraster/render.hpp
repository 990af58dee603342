// The Renderer: one frame of a scene through the whole pipeline.
//
//   instances --frustum cull--> vertex stage --assemble/cull--> clip --> setup --> bin into
//   tiles --> per tile, in parallel: coverage, depth test, shading --> targets
//
// Tiles own their pixels and process their triangles in submission order, so the images are
// bit-identical for any thread count.
//
// Two entry points, one pipeline:
//  - render(const Scene&, options) and Renderer::render(const Scene&, options): an owning Scene
//    in, RenderTargets (std::vectors) out. The scene is viewed (view_of in mesh_view.hpp) and
//    the targets are the Renderer's own; nothing is copied.
//  - Renderer::render(const SceneView&, options, const TargetViews&): the caller's vertex and
//    index buffers in (mesh_view.hpp), the caller's images out (TargetViews: pointer and row
//    pitch each). Zero copy both ways; the images are bit for bit the owning path's.
//
// Ownership: views and target memory belong to the caller. They must stay valid (and the scene
// unchanged) for the duration of the call; the Renderer keeps nothing of them between calls
// except their addresses and sizes as cache keys (the bounds of RenderOptions::cluster_culling),
// checked against the data before use unless RenderOptions::static_meshes says they need not be.
//
// Threading: a Renderer draws one frame at a time (calls must not overlap); it runs the frame
// on its own oneTBB arena of options.threads threads. Different Renderers may run concurrently.
//
// Memory: a Renderer keeps its working memory from frame to frame. After the first frame of a
// given size, options and scene shape it makes no heap allocation.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/debug_view.hpp>
#include <zraster/depth_buffer.hpp>
#include <zraster/export.hpp>
#include <zraster/lighting.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/raster.hpp>
#include <zraster/scene.hpp>
#include <zraster/texture.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace zraster {

enum class ShadingStrategy {
    Auto,      // deferred: measured faster at any overdraw (docs/architecture.md)
    Forward,   // shade every fragment that passes the depth test, as it is drawn
    Deferred,  // resolve visibility per tile first, then shade each visible pixel once
};

// What materials' alpha does (Material::alpha_mode): as each material says (transparent and
// cut-out surfaces), or nothing (every surface opaque, as renderers without transparency draw).
enum class MaterialAlpha { Auto, Opaque };

// The order instances are drawn in.
enum class InstanceOrder {
    Submission,  // as in Scene::instances
    // Nearest first, by the distance from the eye to the instance's world bounding box (ties
    // in submission order): later instances then fail hierarchical z where earlier ones hide
    // them. The image differs from submission order only where two instances' surfaces meet
    // at exactly the same depth (the first drawn keeps the pixel under LESS).
    FrontToBack,
};

// Portal culling (RenderOptions::portal_cull), after Luebke & Georges 1995: the portals of the
// camera's cell are walked depth first, the view narrowed at each one, and instances outside
// every narrowed view of their cells are skipped (docs/portals.md).
enum class PortalCull {
    Off,
    // Luebke & Georges' cull boxes: the view narrowed to screen rectangles, the intersection of
    // the last one with each portal's projected bounding rectangle.
    Rectangles,
    // The exact variant: each portal polygon clipped against the current view and the view
    // narrowed to the clipped polygon (planes from the eye through its edges).
    Frustum,
};

// What a frame's portal culling did (RenderStats::portal_outcome).
enum class PortalOutcome {
    NotRun,         // portal_cull Off and no PVS, or no cell graph
    Culled,         // the walk (or the PVS) decided which instances are drawn
    CameraOutside,  // the eye is in no cell: nothing culled
    OverBound,      // the walk passed CellGraphLimits::max_walk_visits or max_walk_depth
    NotExact,       // the frame's settings could let hidden instances show: nothing culled
    // The near plane could cut open a wall of the camera's cell (the eye is closer to it than
    // the near plane's corners are), or the camera is orthographic: nothing culled.
    NearWall,
};

// Requests past these are refused by render() with an InputError before anything is allocated:
// they are mistakes or hostile input, not frames (see RELIABILITY.md). Raise them deliberately.
struct RenderLimits {
    // width * height. 64 Mpx is 8192 x 8192; with every target (color, depth, normal, ids,
    // coverage counts) a frame holds about 36 bytes per pixel, so 2.3 GB at the limit.
    std::uint64_t max_pixels = std::uint64_t{64} << 20;
    // Triangles and vertices over all instances (before culling): the vertex stage keeps about
    // 100 bytes per vertex and binning about 50 per triangle. Vertices are counted in 32 bits, so
    // max_vertices cannot usefully exceed 2^32 - 1.
    std::uint64_t max_triangles = 100'000'000;
    std::uint64_t max_vertices = 100'000'000;
    // Binning's records: each triangle once per 64x64-pixel tile it overlaps (tens of bytes each).
    // Small triangles need a few hundred MB at 100 million; large ones drawn over each other need
    // far more (a 6 KB glTF placing one screen-sized triangle a million times: 20 GB), refused
    // past this before the records are allocated (LimitExceeded "max_bin_bytes").
    std::uint64_t max_bin_bytes = std::uint64_t{2} << 30;
    // Samples rasterized by the paths that draw every fragment of every triangle, hidden or not:
    // the depth test off (--view overdraw's count, RenderOptions::depth_test false), blended
    // (transparent) triangles, which write no depth, and render_multisampled (its coverage and
    // depth per sample). Counted before rasterizing as the pixels of the frame inside each
    // triangle's bounding box (times the samples per pixel), summed: bins of a few hundred MB can
    // hold minutes of such work (a 2 KB glTF placing a half-screen triangle 50,000 times). Past
    // it, LimitExceeded "max_covered_samples".
    std::uint64_t max_covered_samples = std::uint64_t{1} << 31;
    // The frame's working memory, estimated from the counts before anything is allocated (see
    // estimated_frame_bytes): the per-vertex and per-triangle budgets above allow 100 million
    // of each, about 15 GB, and a small file placing a mesh a million times reaches them. Past
    // it, LimitExceeded "max_frame_bytes". 4 GiB holds 30 million instanced vertices with
    // their triangles and a 4K frame.
    std::uint64_t max_frame_bytes = std::uint64_t{4} << 30;

    // The object-space visibility algorithms (visibility.hpp, and the SVG writer): their work
    // grows faster than their input (random, interpenetrating triangles split without end), so
    // each has a budget, scaled to the input unless set here (0: automatic, as stated; the
    // budget functions in visibility.hpp compute it). Exceeding one throws LimitExceeded.
    // Painter's algorithm: polygon-pair comparisons (0.1 to 0.2 us each). Automatic: 2048 per
    // polygon + 10^7, at most 10^8 (10 to 20 s on one core; the meshes measured need 10 to 420
    // per polygon, so a mesh of more than about 250,000 visible polygons may need it raised).
    std::uint64_t max_painter_comparisons = 0;
    // BSP tree: polygons in its pool after splitting (about 250 bytes each). Automatic: 16 per
    // input triangle + 65,536, at most 2^22 (about 1 GB; the meshes measured need about 2 per
    // triangle). A scene of more triangles than the budget is refused before the tree is built.
    std::uint64_t max_bsp_polygons = 0;
    // BSP tree: polygon-plane classifications while building (15 to 20 ns each). Automatic:
    // 16 per pair of input triangles (16 n^2) + 10^7, at most 5 x 10^8 (about 10 s; the meshes
    // measured need 680 to 1,440 per triangle, a convex mesh, whose tree is a chain, about
    // 6.5 n^2).
    std::uint64_t max_bsp_classifications = 0;
    // Polygons kept by projection, the input of the painter's and Warnock's algorithms, the
    // A-buffer and the multisampled path (visibility.hpp's project_scene), counted as they are
    // made: about 0.7 KB each through the painter's sort, 2 KB in the A-buffer. Automatic:
    // 2^19 = 524,288 (at most about 1 GB).
    std::uint64_t max_projected_polygons = 0;
    // Pixels filled by the painter's and the BSP tree's back-to-front drawing: every polygon is
    // filled, hidden or not (overdraw), and each filled pixel is shaded (about 0.2 us).
    // Automatic: 16 per pixel + 2^24, at most 2^26 (about 13 s; 10 s at 1920x1080).
    std::uint64_t max_painted_fragments = 0;
    // Warnock: polygon-region classifications. Automatic: 64 per polygon per level of the
    // region quadtree + 4 per pixel + 10^7.
    std::uint64_t max_warnock_classifications = 0;
};

// What a frame holds, the figures of max_frame_bytes' estimate (measured as the peak memory of
// frames of 1 to 60 million vertices, rounded up): a vertex in the vertex stage (its clip and
// screen positions, attributes and outcodes) and the camera fit's world position; a triangle in
// assembly and binning (its setup record and the tiles it overlaps, for triangles of a few
// pixels); a pixel and sample of the targets a frame allocates (color, depth, normal, ids,
// coverage counts). Targets the caller passes are its own memory and not counted.
inline constexpr std::uint64_t kFrameBytesPerVertex = 100;
inline constexpr std::uint64_t kFrameBytesPerTriangle = 50;
inline constexpr std::uint64_t kFrameBytesPerSample = 36;
// vertices * kFrameBytesPerVertex + triangles * kFrameBytesPerTriangle + target_samples *
// kFrameBytesPerSample, saturated at 2^64 - 1.
// `bytes_per_sample`: what the path keeps per sample (multisampling: its coverage and depth
// per sample, 8 bytes, and the resolved targets' share).
ZRASTER_API std::uint64_t estimated_frame_bytes(
    std::uint64_t vertices, std::uint64_t triangles, std::uint64_t target_samples,
    std::uint64_t bytes_per_sample = kFrameBytesPerSample);
// Throws LimitExceeded(source, "max_frame_bytes"), naming the estimate, the counts and the
// limit, when that estimate is past limits.max_frame_bytes. render() checks it before allocating;
// a front end that copies the scene first (a camera fit over its world positions) checks it
// before that copy.
ZRASTER_API void check_frame_memory(std::string_view source, std::uint64_t vertices,
                                    std::uint64_t triangles, std::uint64_t target_samples,
                                    const RenderLimits& limits,
                                    std::uint64_t bytes_per_sample = kFrameBytesPerSample);

// A frame's threads are capped at this many per hardware thread: oneTBB cannot make an arena of
// millions of threads (it crashes), and more than a few per core only compete for the cores.
inline constexpr int kMaxThreadsPerHardwareThread = 4;
// The threads a frame with RenderOptions::threads = `requested` (>= 0) runs on.
ZRASTER_API int render_thread_count(int requested);

// Told how far a long computation has got: the object-space visibility algorithms (painter's,
// BSP, Warnock) call it from the thread running them, every few thousand steps, with a fraction
// in [0, 1] that does not decrease within a stage. The front end decides what to show (the
// command prints a line to stderr once a run has taken a few seconds).
class ProgressReporter {
  public:
    virtual ~ProgressReporter() = default;
    virtual void report(const char* stage, double fraction) = 0;
};

struct RenderOptions {
    int width = 1920;
    int height = 1080;
    // 0: all hardware threads. At most kMaxThreadsPerHardwareThread times the hardware threads
    // are used (render_thread_count); the images never depend on it.
    int threads = 0;

    // No camera: fit_camera() over the scene's world-space vertices (the benchmark framing).
    std::optional<Camera> camera;

    ShadingMode shading = ShadingMode::Phong;
    LightingModel lighting;
    TextureFilter texture_filter = TextureFilter::Trilinear;
    Interpolation interpolation = Interpolation::PerspectiveCorrect;
    bool textures = true;
    // Back faces are lit with the negated normal (two-sided lighting), as the benchmark shader
    // does.
    bool two_sided_lighting = true;
    // Auto: Mask materials are alpha-tested (fragments under the cutoff are discarded before
    // they write depth) and Blend materials whose alpha can be below 1 are composited over the
    // opaque surfaces, per pixel, nearest last, in any submission order the same image; blended
    // fragments write neither depth nor ids nor normals.
    MaterialAlpha alpha_mode = MaterialAlpha::Auto;
    ShadingStrategy strategy = ShadingStrategy::Auto;
    // Use the SIMD kernels (off: the scalar reference path everywhere, for comparisons).
    bool simd = true;
    // Hierarchical z: skip 8x8 blocks whose stored depths already hide the triangle there. The
    // test is conservative, so the image is the same with it off (for comparisons).
    bool hierarchical_z = true;
    // Back-face culling of whole clusters of 64 triangles by bounds kept from frame to frame
    // (a Renderer drawing an unchanged mesh again), before their vertices are read. Exact: the
    // image and the counts are the same with it off (for comparisons), bar clusters_culled.
    bool cluster_culling = true;
    // A promise that no mesh changes between this Renderer's frames (as static vertex buffers
    // do not): a mesh seen again with the same array sizes is then taken as unchanged, and its
    // positions and indices are not hashed to check it (all of them, every frame: tens of MB for
    // a million triangles). A mesh changed anyway keeps the culling of its old shape: triangles may
    // go missing and skipped vertices hold stale positions. Off: every change is noticed.
    bool static_meshes = false;
    InstanceOrder instance_order = InstanceOrder::Submission;

    CullMode cull = CullMode::Back;
    FrontFace front_face = FrontFace::CounterClockwise;
    // Materials' sides (Material::double_sided, glTF doubleSided): a double-sided material's
    // triangles are never culled and its back faces are lit with the flipped normal, whatever
    // cull and two_sided_lighting say; other materials follow them. Off: every triangle follows
    // cull and two_sided_lighting. Only double-sided materials (glTF files that say so) are
    // affected: OBJ, PLY and STL materials are single-sided.
    bool material_sides = true;

    DepthFormat depth_format = DepthFormat::D32F;
    // Unset: LESS, or GREATER with a reversed-Z camera.
    std::optional<CompareFunc> depth_compare;
    bool depth_test = true;
    bool depth_write = true;

    // Occlusion culling of instances (src/render/occlusion_cull.cpp): the instances covering
    // the most screen are drawn into an OcclusionBuffer at the frame's resolution, then every
    // other instance's box is tested, nearest first, and skipped when hidden. The image is
    // bit-identical with and without it (the buffer is conservative and occluders are always
    // drawn); it only runs where that holds: D32F depth, LESS or LEQUAL with depth writes, a
    // standard depth range, no user clip planes, no edges. RenderStats counts what it skipped.
    bool occlusion_cull = false;

    // Portal culling through the scene's cell graph (SceneView::cells, Scene::cells): instances
    // that no ray from the eye can reach through the portals are skipped. Exact (the same image
    // and ids) when the graph keeps its contract (portals.hpp: cell boundaries opaque outside
    // the portals); it runs only where occlusion culling would (same conditions), and draws
    // everything when the eye is in no cell. A graph's PVS (CellGraph::pvs) filters first, also
    // with Off. RenderStats counts what was skipped and the cells reached.
    PortalCull portal_cull = PortalCull::Off;

    // World-space planes (n.x, n.y, n.z, d): points with dot(n, p) + d >= 0 are kept.
    std::vector<glm::vec4> clip_planes;

    glm::vec3 background{0.2f, 0.2f, 0.2f};  // 0..1

    // Triangle edges drawn over the image with Bresenham lines (src/render/edges.cpp):
    // Wireframe: every edge of every drawn triangle, surfaces not shown (background instead).
    // HiddenLine: surfaces shaded as usual, edges depth-tested against them with a
    // slope-scaled offset, so only visible edges show.
    enum class Edges { None, Wireframe, HiddenLine };
    Edges edges = Edges::None;
    glm::vec3 edge_color{0.0f};

    // Which targets render(const Scene&, ...) produces; depth is always kept. (With TargetViews
    // the non-null pointers choose, and these four are not read.)
    bool color_target = true;
    bool normal_target = false;
    bool id_targets = false;
    // RenderResult::instance_outcomes: what the frame did with each scene instance (the owning
    // entry points only). Off: nothing is recorded or allocated.
    bool report_instance_outcomes = false;
    // Per-pixel counts of front- and back-facing fragments that passed the depth test
    // (with depth_test = false: every fragment): the watertightness check.
    bool coverage_counts = false;

    // A picture of what the pipeline did in place of the shaded color (debug_view.hpp).
    DebugView view = DebugView::None;

    RenderLimits limits;
    ProgressReporter* progress = nullptr;  // not owned; null: no reports
};

struct RenderTargets {
    int width = 0, height = 0;
    // All rows top to bottom.
    std::vector<std::uint8_t> color;         // RGBA8
    std::vector<float> depth;                // window-space depth as stored (decoded)
    std::vector<glm::vec3> normal;           // world-space shading normal, (0,0,0) where empty
    std::vector<std::int32_t> instance_id;   // -1 where empty
    std::vector<std::int32_t> primitive_id;  // triangle index within its mesh, -1 where empty
    std::vector<std::uint32_t> front_hits, back_hits;
};

// The caller's images, for Renderer::render(const SceneView&, ...): each a pointer to the first
// (top) row and the row pitch in bytes (0: rows tightly packed, width elements), the same
// layouts and values as RenderTargets. Null: not wanted (and not computed where nothing else
// needs it). width and height must equal RenderOptions::width and height. float, vec3 and
// 32-bit targets must be 4-byte aligned, with pitches multiples of 4. Every pixel of every given
// target is written every frame (nothing is assumed about what the memory held before, unless
// unchanged_since_last_frame says so); bytes between a row's end and the next row (a pitch's
// padding) are never touched.
struct TargetViews {
    int width = 0, height = 0;
    std::uint8_t* color = nullptr;  // RGBA8
    std::size_t color_pitch = 0;
    float* depth = nullptr;  // window-space depth as stored (decoded)
    std::size_t depth_pitch = 0;
    glm::vec3* normal = nullptr;  // world-space shading normal, (0,0,0) where empty
    std::size_t normal_pitch = 0;
    std::int32_t* instance_id = nullptr;  // -1 where empty
    std::size_t instance_id_pitch = 0;
    std::int32_t* primitive_id = nullptr;  // triangle index within its mesh, -1 where empty
    std::size_t primitive_id_pitch = 0;
    // Per-pixel counts of front- and back-facing fragments (RenderOptions::coverage_counts).
    std::uint32_t* front_hits = nullptr;
    std::size_t front_hits_pitch = 0;
    std::uint32_t* back_hits = nullptr;
    std::size_t back_hits_pitch = 0;
    // The caller's promise that these are the arrays (same addresses and pitches) this Renderer
    // wrote in its previous frame, and that nothing has written them since. Tiles that held the
    // cleared values then and are empty again are not rewritten, as in the Renderer's own
    // targets (at 1080p, most of the 16 MB of color and depth a frame is background). Different
    // addresses, pitches, size or clear values are noticed and every pixel is written; a broken
    // promise about the contents is not noticed (stale pixels stay), as with static_meshes.
    bool unchanged_since_last_frame = false;
};

// Views of RenderTargets' arrays (null where an array is empty), rows tightly packed.
ZRASTER_API TargetViews view_of(RenderTargets& targets);

struct RenderStats {
    std::uint64_t instances = 0, instances_frustum_culled = 0;
    std::uint64_t instances_occlusion_culled = 0;  // with RenderOptions::occlusion_cull
    // With RenderOptions::portal_cull or a PVS: instances inside the view frustum skipped
    // because no portal sequence (or the PVS) reaches them.
    std::uint64_t instances_portal_culled = 0;
    PortalOutcome portal_outcome = PortalOutcome::NotRun;
    std::int64_t portal_camera_cell = -1;    // the eye's cell, -1: none or not looked for
    std::uint64_t portal_cells_visited = 0;  // distinct cells the walk reached
    std::uint64_t portal_visits = 0;     // cell entries (one per portal sequence reaching a cell)
    std::uint64_t portal_pvs_cells = 0;  // cells in the camera cell's PVS (0: no PVS)
    double portal_ms = 0;                // the walk and the instance tests
    std::uint64_t triangles_in = 0;
    std::uint64_t triangles_trivially_rejected = 0;  // all vertices outside one plane
    std::uint64_t triangles_non_finite = 0;          // NaN/Inf vertex: dropped
    std::uint64_t triangles_clipped = 0;             // went through the clipper
    std::uint64_t triangles_backface_culled = 0;
    std::uint64_t triangles_degenerate = 0;
    std::uint64_t triangles_no_coverage = 0;  // no pixel center in their bounding box
    std::uint64_t triangles_rasterized = 0;   // set up and binned (after clipping: pieces)
    std::uint64_t clusters_culled = 0;   // RenderOptions::cluster_culling (their triangles count
                                         // as back-face culled)
    std::uint64_t vertices_skipped = 0;  // not transformed: only culled clusters use them
    std::uint64_t blocks_hidden = 0;     // skipped by hierarchical z (triangle x block)
    std::uint64_t fragments_passed = 0;  // passed the depth test
    std::uint64_t fragments_shaded = 0;
    std::uint64_t fragments_alpha_discarded = 0;  // Mask materials' fragments under the cutoff
    std::uint64_t fragments_blended = 0;          // Blend materials' fragments composited
    std::uint64_t pixels_blended = 0;             // pixels with at least one of them
    bool deferred = false;         // some pixels were shaded deferred (resolved first, then shaded)
    const char* simd_target = "";  // instruction set of the SIMD kernels
    Camera camera;                 // the camera actually used
    double setup_ms = 0, raster_ms = 0, total_ms = 0;
    // setup_ms in its parts: the vertex stage, primitive assembly (culling, clipping, coverage
    // tests) and binning.
    double vertex_ms = 0, assembly_ms = 0, binning_ms = 0;
    // With RenderOptions::view: the ends of the picture's color scale (debug_view_legend).
    DebugViewScale view_scale;
};

// What a frame did with a scene instance: drawn, or skipped by which culling. An instance the
// vertex stage draws may still have no pixel (hidden, or every triangle culled or clipped).
enum class InstanceOutcome : std::uint8_t {
    Drawn,
    FrustumCulled,    // outside the view frustum
    PortalCulled,     // reached by no portal sequence from the eye's cell, or outside its PVS
    OcclusionCulled,  // hidden behind the occluders drawn this frame
};

struct RenderResult {
    RenderTargets targets;
    RenderStats stats;
    // One per scene instance, in scene order, with RenderOptions::report_instance_outcomes;
    // empty otherwise.
    std::vector<InstanceOutcome> instance_outcomes;
};

// Renders one frame. Throws InputError for unusable options (size out of range, more user clip
// planes than supported, a non-finite camera), a request past options.limits, or an inconsistent
// scene (an instance naming a missing mesh, a vertex index past the mesh's positions, normals or
// uvs or colors not one per position, no materials).
ZRASTER_API RenderResult render(const Scene& scene, const RenderOptions& options);
// The same from views into the caller's targets (see Renderer::render below), for one frame.
ZRASTER_API RenderStats render(const SceneView& scene, const RenderOptions& options,
                               const TargetViews& targets);

// How a Renderer fits the machine it runs on. The defaults ask the operating system.
struct RendererConfig {
    // A frame whose bins, vertices and targets together exceed this many bytes will not find
    // its targets in the cache at the next frame, so it writes them with non-temporal stores
    // (past the cache). 0: the size of the last-level cache (Linux's sysfs; 32 MiB where it
    // says nothing). The images never depend on it.
    std::size_t streaming_threshold_bytes = 0;
};

// The same, keeping its working memory (vertex arrays, bins, image targets) and its thread arena
// from frame to frame: what an application rendering many frames wants. Not thread-safe: one
// frame at a time.
class ZRASTER_API Renderer {
  public:
    Renderer();
    explicit Renderer(const RendererConfig& config);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // The result stays valid until the next call, which reuses its targets: tiles that stay
    // empty keep the cleared values they hold and are not rewritten.
    // (So the targets are const: read or copy them, do not change them.)
    const RenderResult& render(const Scene& scene, const RenderOptions& options);

    // One frame of the caller's scene into the caller's targets (see TargetViews), the same
    // images as the call above for the same scene and options. Throws InputError, before
    // anything is read or written, for what the call above refuses and for unusable views: a
    // null pointer with a non-zero count, a stride shorter than its element, normals, uvs or colors
    // neither absent nor one per position, an index past the positions, an instance naming a
    // missing mesh, a mesh naming a missing material, no materials, targets of another size
    // than the options', a pitch shorter than a row, a misaligned target. The messages name
    // the field ("mesh 2 'wall': positions.stride 8 is smaller than a position (12 bytes)").
    // The statistics stay valid until the next call.
    const RenderStats& render(const SceneView& scene, const RenderOptions& options,
                              const TargetViews& targets);

  private:
    struct State;
    std::unique_ptr<State> state_;
};

// The options' effective depth compare function and clear value.
ZRASTER_API CompareFunc effective_depth_compare(const RenderOptions& options);
ZRASTER_API float depth_clear_value(const RenderOptions& options);

}  // namespace zraster
