// Internal data of one frame, shared by the renderer's stages (src/render/*.cpp).
//
// Front end (parallel over chunks of triangles): every triangle is culled, clipped and tested
// for pixel coverage; survivors become TriangleRefs, binned per chunk into screen tiles.
// Back end (parallel over tiles): each tile walks the chunks in order, so every pixel sees its
// triangles in submission order whatever the thread count.
#pragma once
#include <zraster/clip.hpp>
#include <zraster/instance_bvh.hpp>
#include <zraster/lines.hpp>
#include <zraster/occlusion_buffer.hpp>
#include <zraster/precision.hpp>
#include <zraster/render.hpp>

#include "raster/tile_layout.hpp"
#include "raster/visibility_kernel.hpp"
#include "render/blend_scratch.hpp"
#include "render/classify_kernel.hpp"
#include "render/cluster_cache.hpp"
#include "render/debug_view_scratch.hpp"
#include "render/material_alpha.hpp"
#include "render/mesh_access.hpp"
#include "render/portal_cull.hpp"
#include "render/shade_kernel.hpp"
#include "render/stream_lines.hpp"
#include "shade/surface_shading.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace zraster::detail {

// One instance as the later stages see it.
struct FrameInstance {
    std::uint32_t scene_instance = 0;  // index into SceneView::instances (the id written out)
    const FrameMesh* mesh = nullptr;   // in Frame::meshes
    const Material* material = nullptr;
    ShadingMode shading = ShadingMode::Phong;
    std::uint32_t first_vertex = 0;  // into FrameVertices
    glm::mat4 mvp{1.0f};
    glm::mat4 model{1.0f};
    glm::mat3 normal_matrix{1.0f};  // object to world for normals (inverse transpose)
    bool textured = false;
    AlphaMode alpha = AlphaMode::Opaque;  // effective_alpha_mode (material_alpha.hpp)
    AlphaVariation alpha_varies;          // per fragment from textures (uvs needed), vertices
    bool vertex_colored = false;          // base color times the mesh's vertex colors
    // Materials' sides (material_sides.hpp): the faces the front end culls, and whether back
    // faces are lit with the flipped normal.
    CullMode cull = CullMode::Back;
    bool two_sided_lighting = true;
    int phong_kernel = -1;  // index into Frame::phong_constants when the SIMD shader applies
    float distance = 0.0f;  // eye to the world bounding box (InstanceOrder::FrontToBack)
    // Cluster culling (cluster_cache.hpp): the vertex stage's hash of the mesh's positions
    // (kStaticMeshHash, nothing hashed, under RenderOptions::static_meshes), and the mesh's
    // cluster bounds (null: none this frame) with this instance's view of them.
    bool positions_hashed = false;
    std::uint64_t positions_hash = 0;
    const MeshClusters* clusters = nullptr;
    ClusterView cluster_view;
    // The clusters' verdicts (1: culled), made by the vertex stage to skip the vertices only
    // culled clusters use; null when it made none (the front end then tests the clusters
    // itself). When it skipped vertices it checked every cluster's indices first.
    const std::uint8_t* culled_clusters = nullptr;
    bool cluster_indices_checked = false;
};

// Row y of a target whose rows are `pitch` bytes apart.
template <class T>
T* target_row(T* first_row, std::size_t pitch, int y) {
    return reinterpret_cast<T*>(reinterpret_cast<std::byte*>(first_row) +
                                static_cast<std::size_t>(y) * pitch);
}

// The targets a frame writes (TargetViews, pitches resolved: never 0) and what it must compute
// for them. depth is null when neither the caller nor the edges want it.
struct FrameTargets {
    TargetViews views;
    bool color = false, normal = false;
    bool ids = false;       // instance or primitive ids
    bool coverage = false;  // front or back hit counts
    // Targets as the last frame left them (the Renderer's own, or the caller's with
    // TargetViews::unchanged_since_last_frame): tiles that hold the cleared values may be left
    // as they are (ClearedTiles).
    bool kept = false;

    explicit FrameTargets(const TargetViews& v = {}, bool own = false)
        : views(v),
          color(v.color != nullptr),
          normal(v.normal != nullptr),
          ids(v.instance_id != nullptr || v.primitive_id != nullptr),
          coverage(v.front_hits != nullptr || v.back_hits != nullptr),
          kept(own) {}
};

// Whether the frame may use tagged shading: the visibility kernel interpolates the attributes
// of SIMD Phong instances' triangles, and either the deferred pass shades them a vector at a
// time or, shading forward, the kernel lights them as they pass. (ShadingStrategy::Forward uses
// it only when every instance is a SIMD Phong one: the others would be resolved first.) A
// normal target is written from the normals the kernel interpolated, so deferred only: lighting
// forward, the kernel keeps no normals.
inline bool tagged_shading(const RenderOptions& options, const FrameTargets& targets) {
    const bool forward = options.strategy == ShadingStrategy::Forward;
    return options.simd &&
           (forward ? targets.color && !targets.normal : targets.color || targets.normal) &&
           options.depth_format == DepthFormat::D32F && options.depth_test && !targets.coverage;
}

