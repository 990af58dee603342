// The back end: per tile, in parallel. Each tile owns its pixels and walks the chunks' bins in
// submission order, so tiles can run on any thread in any order and the image stays the same.
//
// Inside a tile each triangle is traversed in 8x8 blocks: a block is rejected or fully accepted
// from the edge functions at its corners before any per-pixel work, and the pixels of the rest
// go through the SIMD visibility kernel. Shading is deferred by default: the tile first resolves
// visibility (depth, triangle reference, barycentrics per pixel), then shades each visible pixel
// once. Formats and options the kernel does not cover take the scalar reference path.
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>

#include "memory/huge_pages.hpp"
#include "raster/setup_lanes.hpp"
#include "raster/visibility_kernel.hpp"
#include "render/blend_pass.hpp"
#include "render/frame.hpp"
#include "render/hierarchical_z.hpp"
#include "render/shade_fragment.hpp"
#include "render/stream_lines.hpp"
#include "render/target_streaming.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {
namespace {

constexpr int kLocalBits = 20;  // a pixel's triangle reference: chunk << 20 | index in chunk
// Hierarchical z refreshes a block's bound after a triangle wrote at least this many fragments
// there (or covered it whole).
constexpr int kRefreshAfterFragments = 8;
// A small triangle at most this many pixels wide in the tile is one kernel job (see below).
constexpr int kSingleJobColumns = 32;
// How far ahead of the record being set up the back end prefetches the tile's records.
constexpr std::size_t kRecordPrefetchBytes = 2048;

// Round to nearest (+ 0.5 and truncate: much cheaper than lround), as the SIMD shader does.
std::uint8_t to_unorm8(float v) {
    return static_cast<std::uint8_t>(to_unorm8_int(v));
}

// Hierarchical z and small triangles (one kernel job each): their bound refreshes cost about
// what the kernel spends on such a job, so they are not made (their writes leave the bounds
// stale, still valid), and their tests stop in a tile where fewer than half of the first 64
// hid their job. Measured 2026-11-24 against refreshing and testing every job: raster time of
// the bunny -20% (depth) and -12% (Phong), sphere:1000000 -10%, city:20000 and soup:1000000
// even; 100 large walls in random order (where hierarchical z saves a third) 4% slower. Larger
// triangles keep both: behind large occluders their blocks are what it saves.
struct SmallJobsHiz {
    static constexpr int kJudgeAfter = 64;
    int tests = 0, hidden = 0;
    bool worth_testing() const { return tests < kJudgeAfter || 2 * hidden >= tests; }
};

struct TileContext {
    const Frame& frame;
    const FrameTargets& targets;
    const DepthBuffer& codec;  // encodes/decodes the depth format
    CompareFunc compare;
    bool kernel;                     // the block traversal with the visibility kernel may be used
    bool simd;                       // ... in its SIMD version
    bool forward;                    // shade as fragments pass (scalar path)
    HierarchicalZ hiz;               // per-block depth bounds in use (kernel path, depth writes on)
    std::uint64_t& blocks_hidden;    // this tile's count of blocks skipped by them
    std::uint64_t& alpha_discarded;  // this tile's alpha-tested fragments under the cutoff
    // How many of the tile's blocks have a bound nearer than the clear depth: until one has,
    // no test can hide anything and none is made (a mesh of small triangles rarely covers a
    // whole block in one write).
    int& bounded_blocks;
    SmallJobsHiz& small_jobs;
    bool shade;           // color or normal target wanted
    bool tagged_shading;  // SIMD Phong instances interpolate in the kernel (see below)
    bool stream_targets;  // rows go to the targets with non-temporal stores (see below)
    int x0, y0, x1, y1;   // tile rectangle in the image, [x0, x1) x [y0, y1)

