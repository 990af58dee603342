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
    BlockJob job = shared_job(plan);
    job.planes = {setup.depth, setup.q, setup.p1, setup.p2, setup.l1, setup.l2};
    job.corners = t.corners;
    job.piece = t.piece;
    job.shade_constants = t.shade_constants;
    job.ref = t.id;
    std::uint64_t passed = 0;
    // Runs the kernel on pixels [x0, x1] x [y0, y1] of the triangle, unless hierarchical z
    // shows them hidden; then refreshes the blocks' depth bounds. `small`: the whole triangle
    // is this one job.
    const auto run_block = [&]<bool small>(int x0, int y0, int x1, int y1, bool full,
                                           unsigned inside) {
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
                return;
            }
        }
        set_block_job(setup, c.x0, c.y0, x0, y0, x1, y1, full, inside, job);
        const int kept =
            plan.simd ? visibility_block(job, tile) : visibility_block_scalar(job, tile);
        passed += static_cast<std::uint64_t>(kept);
        // A stale bound is still a bound (stored depths only move nearer): refresh it only
        // after real work, not after every 1-pixel triangle.
        if (plan.hiz != HierarchicalZ::Off && !small && (full || kept >= kRefreshAfterFragments)) {
            for (int by = by0; by <= by1; ++by)
                for (int bx = bx0; bx <= bx1; ++bx) {
                    float& bound = tile.farthest[by * kBlocksPerTileRow + bx];
                    const bool was_bounded = bounded(bound);
                    bound = plan.simd ? block_farthest_depth(tile, bx, by, largest)
                                      : block_farthest_depth_scalar(tile, bx, by, largest);
                    c.counts.bounded_blocks += !was_bounded && bounded(bound);
                }
        }
    };
    for_each_block_job(setup, c.x0, c.y0, c.x1, c.y1, run_block,
                       [&](int x0, int y0, int x1, int y1) {
                           passed += rasterize_scalar(c, t, tile, x0, y0, x1 + 1, y1 + 1);
                       });
    return passed;
}

void draw_into_side(const TileContext& c, const TileTriangle& t, BlockJob& job, TileBuffers& side) {
    const TriangleSetup& setup = t.setup;
    job.planes = {setup.depth, setup.q, setup.p1, setup.p2, setup.l1, setup.l2};
    job.ref = t.id;
    job.corners = t.corners;
    job.piece = t.piece;
    job.shade_constants = t.shade_constants;
    TileContext scalar_context{c.plan, c.x0, c.y0, c.x1, c.y1, {}};
    for_each_block_job(
        setup, c.x0, c.y0, c.x1, c.y1,
        [&]<bool>(int x0, int y0, int x1, int y1, bool full, unsigned inside) {
            set_block_job(setup, c.x0, c.y0, x0, y0, x1, y1, full, inside, job);
            if (c.plan.simd)
                visibility_block(job, side);
            else
                visibility_block_scalar(job, side);
        },
        [&](int x0, int y0, int x1, int y1) {
            rasterize_scalar(scalar_context, t, side, x0, y0, x1 + 1, y1 + 1);
        });
}

void set_block_job(const TriangleSetup& setup, int tile_x0, int tile_y0, int x0, int y0, int x1,
                   int y1, bool full, unsigned inside, BlockJob& job) {
    for (std::size_t k = 0; k < 3; ++k) {
        const bool zero = (inside >> k) & 1;
        job.e[k] = zero ? 0 : static_cast<std::int32_t>(edge_at(setup, k, x0, y0));
        job.step_x[k] = zero ? 0 : static_cast<std::int32_t>(setup.edge_a[k]);
        job.step_y[k] = zero ? 0 : static_cast<std::int32_t>(setup.edge_b[k]);
    }
    job.full = full;
    job.x0 = x0 - tile_x0;
    job.y0 = y0 - tile_y0;
    job.width = x1 - x0 + 1;
    job.height = y1 - y0 + 1;
    job.plane_dx = x0 - setup.min_x;
    job.plane_dy = y0 - setup.min_y;
}

}  // namespace zraster::detail