// Output of the vertex stage for every vertex of every visible instance.
struct FrameVertices {
    std::vector<ScreenVertex> screen;    // valid where outcode == 0
    std::vector<std::uint32_t> outcode;  // ClipPlaneBit mask; kNonFinite for NaN/Inf
    std::vector<glm::vec3> world;        // when shading or user clip planes need them
    std::vector<glm::vec3> normal;       // world space, unit
    std::vector<glm::vec2> uv;           // (0, 0) when the mesh has none
    std::vector<LightTerms> gouraud;     // per-vertex lighting (Gouraud instances only)
    std::vector<glm::vec4> color;        // vertex colors (vertex-colored instances only)
};
inline constexpr std::uint32_t kNonFinite = 0xffffffffu;

// A triangle (or a piece of a clipped one) that covers at least one pixel center. 32 bytes:
// the front end writes one per kept triangle and the bin writer reads them all back.
struct TriangleRef {
    // The original triangle's vertices (attributes), which are also its screen vertices unless
    // it is a clipped piece (see ClippedPiece::screen).
    std::array<std::uint32_t, 3> vertex{};
    std::uint32_t instance = 0;         // into Frame::instances
    std::uint32_t primitive = 0;        // triangle index within its mesh
    std::uint32_t piece = kNotClipped;  // into Chunk::pieces for a clipped piece
    std::uint8_t tile_x0 = 0, tile_y0 = 0, tile_x1 = 0, tile_y1 = 0;  // the tiles it touches
    bool front_facing = true;
    static constexpr std::uint32_t kNotClipped = 0xffffffffu;
};
static_assert(sizeof(TriangleRef) == 32);

// A clipped piece: the barycentric weights of its corners relative to its original triangle,
// and its screen vertices, indices into the chunk's extra vertices (made by the clipper).
struct ClippedPiece {
    std::array<glm::vec3, 3> weights;
    std::array<std::uint32_t, 3> screen;
};

// A triangle in a tile's bin: its snapped vertices travel with it, so the back end reads its
// bins sequentially instead of chasing refs and vertices all over memory.
struct BinEntry {
    std::array<ScreenVertex, 3> vertices;
    std::uint32_t ref;  // index into Chunk::refs, | kClippedPiece for a clipped piece
    // Set for a clipped piece: its corner weights (Chunk::pieces) are looked up through the
    // ref (rare, so CornerAttributes does not carry them).
    static constexpr std::uint32_t kClippedPiece = 0x80000000u;
};

// The first cache line boundary at or after p.
template <class T>
T* align_to_cache_line(T* p) {
    const auto address = reinterpret_cast<std::uintptr_t>(p);
    return p + ((kCacheLine - address % kCacheLine) % kCacheLine);
}

struct Chunk {
    std::size_t first_triangle = 0, end_triangle = 0;  // over all instances' triangles
    std::vector<TriangleRef> refs;
    std::vector<ScreenVertex> extra_vertices;
    std::vector<ClippedPiece> pieces;
    // How many of the chunk's refs touch each tile (binning's first pass).
    std::vector<std::uint32_t> bin_counts;
    RenderStats stats;
    // The frame instance of the chunk's first triangle with a vertex index out of range
    // (kNoBadIndex: none). The renderer then refuses the scene (check_indices).
    std::uint32_t bad_index_instance = kNoBadIndex;
    static constexpr std::uint32_t kNoBadIndex = 0xffffffffu;
    // The bytes of the chunk's bin runs, each rounded up to whole cache lines (write_bins'
    // scratch).
    std::size_t bin_bytes = 0;
    // Scratch kept with the chunk (the same triangles land in the same chunk frame after
    // frame, so its size settles): 16-bit indices widened, cluster verdicts.
    std::vector<std::uint32_t> widened_indices;
    std::vector<std::uint8_t> cluster_verdicts;
};

// A tile's counts of alpha-tested and blended fragments (rasterize_tiles).
struct TileAlphaCounts {
    std::uint64_t discarded = 0;
    std::uint64_t blended_fragments = 0, blended_pixels = 0;
};

// Scratch of one slot of the frame's arena (tbb::this_task_arena::current_thread_index()):
// sized before the parallel stage that uses it, so that no thread allocates within a frame
// whichever chunks or tiles it happens to take.