    // Copies a row into a target.
    void write_row(void* to, const void* from, std::size_t bytes) const {
        if (stream_targets)
            stream_copy(to, from, bytes);
        else
            std::memcpy(to, from, bytes);
    }
};

std::size_t tile_index(int x, int y) {
    return static_cast<std::size_t>(y * TileBuffers::kStride + x);
}

void write_shaded(const TileContext& c, const ShadedFragment& f, int px, int py) {
    const TargetViews& t = c.targets.views;
    if (t.color != nullptr) {
        std::uint8_t* rgba = target_row(t.color, t.color_pitch, py) + std::size_t(px) * 4;
        rgba[0] = to_unorm8(f.color.x);
        rgba[1] = to_unorm8(f.color.y);
        rgba[2] = to_unorm8(f.color.z);
        rgba[3] = 255;
    }
    if (t.normal != nullptr) target_row(t.normal, t.normal_pitch, py)[px] = f.normal;
}

// Counts a fragment in the front or back hits target (when given).
void count_hit(const TileContext& c, bool front_facing, int px, int py) {
    const TargetViews& t = c.targets.views;
    std::uint32_t* hits = front_facing ? t.front_hits : t.back_hits;
    if (hits != nullptr)
        ++target_row(hits, front_facing ? t.front_hits_pitch : t.back_hits_pitch, py)[px];
}

// The scalar reference path for one triangle over [x0, x1) x [y0, y1) of a tile: any depth
// format, the depth test off, coverage counts, forward shading.
std::uint64_t rasterize_scalar(const TileContext& c, const Chunk& chunk, const TriangleRef& ref,
                               const TriangleSetup& setup, std::uint32_t id,
                               const CornerAttributes* corners, const glm::vec3* piece,
                               const PhongConstants* shade_constants, TileBuffers& tile, int x0,
                               int y0, int x1, int y1) {
    const RenderOptions& options = *c.frame.options;
    const FrameInstance& instance = c.frame.instances[ref.instance];
    const bool alpha_test = instance.alpha == AlphaMode::Mask;
    ShadingTriangle shading;
    if ((c.forward && c.shade) || alpha_test)
        prepare_shading_triangle(c.frame, chunk, ref, shading);
    std::uint64_t passed = 0;
    for_each_covered_pixel(setup, x0, y0, x1, y1, [&](int px, int py) {
        const std::size_t at = tile_index(px - c.x0, py - c.y0);
        float code = 0.0f;
        if (options.depth_test) {
            const float z = depth_at(setup, px, py);
            code =
                c.codec.format() == DepthFormat::D32F ? z : static_cast<float>(c.codec.encode(z));
            if (!DepthBuffer::passes(code, tile.depth[at], c.compare)) return;
        }
        const glm::vec3 b = barycentrics(setup, px, py, options.interpolation);
        // The alpha test, before the fragment writes depth (alpha NaN: discarded).
        if (alpha_test && !(fragment_alpha(c.frame, shading, b.y, b.z, px, py) >=
                            instance.material->alpha_cutoff)) {
            ++c.alpha_discarded;
            return;
        }
        if (options.depth_test && options.depth_write) tile.depth[at] = code;
        ++passed;
        if (c.targets.coverage) count_hit(c, ref.front_facing, px, py);
        tile.ref[at] = id;
        tile.b1[at] = b.y;
        tile.b2[at] = b.z;
        tile.shade_tag[at] = corners ? corners->tag : 0;
        if (corners && shade_constants)  // forward, as the kernel does
            tile.color[at] = shade_interpolated_scalar(*shade_constants, *corners, piece, b.y, b.z);
        else if (corners)
            store_interpolated(*corners, piece, b.y, b.z, tile, at);
        if (c.forward && c.shade)
            write_shaded(c, shade_fragment(c.frame, shading, b.y, b.z, px, py, c.targets.normal),
                         px, py);
    });
    return passed;
}

std::int64_t edge_at(const TriangleSetup& t, std::size_t k, int px, int py) {
    return t.edge_a[k] * px + t.edge_b[k] * py + t.edge_c[k];
}

bool fits_int32(std::int64_t v) {
    return v >= std::numeric_limits<std::int32_t>::min() &&
           v <= std::numeric_limits<std::int32_t>::max();
}

// What the kernel jobs of all triangles in the tile share.
BlockJob shared_job(const TileContext& c) {
    const RenderOptions& options = *c.frame.options;
    BlockJob job;
    job.perspective = options.interpolation == Interpolation::PerspectiveCorrect;
    job.compare = c.compare;
    job.write_depth = options.depth_write;
    job.attributes = c.shade || c.targets.ids;
    job.barycentrics = c.shade;
    return job;
}

// Hierarchical traversal of one triangle in one tile: 8x8 blocks classified by their corners,
// then the visibility kernel on the covered or partly covered ones.
std::uint64_t rasterize_blocks(const TileContext& c, const Chunk& chunk, const TriangleRef& ref,
                               const TriangleSetup& setup, std::uint32_t id,
                               const CornerAttributes* corners, const glm::vec3* piece,
                               const PhongConstants* shade_constants, TileBuffers& tile) {
    const int rx0 = std::max(setup.min_x, c.x0), ry0 = std::max(setup.min_y, c.y0);
    const int rx1 = std::min(setup.max_x, c.x1 - 1), ry1 = std::min(setup.max_y, c.y1 - 1);
    BlockJob job = shared_job(c);
    job.planes = {setup.depth, setup.q, setup.p1, setup.p2, setup.l1, setup.l2};
    job.corners = corners;
    job.piece = piece;
    job.shade_constants = shade_constants;
    job.ref = id;
    // Runs the kernel on pixels [x0, x1] x [y0, y1] of the triangle (edge values there fit 32
    // bits), unless hierarchical z shows them hidden; then refreshes the blocks' depth bounds.
    // Edges in `inside` (bit k: edge k) are non-negative over the whole block: the kernel gets
    // zero for them (their values far inside a large triangle need not fit 32 bits).
    // `small`: the whole triangle is this one job (see below).
    const auto run_block = [&]<bool small>(int x0, int y0, int x1, int y1, bool full,
                                           unsigned inside) -> std::uint64_t {
        const int bx0 = (x0 - c.x0) / kBlockSize, bx1 = (x1 - c.x0) / kBlockSize;
        const int by0 = (y0 - c.y0) / kBlockSize, by1 = (y1 - c.y0) / kBlockSize;
        const bool largest = c.hiz == HierarchicalZ::Largest;
        // A bound nearer than the clear depth (1, or 0 reversed): something was drawn there.
        const auto bounded = [largest](float bound) {
            return largest ? bound < 1.0f : bound > 0.0f;
        };
        if (c.hiz != HierarchicalZ::Off && c.bounded_blocks > 0 &&
            (!small || c.small_jobs.worth_testing())) {
            float farthest = tile.farthest[by0 * TileBuffers::kBlocksPerRow + bx0];
            for (int by = by0; by <= by1; ++by)
                for (int bx = bx0; bx <= bx1; ++bx) {
                    const float f = tile.farthest[by * TileBuffers::kBlocksPerRow + bx];
                    farthest = largest ? std::max(farthest, f) : std::min(farthest, f);
                }
            // Blocks still at the far plane (1, or 0 reversed) hide nothing worth the test.
            const bool drawn = bounded(farthest);
            c.small_jobs.tests += small && drawn;
            if (drawn && block_hidden(setup.depth, x0 - setup.min_x, y0 - setup.min_y,
                                      x1 - setup.min_x, y1 - setup.min_y, farthest, c.compare)) {
                c.small_jobs.hidden += small;
                ++c.blocks_hidden;
                return 0;
            }
        }
        for (std::size_t k = 0; k < 3; ++k) {
            const bool zero = (inside >> k) & 1;
            job.e[k] = zero ? 0 : static_cast<std::int32_t>(edge_at(setup, k, x0, y0));
            job.step_x[k] = zero ? 0 : static_cast<std::int32_t>(setup.edge_a[k]);
            job.step_y[k] = zero ? 0 : static_cast<std::int32_t>(setup.edge_b[k]);
        }
        job.full = full;
        job.x0 = x0 - c.x0;
        job.y0 = y0 - c.y0;
        job.width = x1 - x0 + 1;
        job.height = y1 - y0 + 1;
        job.plane_dx = x0 - setup.min_x;
        job.plane_dy = y0 - setup.min_y;
        const int passed =
            c.simd ? visibility_block(job, tile) : visibility_block_scalar(job, tile);
        // A stale bound is still a bound (stored depths only move nearer): refresh it only
        // after real work, not after every 1-pixel triangle.
        if (c.hiz != HierarchicalZ::Off && !small && (full || passed >= kRefreshAfterFragments)) {
            for (int by = by0; by <= by1; ++by)
                for (int bx = bx0; bx <= bx1; ++bx) {
                    float& bound = tile.farthest[by * TileBuffers::kBlocksPerRow + bx];
                    const bool was_bounded = bounded(bound);
                    bound = c.simd ? block_farthest_depth(tile, bx, by, largest)
                                   : block_farthest_depth_scalar(tile, bx, by, largest);
                    c.bounded_blocks += !was_bounded && bounded(bound);
                }
        }
        return static_cast<std::uint64_t>(passed);
    };
    // Small triangles (vertices within 64 pixels each way, the common case) have edge values
    // that fit 32 bits anywhere near them (|E| <= 2^22 * 65 * 2 < 2^30), so one whose pixels in
    // the tile span at most kSingleJobColumns columns is one kernel job, whatever its height and
    // wherever it lies on the block grid: no corner tests, one call instead of one per block.
    // Running the kernel over the rows and vectors the triangle does not cover costs less than
    // a block's corner tests and call: measured 2026-11-24 against the job limit of 8 x 16, raster
    // time -25% on city:20000 (tall slivers of 5-10 blocks) and -20% on soup:1000000; 32
    // columns beat 16 and 64 there.
    const auto [lo_x, hi_x] = std::minmax({setup.x[0], setup.x[1], setup.x[2]});
    const auto [lo_y, hi_y] = std::minmax({setup.y[0], setup.y[1], setup.y[2]});
    if (hi_x - lo_x < kSingleJobExtent && hi_y - lo_y < kSingleJobExtent &&
        rx1 - rx0 < kSingleJobColumns)
        return run_block.template operator()<true>(rx0, ry0, rx1, ry1, false, 0);

    std::uint64_t passed = 0;
    const int first_by = c.y0 + (ry0 - c.y0) / kBlockSize * kBlockSize;
    const int first_bx = c.x0 + (rx0 - c.x0) / kBlockSize * kBlockSize;
    for (int by = first_by; by <= ry1; by += kBlockSize) {
        const int y0 = std::max(by, ry0), y1 = std::min(by + kBlockSize - 1, ry1);
        for (int bx = first_bx; bx <= rx1; bx += kBlockSize) {
            const int x0 = std::max(bx, rx0), x1 = std::min(bx + kBlockSize - 1, rx1);
            bool outside = false, full = true, fits = true;
            unsigned inside = 0;
            for (std::size_t k = 0; k < 3 && !outside; ++k) {
                // The extremes over the block's corners, from its first corner and the steps
                // across it (a linear function: each step's sign picks the corner).
                const std::int64_t e00 = edge_at(setup, k, x0, y0);
                const std::int64_t across_x = setup.edge_a[k] * (x1 - x0);
                const std::int64_t across_y = setup.edge_b[k] * (y1 - y0);
                const std::int64_t lo =
                    e00 + std::min<std::int64_t>(across_x, 0) + std::min<std::int64_t>(across_y, 0);
                const std::int64_t hi =
                    e00 + std::max<std::int64_t>(across_x, 0) + std::max<std::int64_t>(across_y, 0);
                outside = hi < 0;  // linear: negative at all corners means negative everywhere
                full &= lo >= 0;
                inside |= unsigned(lo >= 0) << k;
                // Only edges crossing the block are evaluated in 32-bit lanes.
                fits &= lo >= 0 || (fits_int32(lo) && fits_int32(hi) &&
                                    fits_int32(setup.edge_a[k]) && fits_int32(setup.edge_b[k]));
            }
            if (outside) continue;
            if (!fits && !full)  // edges too long for 32-bit lanes: the exact 64-bit scalar path
                passed += rasterize_scalar(c, chunk, ref, setup, id, corners, piece,
                                           shade_constants, tile, x0, y0, x1 + 1, y1 + 1);
            else
                passed += run_block.template operator()<false>(x0, y0, x1, y1, full, inside);
        }
    }
    return passed;
}

// The targets of a tile where nothing was drawn, from rows of the cleared values.
void clear_tile_targets(const TileContext& c, const float* clear_row,
                        const std::uint32_t* background_row) {
    const TargetViews& t = c.targets.views;
    const auto n = static_cast<std::size_t>(c.x1 - c.x0);
    const auto x0 = static_cast<std::size_t>(c.x0);
    for (int py = c.y0; py < c.y1; ++py) {
        if (t.depth != nullptr)
            c.write_row(target_row(t.depth, t.depth_pitch, py) + x0, clear_row, n * sizeof(float));
        if (t.color != nullptr)
            c.write_row(target_row(t.color, t.color_pitch, py) + x0 * 4, background_row, n * 4);
        if (t.normal != nullptr)
            std::fill_n(target_row(t.normal, t.normal_pitch, py) + x0, n, glm::vec3(0.0f));
        if (t.instance_id != nullptr)
            std::fill_n(target_row(t.instance_id, t.instance_id_pitch, py) + x0, n, -1);
        if (t.primitive_id != nullptr)
            std::fill_n(target_row(t.primitive_id, t.primitive_id_pitch, py) + x0, n, -1);
    }
}

// Zeroes a tile's rows of the coverage counts (they are counted up as fragments pass).
void clear_tile_counts(const TileContext& c) {
    const TargetViews& t = c.targets.views;
    const auto n = static_cast<std::size_t>(c.x1 - c.x0);
    const auto x0 = static_cast<std::size_t>(c.x0);
    for (int py = c.y0; py < c.y1; ++py) {
        if (t.front_hits != nullptr)
            std::fill_n(target_row(t.front_hits, t.front_hits_pitch, py) + x0, n, 0u);
        if (t.back_hits != nullptr)
            std::fill_n(target_row(t.back_hits, t.back_hits_pitch, py) + x0, n, 0u);
    }
}

// What the deferred pass needs of the triangle of the last pixel: consecutive pixels mostly
// share one, so the lookups (chunk, ref, instance: cache misses on dense meshes) are done once
// per run.
struct TriangleRun {
    std::uint32_t id = kNoTriangle;
    const Chunk* chunk = nullptr;
    const TriangleRef* ref = nullptr;
    std::int32_t instance_id = -1, primitive_id = -1;

