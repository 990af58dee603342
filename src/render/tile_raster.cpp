// The back end: per tile, in parallel. Each tile owns its pixels and walks the chunks' bins in
// submission order, so tiles can run on any thread in any order and the image stays the same.
//
// A tile, stage by stage:
//   records (tile_records.hpp): its bin records streamed, kSetupLanes at a time, set up in lanes;
//   traversal (tile_traversal.hpp): each triangle's pixels found and depth-tested, small ones as
//     one kernel job straight from the lanes, the others block by block (hierarchical z);
//     alpha-tested ones through a side buffer (mask_pass.hpp);
//   resolve (tile_resolve.hpp): the visible pixels shaded once (deferred) and written out;
//   blend (blend_pass.hpp): blended surfaces composited over the result.
// The frame decides once how pixels are shaded (ShadingPath) and traversed (Traversal).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <cstring>
#include <memory>

#include "raster/setup_lanes.hpp"
#include "raster/tile_layout.hpp"
#include "raster/visibility_kernel.hpp"
#include "render/blend_pass.hpp"
#include "render/frame.hpp"
#include "render/mask_pass.hpp"
#include "render/target_streaming.hpp"
#include "render/tile_context.hpp"
#include "render/tile_records.hpp"
#include "render/tile_resolve.hpp"
#include "render/tile_traversal.hpp"