struct SlotScratch {
    ClassifyOutput classify;                     // assemble_and_bin's front end
    std::unique_ptr<TileBuffers> tile;           // rasterize_tiles
    std::vector<std::size_t> run_start, cursor;  // write_bins
    std::vector<std::byte> bin_storage;          // write_bins, from its first cache line
    BlendScratch blend;                          // rasterize_tiles' blended surfaces
    std::unique_ptr<TileBuffers> side;           // ... and alpha-tested ones (mask_pass.hpp)
};

// Instance culling's working memory (occlusion_cull.cpp), kept from frame to frame.
struct InstanceCulling {
    std::vector<std::uint8_t> verdicts;  // InstanceCull per scene instance
    PortalWalk portal;                   // RenderOptions::portal_cull, a cell graph's PVS
    std::vector<Bounds3f> world_boxes;
    InstanceBvh bvh;
    std::vector<std::uint32_t> inside;
    std::unique_ptr<OcclusionBuffer> buffer;
    struct Candidate {
        std::uint32_t instance = 0;
        glm::mat4 mvp{1.0f};
        double screen_fraction = 0.0;  // of the projected box, clamped to the screen
        double distance = 0.0;         // eye to the world box's center
        std::size_t triangles = 0;
        bool opaque = true;  // only opaque surfaces occlude (not alpha-tested or blended ones)
    };
    std::vector<Candidate> candidates;
    std::vector<std::size_t> by_size, occluders, by_distance;
    std::vector<std::uint8_t> is_occluder;
    // An occluder whose arrays are strided or 16-bit, one position per corner (occlusion_cull).
    std::vector<glm::vec3> occluder_positions;
    std::vector<std::uint32_t> occluder_indices;
};

// Which tiles of a kept Renderer's targets still hold the cleared values from the previous
// frame, so that a tile empty again is not rewritten (1080p depth and color are 16 MB a frame,
// most of them background around a small model). Valid only for the same clear values and
// targets (the same arrays: own and caller targets in turn are each written whole); invalid
// while a frame is being written and after frames that draw edges (a line may reach a pixel
// past the tiles its triangle was binned to).
struct ClearedTiles {
    struct Signature {
        int width = 0, height = 0;
        DepthFormat format = DepthFormat::D32F;
        std::uint32_t clear_bits = 0, background = 0;
        // The targets written (null: not written), pitches resolved.
        const void *color = nullptr, *depth = nullptr, *normal = nullptr;
        const void *instance_id = nullptr, *primitive_id = nullptr;
        std::size_t color_pitch = 0, depth_pitch = 0, normal_pitch = 0;
        std::size_t instance_id_pitch = 0, primitive_id_pitch = 0;
        bool operator==(const Signature&) const = default;
        // Whether the two write some array in common.
        bool shares_an_array_with(const Signature& o) const {
            const void* const mine[] = {color, depth, normal, instance_id, primitive_id};
            const void* const theirs[] = {o.color, o.depth, o.normal, o.instance_id,
                                          o.primitive_id};
            for (const void* a : mine)
                for (const void* b : theirs)
                    if (a != nullptr && a == b) return true;
            return false;
        }
    };
    bool valid = false;
    Signature signature;
    std::vector<std::uint8_t> cleared;  // per tile, row-major: 1 when it holds the cleared values
};

struct Frame {
    const SceneView* scene = nullptr;
    std::string_view source;  // the scene's file or builtin name, for messages
    // RenderOptions::report_instance_outcomes: where the vertex stage records them; null: not
    // asked for.
    std::vector<InstanceOutcome>* instance_outcomes = nullptr;
    const RenderOptions* options = nullptr;
    // One per scene mesh, set for the meshes instances use (the others: view null).
    std::vector<FrameMesh> meshes;
    FrameTargets targets;
    Camera camera;
    glm::vec3 eye{0.0f}, view_axis{0.0f, 0.0f, 1.0f};
    ClipSettings clip_settings;
    SetupSettings setup_settings;
    bool needs_attributes = true;  // false for depth-only frames
    bool tagged_shading = false;   // tagged_shading(options) and an instance uses it
    bool alpha_instances = false;  // an instance is alpha-tested or blended
    int tiles_x = 0, tiles_y = 0;
    std::vector<FrameInstance> instances;
    std::vector<std::size_t> instance_first_triangle;  // prefix sums, one more than instances
    FrameVertices vertices;
    std::vector<Chunk> chunks;
    // Bins, tile-major: the run of chunk c in tile t (i = t * chunks.size() + c) is
    // bin_run_counts[i] records of bin_record_bytes from bin_records() + bin_run_offsets[i].
    // A record is a BinEntry, followed with tagged shading by its triangle's CornerAttributes
    // (tag 0: not a SIMD Phong instance's). A tile's triangles of all chunks, in order, are
    // one stretch of memory the back end streams (bins per chunk cost a cache and TLB miss per
    // chunk in every tile). Runs start on cache lines: the bin writer builds a chunk's runs in
    // a scratch buffer that stays in cache and streams them out in whole lines (stores into
    // 500 runs spread over 90 MB read every line from memory before writing it).
    std::vector<std::size_t> bin_run_offsets;
    std::vector<std::uint32_t> bin_run_counts;
    std::vector<std::size_t> tile_bin_counts;  // records per tile, all chunks
    std::size_t bin_record_bytes = 0;
    std::size_t bin_bytes = 0;           // this frame's runs, from bin_records()
    std::vector<std::byte> bin_storage;  // the records, from its first cache line boundary
    std::byte* bin_records() { return align_to_cache_line(bin_storage.data()); }
    const std::byte* bin_records() const { return align_to_cache_line(bin_storage.data()); }
    std::vector<PhongConstants> phong_constants;
    ClearedTiles cleared_tiles;  // kept from frame to frame (see above)
    ClusterCache cluster_cache;  // kept from frame to frame
    std::vector<std::vector<std::uint8_t>> cluster_verdicts;  // FrameInstance::culled_clusters
    std::vector<std::uint8_t> needed_vertex_blocks;           // the vertex stage's scratch