    void load(const Frame& frame, std::uint32_t triangle) {
        id = triangle;
        chunk = &frame.chunks[triangle >> kLocalBits];
        ref = &chunk->refs[triangle & ((1u << kLocalBits) - 1)];
        instance_id = static_cast<std::int32_t>(frame.instances[ref->instance].scene_instance);
        primitive_id = static_cast<std::int32_t>(ref->primitive);
    }
};

// The normal target's value at a tagged pixel: what shade_fragment gives a Phong fragment, from
// the normal the kernel interpolated as shade_fragment interpolates it.
glm::vec3 tagged_normal(const TileBuffers& tile, std::size_t at) {
    const glm::vec3 n = unit_normal(glm::vec3(tile.nx[at], tile.ny[at], tile.nz[at]));
    return (tile.shade_tag[at] & kShadeFlip) != 0 ? -n : n;
}

// Finishes a tile: deferred shading of every pixel with a triangle (once each), background
// elsewhere, and the depth and id targets. With tagged shading, the SIMD shader colors the
// tagged pixels a row at a time, and only the others (other materials) go pixel by pixel.
// `untagged` says whether any triangle without a tag was drawn in the tile. Returns the number
// of pixels shaded.
std::uint64_t finish_tile(const TileContext& c, const TileBuffers& tile, std::uint32_t background,
                          const std::uint32_t* background_row, bool shade_now, bool untagged,
                          bool forward_tile) {
    const TargetViews& t = c.targets.views;
    const bool d32 = c.codec.format() == DepthFormat::D32F;
    const bool want_normal = c.targets.normal, want_ids = c.targets.ids;
    const bool want_color = c.targets.color;
    const bool tagged = shade_now && c.tagged_shading;
    // Pixel by pixel only where something needs it.
    const bool per_pixel =
        want_ids || (shade_now && (!tagged || untagged)) || (want_color && !tagged) || want_normal;
    ShadingTriangle cache;
    std::uint32_t cached_id = kNoTriangle;
    TriangleRun run;
    std::uint64_t shaded = 0;
    const int n = c.x1 - c.x0;
    std::uint32_t row_rgba[TileBuffers::kStride];
    for (int py = c.y0; py < c.y1; ++py) {
        const std::size_t at_row = tile_index(0, py - c.y0);
        // The rows of the targets (null where not wanted).
        const auto row = [py](auto* first_row, std::size_t pitch) {
            return first_row != nullptr ? target_row(first_row, pitch, py) : nullptr;
        };
        std::uint8_t* const color_row = row(t.color, t.color_pitch);
        glm::vec3* const normal_row = row(t.normal, t.normal_pitch);
        std::int32_t* const instance_row = row(t.instance_id, t.instance_id_pitch);
        std::int32_t* const primitive_row = row(t.primitive_id, t.primitive_id_pitch);
        if (t.depth != nullptr) {
            float* const depth_row = target_row(t.depth, t.depth_pitch, py);
            if (d32) {
                c.write_row(depth_row + c.x0, tile.depth + at_row, std::size_t(n) * sizeof(float));
            } else {
                for (int i = 0; i < n; ++i)
                    depth_row[c.x0 + i] = c.codec.decode(
                        static_cast<std::uint32_t>(tile.depth[at_row + std::size_t(i)]));
            }
        }
        if (tagged && forward_tile) {  // lit as they passed
            c.write_row(color_row + std::size_t(c.x0) * 4, tile.color + at_row,
                        std::size_t(n) * sizeof(std::uint32_t));
        } else if (tagged && want_color) {
            // (A copy, not a fill: GCC at -O2 fills element by element.)
            std::memcpy(row_rgba, background_row, std::size_t(n) * sizeof(std::uint32_t));
            shaded += std::uint64_t(
                shade_tagged_row(c.frame.phong_constants.data(), tile, at_row, n, row_rgba));
            c.write_row(color_row + std::size_t(c.x0) * 4, row_rgba,
                        std::size_t(n) * sizeof(std::uint32_t));
        }
        if (!per_pixel) continue;
        for (int px = c.x0; px < c.x1; ++px) {
            const std::size_t at = at_row + std::size_t(px - c.x0);
            const std::uint32_t id = tile.ref[at];
            if (id == kNoTriangle) {
                if (want_color && !tagged)
                    std::memcpy(color_row + std::size_t(px) * 4, &background, 4);
                if (want_normal) normal_row[px] = glm::vec3(0.0f);
                if (instance_row != nullptr) instance_row[px] = -1;
                if (primitive_row != nullptr) primitive_row[px] = -1;
                continue;
            }
            if (tagged && tile.shade_tag[at] != 0) {
                if (want_normal) normal_row[px] = tagged_normal(tile, at);
                shaded += !want_color;  // (counted by shade_tagged_row otherwise)
                if (!want_ids) continue;
            }
            if (id != run.id) run.load(c.frame, id);
            if (instance_row != nullptr) instance_row[px] = run.instance_id;
            if (primitive_row != nullptr) primitive_row[px] = run.primitive_id;
            if (!shade_now || (tagged && tile.shade_tag[at] != 0)) continue;
            ++shaded;
            if (id != cached_id) {
                prepare_shading_triangle(c.frame, *run.chunk, *run.ref, cache);
                cached_id = id;
            }
            write_shaded(
                c, shade_fragment(c.frame, cache, tile.b1[at], tile.b2[at], px, py, want_normal),
                px, py);
        }
    }
    return shaded;
}

}  // namespace