namespace zraster::detail {
namespace {

// Rows of the cleared values: copied into the targets of empty tiles (depth decoded), and into
// a drawn tile's own depths (depth as stored: encoded for D24 and D16, whose LESS test would
// otherwise see a clear depth of about 1/2^24 and pass nothing).
struct ClearRows {
    float stored = 0.0f;  // the clear depth as stored
    float depth[kTileSize], stored_depth[kTileSize];
    std::uint32_t background[kTileSize];
};

ClearRows clear_rows(const RenderOptions& options, const DepthBuffer& codec) {
    ClearRows rows;
    const bool d32 = options.depth_format == DepthFormat::D32F;
    rows.stored = d32 ? depth_clear_value(options)
                      : static_cast<float>(codec.encode(depth_clear_value(options)));
    std::fill_n(rows.depth, kTileSize,
                d32 ? rows.stored : codec.decode(static_cast<std::uint32_t>(rows.stored)));
    std::fill_n(rows.stored_depth, kTileSize, rows.stored);
    const std::uint8_t rgba[4] = {static_cast<std::uint8_t>(to_unorm8_int(options.background.x)),
                                  static_cast<std::uint8_t>(to_unorm8_int(options.background.y)),
                                  static_cast<std::uint8_t>(to_unorm8_int(options.background.z)),
                                  255};
    std::uint32_t background;
    std::memcpy(&background, rgba, 4);
    std::fill_n(rows.background, kTileSize, background);
    return rows;
}

// The tile buffers at the start of a drawn tile: cleared depth, no triangle, no shade tag, depth
// bounds at the clear depth, and shading forward the background color.
void start_tile(const TileContext& c, const ClearRows& clear, TileBuffers& tile) {
    const TilePlan& plan = c.plan;
    const auto row_bytes = std::size_t(c.x1 - c.x0) * sizeof(float);
    for (int y = 0; y < c.y1 - c.y0; ++y) {
        std::memcpy(tile.depth + tile_index(0, y), clear.stored_depth, row_bytes);
        // Depth-only frames never read the refs.
        if (plan.shades() || plan.targets.ids)
            std::memset(tile.ref + tile_index(0, y), 0xff, row_bytes);  // kNoTriangle
        if (plan.tagged()) std::memset(tile.shade_tag + tile_index(0, y), 0, row_bytes);
        if (plan.shading == ShadingPath::TaggedForward)
            std::memcpy(tile.color + tile_index(0, y), clear.background,
                        std::size_t(c.x1 - c.x0) * sizeof(std::uint32_t));
    }
    // Blocks past the image edge are never drawn; their bound only has to be valid.
    std::fill_n(tile.farthest, std::size(tile.farthest), clear.stored);
}

// The tile's triangles, batch by batch: set up in lanes; small ones run as single kernel jobs
// straight from the lanes, the others go one by one to their traversal (or, blended, to the
// blend pass after the tile).
void draw_triangles(TileContext& c, std::size_t tile_number, TileBuffers& tile,
                    std::unique_ptr<TileBuffers>& side, std::vector<BlendTriangle>& blended) {
    const TilePlan& plan = c.plan;
    const Frame& frame = plan.frame;
    const bool blocks = plan.traversal == Traversal::Blocks;
    const bool tagged_records = blocks && plan.tagged();
    const auto setup_batch = plan.simd ? setup_lanes : setup_lanes_scalar;
    const auto run_lanes = plan.simd ? visibility_lanes : visibility_lanes_scalar;
    const BlockJob shared = shared_job(plan);
    const JobWindow window{c.x0, c.y0, c.x1, c.y1, kSingleJobColumns};
    // While small triangles' hierarchical z tests are worth making, rasterize_blocks makes
    // them. (Only triangles that are not single jobs make bounded blocks.)
    const auto lanes_run = [&] {
        return plan.hiz == HierarchicalZ::Off || c.counts.bounded_blocks == 0 ||
               !c.counts.small_jobs.worth_testing();
    };
    TileRecordCursor cursor(frame, tile_number);
    RecordBatch batch;
    SetupLanes lanes;
    VertexLanes vertices;
    LaneJobs jobs;
    jobs.lanes = &lanes;
    TriangleSetup setup;
    while (!cursor.done()) {
        cursor.next(batch);
        const int count = batch.count;
        for (int lane = 0; lane < count; ++lane)
            for (int k = 0; k < 3; ++k)
                vertices.set_vertex(k, lane, batch.entry(lane).vertices[std::size_t(k)]);
        setup_batch(vertices, count, frame.setup_settings, lanes, blocks ? &window : nullptr);
        for (int lane = 0; lane < count; ++lane) {
            const Chunk& chunk = frame.chunks[batch.chunk[lane]];
            const std::uint32_t local = batch.entry(lane).ref & ~BinEntry::kClippedPiece;
            jobs.ref[lane] = triangle_reference(batch.chunk[lane], local);
            // Alpha-tested and blended triangles go their own ways (below), not the lanes'.
            if (plan.alpha_instances &&
                frame.instances[chunk.refs[local].instance].alpha != AlphaMode::Opaque)
                lanes.single_job[lane] = 0;
            const CornerAttributes* with = nullptr;
            const glm::vec3* piece = nullptr;
            if (tagged_records) {
                with = &batch.corners(lane);
                if (with->tag == 0) {
                    with = nullptr;
                    c.counts.untagged = true;
                } else if (batch.entry(lane).ref & BinEntry::kClippedPiece) {
                    piece = chunk.pieces[chunk.refs[local].piece].weights.data();
                }
            }
            // The deferred pass reads the ref of every pixel the triangle keeps (unless
            // tagged); fetching it now, while the tile rasterizes, saves a cache miss there
            // (refs are read in bin order here but in pixel order there).
            if (blocks && plan.shades() && with == nullptr) __builtin_prefetch(&chunk.refs[local]);
            jobs.corners[lane] = with;
            jobs.piece[lane] = piece;
            jobs.shade_constants[lane] =
                with != nullptr && plan.shading == ShadingPath::TaggedForward
                    ? &frame.phong_constants[(with->tag & ~kShadeFlip) - 1]
                    : nullptr;
        }
        for (int lane = 0; lane < count; ++lane) {
            if (blocks && lanes_run()) {
                const LaneJobsDone done = run_lanes(jobs, lane, count, shared, tile);
                c.counts.passed += done.passed;
                c.counts.shaded_forward += done.passed_shaded;
                lane = done.next;
                if (lane == count) break;
            }
            // The front end kept the triangle on the same decision.
            [[maybe_unused]] const SetupResult visible =
                load_setup(vertices, lanes, lane, frame.setup_settings, setup);
            assert(visible == SetupResult::Visible);
            const std::uint32_t id = jobs.ref[lane];
            const Chunk& chunk = frame.chunks[batch.chunk[lane]];
            const TileTriangle triangle{chunk,
                                        chunk.refs[reference_local(id)],
                                        setup,
                                        id,
                                        jobs.corners[lane],
                                        jobs.piece[lane],
                                        jobs.shade_constants[lane]};
            const AlphaMode alpha = plan.alpha_instances
                                        ? frame.instances[triangle.ref.instance].alpha
                                        : AlphaMode::Opaque;
            if (alpha == AlphaMode::Blend) {  // drawn after the tile (blend_pass.hpp)
                if (plan.targets.color)
                    blended.push_back({batch.chunk[lane], reference_local(id), setup});
            } else if (alpha == AlphaMode::Mask) {  // alpha-tested (mask_pass.hpp)
                if (blocks) {
                    if (!side) side = make_side_buffer();
                    c.counts.passed += rasterize_masked(c, triangle, tile, *side);
                } else {
                    c.counts.passed += rasterize_scalar(c, triangle, tile, c.x0, c.y0, c.x1, c.y1);
                }
                c.counts.untagged = true;
            } else if (!blocks) {
                c.counts.passed += rasterize_scalar(c, triangle, tile, c.x0, c.y0, c.x1, c.y1);
            } else {
                const std::uint64_t kept = rasterize_blocks(c, triangle, tile);
                c.counts.passed += kept;
                if (triangle.shade_constants != nullptr) c.counts.shaded_forward += kept;
            }
        }
    }
}

// The frame's per-tile counts, summed into the stats in tile order.
struct TileTotals {
    std::vector<std::uint64_t>& passed;
    std::vector<std::uint64_t>& shaded;
    std::vector<std::uint64_t>& hidden;
    std::vector<std::uint8_t>& deferred;  // some pixels shaded deferred
    std::vector<TileAlphaCounts>& alpha;  // empty without alpha-tested or blended instances
};

// Draws one tile with something binned to it, start to finish.
void draw_tile(const TilePlan& plan, std::size_t tile_number, const ClearRows& clear,
               TileContext& c, SlotScratch& slot, TileTotals& totals) {
    if (!slot.tile) slot.tile = std::make_unique<TileBuffers>();  // (one-shot frames)
    TileBuffers& tile = *slot.tile;
    start_tile(c, clear, tile);
    std::vector<BlendTriangle>& blended = slot.blend.triangles;
    blended.clear();
    draw_triangles(c, tile_number, tile, slot.side, blended);
    // (Resolved in every path: the depth and id targets are written there.)
    const std::uint64_t shaded_deferred = resolve_tile(c, tile, clear.background);
    totals.passed[tile_number] = c.counts.passed;
    totals.shaded[tile_number] = plan.shading == ShadingPath::ScalarForward
                                     ? c.counts.passed
                                     : c.counts.shaded_forward + shaded_deferred;
    if (!blended.empty()) {
        if (!slot.side) slot.side = make_side_buffer();
        const BlendCounts counts = composite_blended(c, tile, *slot.side, slot.blend);
        totals.alpha[tile_number].blended_fragments = counts.fragments;
        totals.alpha[tile_number].blended_pixels = counts.pixels;
    }
    totals.deferred[tile_number] =
        plan.resolves_then_shades() &&
        (plan.shading != ShadingPath::TaggedForward || c.counts.untagged);
    totals.hidden[tile_number] = c.counts.blocks_hidden;
    if (!totals.alpha.empty()) totals.alpha[tile_number].discarded = c.counts.alpha_discarded;
}

// Which of the targets' tiles already hold the cleared values (ClearedTiles), and the
// signature this frame leaves them with. Returns the per-tile flags to keep up to date, or
// null when every empty tile must be written.
std::uint8_t* cleared_tiles_for(Frame& frame, const ClearRows& clear,
                                ClearedTiles::Signature& signature) {
    const RenderOptions& options = *frame.options;
    const FrameTargets& targets = frame.targets;
    ClearedTiles& cleared_tiles = frame.cleared_tiles;
    signature.width = options.width;
    signature.height = options.height;
    signature.format = options.depth_format;
    std::memcpy(&signature.clear_bits, &clear.stored, sizeof(float));
    signature.background = targets.color ? clear.background[0] : 0;
    const TargetViews& views = targets.views;
    signature.color = views.color;
    signature.depth = views.depth;
    signature.normal = views.normal;
    signature.instance_id = views.instance_id;
    signature.primitive_id = views.primitive_id;
    signature.color_pitch = views.color_pitch;
    signature.depth_pitch = views.depth_pitch;
    signature.normal_pitch = views.normal_pitch;
    signature.instance_id_pitch = views.instance_id_pitch;
    signature.primitive_id_pitch = views.primitive_id_pitch;
    if (targets.kept) {
        const std::size_t tiles = std::size_t(frame.tiles_x) * std::size_t(frame.tiles_y);
        const bool reuse_cleared = cleared_tiles.valid && cleared_tiles.signature == signature;
        if (!reuse_cleared) cleared_tiles.cleared.assign(tiles, 0);
        cleared_tiles.valid = false;  // until every tile is written
        return cleared_tiles.cleared.data();
    }
    if (cleared_tiles.valid && cleared_tiles.signature.shares_an_array_with(signature))
        cleared_tiles.valid = false;  // this frame changes what the kept tiles hold
    return nullptr;
}

}  // namespace

void rasterize_tiles(Frame& frame, RenderStats& stats) {
    const RenderOptions& options = *frame.options;
    const FrameTargets& targets = frame.targets;
    const int width = options.width, height = options.height;

    // (A 1x1 buffer as the codec, kept: a frame allocates nothing.)
    if (!frame.depth_codec || frame.depth_codec->format() != options.depth_format)
        frame.depth_codec.emplace(1, 1, options.depth_format);
    const DepthBuffer& codec = *frame.depth_codec;
    const CompareFunc compare = effective_depth_compare(options);
    const ShadingPath shading = choose_shading_path(options, targets, frame.tagged_shading);
    const Traversal traversal = choose_traversal(options, targets, shading);
    // Without depth writes the stored depths stay the clear value: nothing to gain.
    const HierarchicalZ hiz =
        traversal == Traversal::Blocks && options.depth_write && options.hierarchical_z
            ? hierarchical_z_mode(compare)
            : HierarchicalZ::Off;
    stats.simd_target = options.simd ? visibility_kernel_target() : "scalar";
    const ClearRows clear = clear_rows(options, codec);

    const std::size_t tiles = std::size_t(frame.tiles_x) * std::size_t(frame.tiles_y);
    ClearedTiles::Signature signature;
    std::uint8_t* const cleared = cleared_tiles_for(frame, clear, signature);
    TileTotals totals{frame.tile_passed, frame.tile_shaded, frame.tile_hidden, frame.tile_deferred,
                      frame.tile_alpha};
    totals.alpha.assign(frame.alpha_instances ? tiles : 0, TileAlphaCounts{});
    totals.passed.assign(tiles, 0);
    totals.shaded.assign(tiles, 0);
    totals.hidden.assign(tiles, 0);
    totals.deferred.assign(tiles, 0);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const std::size_t target_bytes =
        ((targets.views.depth != nullptr ? pixels : 0) + (targets.color ? pixels : 0)) *
        sizeof(float);
    const TilePlan plan{frame,
                        targets,
                        codec,
                        compare,
                        shading,
                        traversal,
                        options.simd,
                        hiz,
                        stream_targets(frame, target_bytes),
                        frame.alpha_instances,
                        frame.hiz_block_counts};
    tbb::parallel_for(std::size_t{0}, tiles, [&](std::size_t tile_number) {
        // Streamed target rows (TilePlan::write_row) are ordered before whatever reads them
        // after the loop.
        struct FenceOnExit {
            bool stream;
            ~FenceOnExit() {
                if (stream) stream_fence();
            }
        } fence_on_exit{plan.stream_targets};
        const int tx = int(tile_number % std::size_t(frame.tiles_x));
        const int ty = int(tile_number / std::size_t(frame.tiles_x));
        TileContext c{plan,
                      tx * kTileSize,
                      ty * kTileSize,
                      std::min(width, (tx + 1) * kTileSize),
                      std::min(height, (ty + 1) * kTileSize),
                      {}};
        if (targets.coverage) clear_tile_counts(c);
        if (frame.tile_bin_counts[tile_number] == 0) {
            // Nothing drawn here: write the cleared targets directly, unless they hold them.
            if (cleared == nullptr || !cleared[tile_number])
                clear_tile_targets(c, clear.depth, clear.background);
            if (cleared != nullptr) cleared[tile_number] = 1;
            return;
        }
        if (cleared != nullptr) cleared[tile_number] = 0;
        draw_tile(plan, tile_number, clear, c, frame.slot(), totals);
    });
    // Edges are drawn over the targets after this, across empty tiles too.
    if (targets.kept) {
        frame.cleared_tiles.valid = options.edges == RenderOptions::Edges::None;
        frame.cleared_tiles.signature = signature;
    }
    for (std::size_t t = 0; t < tiles; ++t) {
        stats.deferred |= totals.deferred[t] != 0;
        stats.fragments_passed += totals.passed[t];
        stats.fragments_shaded += totals.shaded[t];
        stats.blocks_hidden += totals.hidden[t];
    }
    for (const TileAlphaCounts& counts : totals.alpha) {
        stats.fragments_alpha_discarded += counts.discarded;
        stats.fragments_blended += counts.blended_fragments;
        stats.pixels_blended += counts.blended_pixels;
    }
}

}  // namespace zraster::detail