    // Working memory kept from frame to frame, so that a frame like the last allocates nothing.
    std::vector<SlotScratch> slots;  // one per arena slot
    InstanceCulling culling;
    // The vertex stage: per scene mesh, whether its positions were hashed and their hash.
    std::vector<std::uint8_t> mesh_hashed;
    std::vector<std::uint64_t> mesh_hash;
    std::vector<std::uint8_t> mesh_flags;            // used, drawn (input_checks.cpp)
    std::vector<glm::vec3> world_points;             // fit_camera's input without a camera
    std::vector<std::size_t> tile_bytes, tile_base;  // bin_offsets
    // Per tile (rasterize_tiles): fragments passed and shaded, blocks hidden, deferred.
    std::vector<std::uint64_t> tile_passed, tile_shaded, tile_hidden;
    std::vector<TileAlphaCounts> tile_alpha;  // empty when no instance is alpha-tested or blended
    std::vector<std::uint8_t> tile_deferred;
    std::vector<LinePixel> line;             // draw_edges
    std::optional<DepthBuffer> depth_codec;  // rasterize_tiles: encodes and decodes the format
    // The size above which a frame's data is taken not to stay in the last-level cache from one
    // frame to the next: rasterize_tiles then writes the targets with non-temporal stores
    // (RendererConfig::streaming_threshold_bytes, resolved).
    std::size_t streaming_threshold = std::size_t{32} << 20;
    // Debug views (RenderOptions::view): their auxiliary frames' targets and tables, and, for
    // the hiz view's frame only, the per-block counts of hierarchical-z skips (null otherwise:
    // the tiles count nothing more).
    DebugViewScratch debug_view;
    std::uint32_t* hiz_block_counts = nullptr;

    // The slot of the calling thread in the frame's arena.
    SlotScratch& slot();

    // Corner k of a ref's triangle on screen.
    const ScreenVertex& screen_vertex(const Chunk& chunk, const TriangleRef& ref,
                                      std::size_t k) const {
        return ref.piece == TriangleRef::kNotClipped
                   ? vertices.screen[ref.vertex[k]]
                   : chunk.extra_vertices[chunk.pieces[ref.piece].screen[k]];
    }
};

// The setup settings of one instance's triangles in the front end: the frame's, with the
// instance's cull mode (material_sides.hpp; the frame's own culls nothing when they differ).
inline SetupSettings instance_setup(const Frame& frame, const FrameInstance& fi) {
    SetupSettings s = frame.setup_settings;
    s.cull = fi.cull;
    return s;
}

// One frame through every stage (below) into `targets` (pitches resolved; `kept`: as
// FrameTargets::kept), the options and scene already validated (renderer.cpp).
void draw_frame(Frame& frame, const SceneView& scene, std::string_view source,
                const RenderOptions& options, const TargetViews& targets, bool kept,
                RenderStats& stats);
// The same with RenderOptions::view set: the frame as without the view, then its color target
// replaced by the view's picture (debug_view_frame.cpp).
void draw_debug_view(Frame& frame, const SceneView& scene, std::string_view source,
                     const RenderOptions& options, const TargetViews& targets, bool kept,
                     RenderStats& stats);

// Stages, in order.
void run_vertex_stage(Frame& frame, RenderStats& stats);
void attach_clusters(Frame& frame);  // cluster_cache.cpp
void assemble_and_bin(Frame& frame, RenderStats& stats);
void drop_stale_clusters(Frame& frame);

// Sizes Frame::slots to the arena's concurrency (each with its TileBuffers).
void prepare_slots(Frame& frame);
void rasterize_tiles(Frame& frame, RenderStats& stats);
void draw_edges(Frame& frame);

}  // namespace zraster::detail
