// Finding a triangle's pixels in a tile and depth-testing them: the block traversal with the
// visibility kernel (hierarchical z, small triangles as one job) and the scalar reference path.
#pragma once
#include <zraster/raster.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>

#include "raster/visibility_kernel.hpp"
#include "render/frame.hpp"
#include "render/tile_context.hpp"

namespace zraster::detail {

// A small triangle at most this many pixels wide in the tile is one kernel job
// (rasterize_blocks, JobWindow).
inline constexpr int kSingleJobColumns = 32;

// One triangle as the traversal draws it.
struct TileTriangle {
    const Chunk& chunk;
    const TriangleRef& ref;
    const TriangleSetup& setup;
    std::uint32_t id;  // its triangle reference (tile_layout.hpp), stored per pixel
    // Tagged shading: the corner attributes the kernel interpolates (null: untagged), a clipped
    // piece's corner weights (or null), and shading forward the SIMD shader's constants.
    const CornerAttributes* corners = nullptr;
    const glm::vec3* piece = nullptr;
    const PhongConstants* shade_constants = nullptr;
};

// What the kernel jobs of all triangles in a tile share.
BlockJob shared_job(const TilePlan& plan);

// The scalar reference path for one triangle over [x0, x1) x [y0, y1) of the tile: any depth
// format, the depth test off, coverage counts, forward shading, the alpha test. Returns the
// fragments that passed.
std::uint64_t rasterize_scalar(TileContext& c, const TileTriangle& t, TileBuffers& tile, int x0,
                               int y0, int x1, int y1);

// The block traversal of one triangle over the tile: 8x8 blocks classified by their corners,
// then the visibility kernel on the covered and partly covered ones (edges too long for 32-bit
// lanes: rasterize_scalar on that block). Returns the fragments that passed.
std::uint64_t rasterize_blocks(TileContext& c, const TileTriangle& t, TileBuffers& tile);

// The side passes' traversal (mask_pass.hpp, blend_pass.hpp): triangle `t` over the tile into
// `side`, each block job by the kernel (blocks whose edges are too long for its lanes by
// rasterize_scalar, counting apart from the tile), without hierarchical z. `job` carries the
// depth test and what to write; its triangle's fields (planes, ref, corners, piece, shade
// constants) are set from t.
void draw_into_side(const TileContext& c, const TileTriangle& t, BlockJob& job, TileBuffers& side);

// The edge and position fields of a kernel job on pixels [x0, x1] x [y0, y1] of the triangle
// (image coordinates) in the tile whose first pixel is (tile_x0, tile_y0). Edges in `inside`
// (bit k: edge k, non-negative over the whole job) get zero: their values far inside a large
// triangle need not fit 32 bits.
void set_block_job(const TriangleSetup& setup, int tile_x0, int tile_y0, int x0, int y0, int x1,
                   int y1, bool full, unsigned inside, BlockJob& job);

inline std::int64_t edge_at(const TriangleSetup& t, std::size_t k, int px, int py) {
    return t.edge_a[k] * px + t.edge_b[k] * py + t.edge_c[k];
}

inline bool fits_int32(std::int64_t v) {
    return v >= std::numeric_limits<std::int32_t>::min() &&
           v <= std::numeric_limits<std::int32_t>::max();
}

// The triangle's pixels in the tile [tile_x0, tile_x1) x [tile_y0, tile_y1) as kernel jobs
// (inclusive pixel rectangles whose edge values fit 32 bits): a small triangle (vertices
// within kSingleJobExtent each way, at most kSingleJobColumns columns in the tile) is one job,
// block.template operator()<true>(x0, y0, x1, y1, false, 0); a larger one is cut into the tile's
// 8x8 blocks, each it may cover as block.template operator()<false>(x0, y0, x1, y1, full,
// inside), or scalar(x0, y0, x1, y1) where an edge crossing the block is too long for 32 bits.
//
// Small triangles' edge values fit 32 bits anywhere near them (|E| <= 2^22 * 65 * 2 < 2^30),
// so one whose pixels in the tile span at most kSingleJobColumns columns is one kernel job,
// whatever its height and wherever it lies on the block grid: no corner tests, one call instead
// of one per block. Running the kernel over the rows and vectors the triangle does not cover
// costs less than a block's corner tests and call (docs/architecture.md has the measurements).
template <class Block, class Scalar>
void for_each_block_job(const TriangleSetup& setup, int tile_x0, int tile_y0, int tile_x1,
                        int tile_y1, Block&& block, Scalar&& scalar) {
    const int rx0 = std::max(setup.min_x, tile_x0), ry0 = std::max(setup.min_y, tile_y0);
    const int rx1 = std::min(setup.max_x, tile_x1 - 1), ry1 = std::min(setup.max_y, tile_y1 - 1);
    const auto [lo_x, hi_x] = std::minmax({setup.x[0], setup.x[1], setup.x[2]});
    const auto [lo_y, hi_y] = std::minmax({setup.y[0], setup.y[1], setup.y[2]});
    if (hi_x - lo_x < kSingleJobExtent && hi_y - lo_y < kSingleJobExtent &&
        rx1 - rx0 < kSingleJobColumns) {
        block.template operator()<true>(rx0, ry0, rx1, ry1, false, 0u);
        return;
    }
    const int first_by = tile_y0 + (ry0 - tile_y0) / kBlockSize * kBlockSize;
    const int first_bx = tile_x0 + (rx0 - tile_x0) / kBlockSize * kBlockSize;
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
                scalar(x0, y0, x1, y1);
            else
                block.template operator()<false>(x0, y0, x1, y1, full, inside);
        }
    }
}

}  // namespace zraster::detail
