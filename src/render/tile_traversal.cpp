// The traversal of a triangle's pixels in a tile (tile_traversal.hpp).
#include "render/tile_traversal.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "raster/tile_layout.hpp"
#include "render/hierarchical_z.hpp"
#include "render/shade_fragment.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {
namespace {

// Hierarchical z refreshes a block's bound after a triangle wrote at least this many fragments
// there (or covered it whole).
constexpr int kRefreshAfterFragments = 8;

// Counts a fragment in the front or back hits target (when given).
void count_hit(const TargetViews& t, bool front_facing, int px, int py) {
    std::uint32_t* hits = front_facing ? t.front_hits : t.back_hits;
    if (hits != nullptr)
        ++target_row(hits, front_facing ? t.front_hits_pitch : t.back_hits_pitch, py)[px];
}

std::int64_t edge_at(const TriangleSetup& t, std::size_t k, int px, int py) {
    return t.edge_a[k] * px + t.edge_b[k] * py + t.edge_c[k];
}

// The hiz view's counts: each 8x8 block of a skipped job, in the image's block grid.
void count_hidden_blocks(const TileContext& c, int bx0, int by0, int bx1, int by1) {
    const std::size_t blocks_per_row =
        std::size_t(c.plan.frame.tiles_x) * std::size_t(kBlocksPerTileRow);
    const std::size_t first_x = std::size_t(c.x0 / kBlockSize);
    const std::size_t first_y = std::size_t(c.y0 / kBlockSize);
    for (int by = by0; by <= by1; ++by)
        for (int bx = bx0; bx <= bx1; ++bx)
            ++c.plan.hiz_block_counts[(first_y + std::size_t(by)) * blocks_per_row + first_x +
                                      std::size_t(bx)];
}

bool fits_int32(std::int64_t v) {
    return v >= std::numeric_limits<std::int32_t>::min() &&
           v <= std::numeric_limits<std::int32_t>::max();
}

}  // namespace

BlockJob shared_job(const TilePlan& plan) {
    const RenderOptions& options = *plan.frame.options;
    BlockJob job;
    job.perspective = options.interpolation == Interpolation::PerspectiveCorrect;
    job.compare = plan.compare;
    job.write_depth = options.depth_write;
    job.attributes = plan.shades() || plan.targets.ids;
    job.barycentrics = plan.shades();
    return job;
}

std::uint64_t rasterize_scalar(TileContext& c, const TileTriangle& t, TileBuffers& tile, int x0,
                               int y0, int x1, int y1) {
    const TilePlan& plan = c.plan;
    const Frame& frame = plan.frame;
    const RenderOptions& options = *frame.options;
    const TriangleSetup& setup = t.setup;
    const CornerAttributes* corners = t.corners;
    const FrameInstance& instance = frame.instances[t.ref.instance];
    const bool alpha_test = instance.alpha == AlphaMode::Mask;
    const bool forward = plan.shading == ShadingPath::ScalarForward;
    ShadingTriangle shading;
    if (forward || alpha_test) prepare_shading_triangle(frame, t.chunk, t.ref, shading);
    std::uint64_t passed = 0;
    for_each_covered_pixel(setup, x0, y0, x1, y1, [&](int px, int py) {
        const std::size_t at = tile_index(px - c.x0, py - c.y0);
        float code = 0.0f;
        if (options.depth_test) {
            const float z = depth_at(setup, px, py);
            code = plan.codec.format() == DepthFormat::D32F
                       ? z
                       : static_cast<float>(plan.codec.encode(z));
            if (!DepthBuffer::passes(code, tile.depth[at], plan.compare)) return;
        }
        const glm::vec3 b = barycentrics(setup, px, py, options.interpolation);
        // The alpha test, before the fragment writes depth (alpha NaN: discarded).
        if (alpha_test && !(fragment_alpha(frame, shading, b.y, b.z, px, py) >=
                            instance.material->alpha_cutoff)) {
            ++c.counts.alpha_discarded;
            return;
        }
        if (options.depth_test && options.depth_write) tile.depth[at] = code;
        ++passed;
        if (plan.targets.coverage) count_hit(plan.targets.views, t.ref.front_facing, px, py);
        tile.ref[at] = t.id;
        tile.b1[at] = b.y;
        tile.b2[at] = b.z;
        tile.shade_tag[at] = corners ? corners->tag : 0;
        if (corners && t.shade_constants)  // forward, as the kernel does
            tile.color[at] =
                shade_interpolated_scalar(*t.shade_constants, *corners, t.piece, b.y, b.z);
        else if (corners)
            store_interpolated(*corners, t.piece, b.y, b.z, tile, at);
        if (forward)
            write_shaded(plan,
                         shade_fragment(frame, shading, b.y, b.z, px, py, plan.targets.normal), px,
                         py);
    });
    return passed;
}