void rasterize_tiles(Frame& frame, RenderStats& stats) {
    const RenderOptions& options = *frame.options;
    const FrameTargets& targets = frame.targets;
    ClearedTiles& cleared_tiles = frame.cleared_tiles;
    const int width = options.width, height = options.height;

    // (A 1x1 buffer as the codec, kept: a frame allocates nothing.)
    if (!frame.depth_codec || frame.depth_codec->format() != options.depth_format)
        frame.depth_codec.emplace(1, 1, options.depth_format);
    const DepthBuffer& codec = *frame.depth_codec;
    const float clear = options.depth_format == DepthFormat::D32F
                            ? depth_clear_value(options)
                            : static_cast<float>(codec.encode(depth_clear_value(options)));
    const CompareFunc compare = effective_depth_compare(options);
    const bool shade = targets.color || targets.normal;
    // Tagged shading: triangles of SIMD Phong instances interpolate their attributes in the
    // visibility kernel; the kernel lights them as they pass (forward) or the deferred pass
    // shades them a vector at a time and writes the normal target from the kernel's normals.
    const bool tagged = frame.tagged_shading;
    // Forward shading otherwise goes the scalar way, fragment by fragment.
    const bool forward = shade && options.strategy == ShadingStrategy::Forward && !tagged;
    // The block kernel covers the common case; the rest takes the scalar reference path.
    const bool kernel = options.depth_format == DepthFormat::D32F && options.depth_test &&
                        !targets.coverage && !forward;
    // Without depth writes the stored depths stay the clear value: nothing to gain.
    const HierarchicalZ hiz = kernel && options.depth_write && options.hierarchical_z
                                  ? hierarchical_z_mode(compare)
                                  : HierarchicalZ::Off;
    const std::uint8_t background_rgba[4] = {to_unorm8(options.background.x),
                                             to_unorm8(options.background.y),
                                             to_unorm8(options.background.z), 255};
    std::uint32_t background;
    std::memcpy(&background, background_rgba, 4);
    stats.simd_target = options.simd ? visibility_kernel_target() : "scalar";

    // Rows of cleared values, copied into the targets of empty tiles (decoded depth), and into
    // the tile's own depths (stored: encoded for D24 and D16, whose LESS test would otherwise
    // see a clear depth of about 1/2^24 and pass nothing).
    float clear_row[kTileSize], stored_clear_row[kTileSize];
    std::uint32_t background_row[kTileSize];
    std::fill_n(clear_row, kTileSize,
                options.depth_format == DepthFormat::D32F
                    ? clear
                    : codec.decode(static_cast<std::uint32_t>(clear)));
    std::fill_n(stored_clear_row, kTileSize, clear);
    std::fill_n(background_row, kTileSize, background);

    const std::size_t tiles = std::size_t(frame.tiles_x) * std::size_t(frame.tiles_y);
    // Empty tiles that already hold the cleared values (the previous frame into the same
    // targets, same clear values, kept since) are left as they are. Other targets are written
    // whole.
    ClearedTiles::Signature signature;
    signature.width = width;
    signature.height = height;
    signature.format = options.depth_format;
    std::memcpy(&signature.clear_bits, &clear, sizeof(float));
    signature.background = targets.color ? background : 0;
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
    std::uint8_t* cleared = nullptr;  // null: write every empty tile
    if (targets.kept) {
        const bool reuse_cleared = cleared_tiles.valid && cleared_tiles.signature == signature;
        if (!reuse_cleared) cleared_tiles.cleared.assign(tiles, 0);
        cleared_tiles.valid = false;  // until every tile is written
        cleared = cleared_tiles.cleared.data();
    } else if (cleared_tiles.valid && cleared_tiles.signature.shares_an_array_with(signature)) {
        cleared_tiles.valid = false;  // this frame changes what the kept tiles hold
    }
    std::vector<std::uint64_t>& passed_per_tile = frame.tile_passed;
    std::vector<std::uint64_t>& shaded_per_tile = frame.tile_shaded;
    std::vector<std::uint64_t>& hidden_per_tile = frame.tile_hidden;
    std::vector<std::uint8_t>& deferred_per_tile = frame.tile_deferred;  // some shaded deferred
    std::vector<TileAlphaCounts>& alpha_per_tile = frame.tile_alpha;
    // (A local: the loops below would read the frame's flag again for every triangle.)
    const bool alpha_instances = frame.alpha_instances;
    alpha_per_tile.assign(alpha_instances ? tiles : 0, TileAlphaCounts{});
    passed_per_tile.assign(tiles, 0);
    shaded_per_tile.assign(tiles, 0);
    hidden_per_tile.assign(tiles, 0);
    deferred_per_tile.assign(tiles, 0);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const std::size_t target_bytes =
        ((targets.views.depth != nullptr ? pixels : 0) + (targets.color ? pixels : 0)) *
        sizeof(float);
    const bool stream = stream_targets(frame, target_bytes);
    tbb::parallel_for(std::size_t{0}, tiles, [&](std::size_t tile_number) {
        // Streamed target rows (TileContext::write_row) are ordered before whatever reads them
        // after the loop.
        struct FenceOnExit {
            bool stream;
            ~FenceOnExit() {
                if (stream) stream_fence();
            }
        } fence_on_exit{stream};
        SlotScratch& slot = frame.slot();
        if (!slot.tile) slot.tile = std::make_unique<TileBuffers>();  // (one-shot frames)
        TileBuffers& tile = *slot.tile;
        const int tx = int(tile_number % std::size_t(frame.tiles_x));
        const int ty = int(tile_number / std::size_t(frame.tiles_x));
        int bounded_blocks = 0;
        std::uint64_t unused_count = 0;  // (frames without alpha-tested instances)
        SmallJobsHiz small_jobs;
        const TileContext c{
            frame,
            targets,
            codec,
            compare,
            kernel,
            options.simd,
            forward,
            hiz,
            hidden_per_tile[tile_number],
            alpha_per_tile.empty() ? unused_count : alpha_per_tile[tile_number].discarded,
            bounded_blocks,
            small_jobs,
            shade,
            tagged,
            stream,
            tx * kTileSize,
            ty * kTileSize,
            std::min(width, (tx + 1) * kTileSize),
            std::min(height, (ty + 1) * kTileSize)};
        const std::size_t chunks = frame.chunks.size();
        // The tile's run in each chunk (see Frame::bin_run_offsets).
        const std::size_t* run_offset = frame.bin_run_offsets.data() + tile_number * chunks;
        const std::uint32_t* run_count = frame.bin_run_counts.data() + tile_number * chunks;
        if (targets.coverage) clear_tile_counts(c);
        const bool empty = frame.tile_bin_counts[tile_number] == 0;
        if (empty) {
            // Nothing drawn here: write the cleared targets directly, unless they hold them.
            if (cleared == nullptr || !cleared[tile_number])
                clear_tile_targets(c, clear_row, background_row);
            if (cleared != nullptr) cleared[tile_number] = 1;
            return;
        }
        if (cleared != nullptr) cleared[tile_number] = 0;
        const auto row_bytes = std::size_t(c.x1 - c.x0) * sizeof(float);
        for (int y = 0; y < c.y1 - c.y0; ++y) {
            std::memcpy(tile.depth + tile_index(0, y), stored_clear_row, row_bytes);
            // Depth-only frames never read the refs.
            if (shade || targets.ids)
                std::memset(tile.ref + tile_index(0, y), 0xff, row_bytes);  // kNoTriangle
            if (tagged) std::memset(tile.shade_tag + tile_index(0, y), 0, row_bytes);
        }
        // Blocks past the image edge are never drawn; their bound only has to be valid.
        std::fill_n(tile.farthest, std::size(tile.farthest), clear);
        // Forward with tagged shading: the kernel lights the fragments as they pass. (Not
        // Auto's choice: measured slower than deferred even on large, barely overlapping
        // triangles; see docs/architecture.md.)
        const bool forward_tile = tagged && options.strategy == ShadingStrategy::Forward;
        if (forward_tile)
            for (int y = 0; y < c.y1 - c.y0; ++y)
                std::memcpy(tile.color + tile_index(0, y), background_row,
                            std::size_t(c.x1 - c.x0) * sizeof(std::uint32_t));
        std::uint64_t shaded_forward = 0;

        std::uint64_t passed = 0;
        bool untagged = false;  // a triangle without a shade tag was drawn
        std::vector<BlendTriangle>& blended = slot.blend.triangles;
        blended.clear();
        TriangleSetup setup;
        // The tile's entries, kSetupLanes at a time (set up together), the chunks in order.
        // Small triangles are single jobs (see rasterize_blocks), which the setup computes in
        // lanes and the kernel runs straight from them; the others take rasterize_blocks.
        SetupLanes lanes;
        VertexLanes vertices;
        LaneJobs jobs;
        jobs.lanes = &lanes;
        const BlockJob shared_lane_job = shared_job(c);
        const JobWindow window{c.x0, c.y0, c.x1, c.y1, kSingleJobColumns};
        const auto setup_block = options.simd ? setup_lanes : setup_lanes_scalar;
        const auto run_lanes = options.simd ? visibility_lanes : visibility_lanes_scalar;
        // While small triangles' hierarchical z tests are worth making, rasterize_blocks makes
        // them. (Only triangles that are not single jobs make bounded blocks.)
        const auto lanes_run = [&] {
            return hiz == HierarchicalZ::Off || bounded_blocks == 0 || !small_jobs.worth_testing();
        };
        const std::byte* lane_record[kSetupLanes];
        std::uint32_t lane_chunk_index[kSetupLanes];
        // A cursor over the tile's records: run by run, chunks in order.
        const std::byte* records = frame.bin_records();
        const std::size_t record_bytes = frame.bin_record_bytes;
        std::size_t ci = 0, left = 0;
        const std::byte* next_record = nullptr;
        const auto next_run = [&] {
            while (ci < chunks && run_count[ci] == 0) ++ci;
            if (ci == chunks) return;
            next_record = records + run_offset[ci];
            left = run_count[ci];
        };
        next_run();
        for (std::size_t remaining = frame.tile_bin_counts[tile_number]; remaining > 0;) {
            const int count = int(std::min<std::size_t>(remaining, kSetupLanes));
            remaining -= std::size_t(count);
            for (int lane = 0; lane < count; ++lane) {
                lane_record[lane] = next_record;
                // Every line of the record 2 KiB ahead: the runs were streamed out past the
                // caches, and the hardware prefetcher stops at each 4 KiB page. (Measured
                // 2026-11-24, raster time: sphere:1000000 Phong -1 ms, soup:1000000 -2.3 ms;
                // one line per record gained nothing.)
                // (As addresses: 2 KiB ahead may be past the arena, where a pointer may not go.)
                const std::uintptr_t ahead =
                    reinterpret_cast<std::uintptr_t>(next_record) + kRecordPrefetchBytes;
                static_assert(sizeof(BinEntry) + sizeof(CornerAttributes) <= 3 * kCacheLine);
                for (const std::size_t line :
                     {std::size_t{0}, kCacheLine, 2 * kCacheLine, record_bytes - 1})
                    __builtin_prefetch(reinterpret_cast<const void*>(ahead + line));
                lane_chunk_index[lane] = std::uint32_t(ci);
                if (--left == 0) {
                    ++ci;
                    next_run();
                } else {
                    next_record += record_bytes;
                }
            }
            const auto entry = [&](int lane) -> const BinEntry& {
                return *reinterpret_cast<const BinEntry*>(lane_record[lane]);
            };
            for (int lane = 0; lane < count; ++lane)
                for (int k = 0; k < 3; ++k)
                    vertices.set_vertex(k, lane, entry(lane).vertices[std::size_t(k)]);
            setup_block(vertices, count, frame.setup_settings, lanes, kernel ? &window : nullptr);
            for (int lane = 0; lane < count; ++lane) {
                const Chunk& chunk = frame.chunks[lane_chunk_index[lane]];
                const std::uint32_t local = entry(lane).ref & ~BinEntry::kClippedPiece;
                jobs.ref[lane] = lane_chunk_index[lane] << kLocalBits | local;
                // Alpha-tested and blended triangles go their own ways (below), not the lanes'.
                if (alpha_instances &&
                    frame.instances[chunk.refs[local].instance].alpha != AlphaMode::Opaque)
                    lanes.single_job[lane] = 0;
                const CornerAttributes* with = nullptr;
                const glm::vec3* piece = nullptr;
                if (kernel && tagged) {
                    with = reinterpret_cast<const CornerAttributes*>(lane_record[lane] +
                                                                     sizeof(BinEntry));
                    if (with->tag == 0) {
                        with = nullptr;
                        untagged = true;
                    } else if (entry(lane).ref & BinEntry::kClippedPiece) {
                        piece = chunk.pieces[chunk.refs[local].piece].weights.data();
                    }
                }
                // The deferred pass reads the ref of every pixel the triangle keeps (unless
                // tagged); fetching it now, while the tile rasterizes, saves a cache miss there
                // (refs are read in bin order here but in pixel order there).
                if (kernel && shade && with == nullptr) __builtin_prefetch(&chunk.refs[local]);
                jobs.corners[lane] = with;
                jobs.piece[lane] = piece;
                jobs.shade_constants[lane] =
                    with != nullptr && forward_tile
                        ? &frame.phong_constants[(with->tag & ~kShadeFlip) - 1]
                        : nullptr;
            }
            for (int lane = 0; lane < count; ++lane) {
                if (kernel && lanes_run()) {
                    const LaneJobsDone done = run_lanes(jobs, lane, count, shared_lane_job, tile);
                    passed += done.passed;
                    shaded_forward += done.passed_shaded;
                    lane = done.next;
                    if (lane == count) break;
                }
                if (load_setup(vertices, lanes, lane, frame.setup_settings, setup) !=
                    SetupResult::Visible)
                    continue;  // cannot happen: the front end made the same decision
                const Chunk& chunk = frame.chunks[lane_chunk_index[lane]];
                const std::uint32_t id = jobs.ref[lane];
                const TriangleRef& ref = chunk.refs[id & ((1u << kLocalBits) - 1)];
                if (alpha_instances) {
                    const AlphaMode alpha = frame.instances[ref.instance].alpha;
                    if (alpha == AlphaMode::Blend) {  // drawn after the tile (blend_pass.hpp)
                        if (targets.color)
                            blended.push_back(
                                {lane_chunk_index[lane], id & ((1u << kLocalBits) - 1), setup});
                        continue;
                    }
                    if (alpha == AlphaMode::Mask) {  // alpha-tested on the scalar way
                        passed += rasterize_scalar(c, chunk, ref, setup, id, nullptr, nullptr,
                                                   nullptr, tile, c.x0, c.y0, c.x1, c.y1);
                        untagged = true;
                        continue;
                    }
                }
                if (!kernel) {
                    passed += rasterize_scalar(c, chunk, ref, setup, id, nullptr, nullptr, nullptr,
                                               tile, c.x0, c.y0, c.x1, c.y1);
                    continue;
                }
                const PhongConstants* shade_now = jobs.shade_constants[lane];
                const std::uint64_t kept =
                    rasterize_blocks(c, chunk, ref, setup, id, jobs.corners[lane], jobs.piece[lane],
                                     shade_now, tile);
                passed += kept;
                if (shade_now != nullptr) shaded_forward += kept;
            }
        }
        passed_per_tile[tile_number] = passed;
        shaded_per_tile[tile_number] =
            shaded_forward + finish_tile(c, tile, background, background_row, shade && !forward,
                                         untagged, forward_tile);
        if (forward) shaded_per_tile[tile_number] = passed;
        if (!blended.empty()) {
            const BlendCounts counts = composite_blended(
                BlendTile{frame, codec, compare, targets.views, tile.depth, c.x0, c.y0, c.x1, c.y1},
                slot.blend);
            alpha_per_tile[tile_number].blended_fragments = counts.fragments;
            alpha_per_tile[tile_number].blended_pixels = counts.pixels;
        }
        deferred_per_tile[tile_number] = shade && !forward && (!forward_tile || untagged);
    });
    // Edges are drawn over the targets after this, across empty tiles too.
    if (targets.kept) {
        cleared_tiles.valid = options.edges == RenderOptions::Edges::None;
        cleared_tiles.signature = signature;
    }
    for (std::size_t t = 0; t < tiles; ++t) {
        stats.deferred |= deferred_per_tile[t] != 0;
        stats.fragments_passed += passed_per_tile[t];
        stats.fragments_shaded += shaded_per_tile[t];
        stats.blocks_hidden += hidden_per_tile[t];
    }
    for (const TileAlphaCounts& counts : alpha_per_tile) {
        stats.fragments_alpha_discarded += counts.discarded;
        stats.fragments_blended += counts.blended_fragments;
        stats.pixels_blended += counts.blended_pixels;
    }
}

}  // namespace zraster::detail