std::uint64_t rasterize_blocks(TileContext& c, const TileTriangle& t, TileBuffers& tile) {
    const TilePlan& plan = c.plan;
    const TriangleSetup& setup = t.setup;
    const int rx0 = std::max(setup.min_x, c.x0), ry0 = std::max(setup.min_y, c.y0);
    const int rx1 = std::min(setup.max_x, c.x1 - 1), ry1 = std::min(setup.max_y, c.y1 - 1);
    BlockJob job = shared_job(plan);
    job.planes = {setup.depth, setup.q, setup.p1, setup.p2, setup.l1, setup.l2};
    job.corners = t.corners;
    job.piece = t.piece;
    job.shade_constants = t.shade_constants;
    job.ref = t.id;
    // Runs the kernel on pixels [x0, x1] x [y0, y1] of the triangle (edge values there fit 32
    // bits), unless hierarchical z shows them hidden; then refreshes the blocks' depth bounds.
    // Edges in `inside` (bit k: edge k) are non-negative over the whole block: the kernel gets
    // zero for them (their values far inside a large triangle need not fit 32 bits).
    // `small`: the whole triangle is this one job (see below).
    const auto run_block = [&]<bool small>(int x0, int y0, int x1, int y1, bool full,
                                           unsigned inside) -> std::uint64_t {
        const int bx0 = (x0 - c.x0) / kBlockSize, bx1 = (x1 - c.x0) / kBlockSize;
        const int by0 = (y0 - c.y0) / kBlockSize, by1 = (y1 - c.y0) / kBlockSize;
        const bool largest = plan.hiz == HierarchicalZ::Largest;
        // A bound nearer than the clear depth (1, or 0 reversed): something was drawn there.
        const auto bounded = [largest](float bound) {
            return largest ? bound < 1.0f : bound > 0.0f;
        };
        if (plan.hiz != HierarchicalZ::Off && c.counts.bounded_blocks > 0 &&
            (!small || c.counts.small_jobs.worth_testing())) {
            float farthest = tile.farthest[by0 * kBlocksPerTileRow + bx0];
            for (int by = by0; by <= by1; ++by)
                for (int bx = bx0; bx <= bx1; ++bx) {
                    const float f = tile.farthest[by * kBlocksPerTileRow + bx];
                    farthest = largest ? std::max(farthest, f) : std::min(farthest, f);
                }
            // Blocks still at the far plane (1, or 0 reversed) hide nothing worth the test.
            const bool drawn = bounded(farthest);
            c.counts.small_jobs.tests += small && drawn;
            if (drawn && block_hidden(setup.depth, x0 - setup.min_x, y0 - setup.min_y,
                                      x1 - setup.min_x, y1 - setup.min_y, farthest, plan.compare)) {
                c.counts.small_jobs.hidden += small;
                ++c.counts.blocks_hidden;
                if (plan.hiz_block_counts != nullptr) count_hidden_blocks(c, bx0, by0, bx1, by1);
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
            plan.simd ? visibility_block(job, tile) : visibility_block_scalar(job, tile);
        // A stale bound is still a bound (stored depths only move nearer): refresh it only
        // after real work, not after every 1-pixel triangle.
        if (plan.hiz != HierarchicalZ::Off && !small &&
            (full || passed >= kRefreshAfterFragments)) {
            for (int by = by0; by <= by1; ++by)
                for (int bx = bx0; bx <= bx1; ++bx) {
                    float& bound = tile.farthest[by * kBlocksPerTileRow + bx];
                    const bool was_bounded = bounded(bound);
                    bound = plan.simd ? block_farthest_depth(tile, bx, by, largest)
                                      : block_farthest_depth_scalar(tile, bx, by, largest);
                    c.counts.bounded_blocks += !was_bounded && bounded(bound);
                }
        }
        return static_cast<std::uint64_t>(passed);
    };
    // Small triangles (vertices within 64 pixels each way, the common case) have edge values
    // that fit 32 bits anywhere near them (|E| <= 2^22 * 65 * 2 < 2^30), so one whose pixels in
    // the tile span at most kSingleJobColumns columns is one kernel job, whatever its height and
    // wherever it lies on the block grid: no corner tests, one call instead of one per block.
    // Running the kernel over the rows and vectors the triangle does not cover costs less than
    // a block's corner tests and call (docs/architecture.md has the measurements).
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
                passed += rasterize_scalar(c, t, tile, x0, y0, x1 + 1, y1 + 1);
            else
                passed += run_block.template operator()<false>(x0, y0, x1, y1, full, inside);
        }
    }
    return passed;
}

}  // namespace zraster::detail
