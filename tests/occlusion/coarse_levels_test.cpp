// The occlusion buffer's summaries (per tile: smallest bound and largest far layer; per 8x8
// block: largest bound) against the pixels they summarize, SIMD against scalar on every target,
// and the rectangle test that reads them against the pixel-by-pixel answer, on grids whose
// sides are whole tiles (the block probe then reaches the padding row).
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstring>
#include <vector>

#include <zraster/scenes.hpp>
#include "occlusion/occlusion_kernel.hpp"
#include "support/simd_target_scope.hpp"

namespace zraster::detail {
namespace {

// A grid with its storage. Rows are random but keep the invariants of TileGrid: no full mask,
// near <= far. Depths come from a few levels so that equal bounds and ties occur; the kind of
// content (empty, full far layer, mixed, dense) changes per tile.
struct Grid {
    StripStorage rows;
    std::vector<float> coarse, block_max;
    TileGrid grid;

    Grid(int tiles_x, int tiles_y, std::uint64_t seed) {
        const std::size_t tiles = static_cast<std::size_t>(tiles_x) * tiles_y;
        coarse.assign(2 * tiles + kCoarsePadding, -1.0f);
        block_max.assign(block_max_size(tiles_x, tiles_y), -1.0f);
        grid.coarse = coarse.data();
        grid.block_max = block_max.data();
        grid.tiles_x = tiles_x;
        grid.tiles_y = tiles_y;
        grid.width = tiles_x * kOcclusionTileWidth;
        grid.height = tiles_y * kOcclusionTileHeight;
        rows.attach(grid);
        rows.clear();
        SplitMix64 rng{seed};
        const auto level = [&] {
            return static_cast<float>(static_cast<int>(rng.uniform(0, 9))) / 8;
        };
        for (int ty = 0; ty < tiles_y; ++ty)
            for (int tx = 0; tx < tiles_x; ++tx) {
                const int kind = static_cast<int>(rng.uniform(0, 4));
                for (int r = 0; r < kOcclusionTileHeight; ++r) {
                    std::uint32_t mask = 0;
                    if (kind == 2)
                        mask = static_cast<std::uint32_t>(rng.next()) & kOcclusionFullMask;
                    if (kind == 3) {  // most bits set, often whole halves
                        mask = kOcclusionFullMask & ~(1u << static_cast<int>(rng.uniform(0, 16)));
                        if (rng.uniform(0, 1) < 0.3) mask &= 0xff00u;
                    }
                    if (mask == kOcclusionFullMask) mask &= ~1u;
                    const float a = level(), b = level();
                    const std::size_t at = row_index(grid, tx, ty * kOcclusionTileHeight + r);
                    grid.far_depth[at] = kind == 0 ? kClearFarDepth : std::max(a, b);
                    grid.near_depth[at] = mask != 0 ? std::min(a, b) : kEmptyNearDepth;
                    grid.mask[at] = mask;
                }
            }
    }

    float pixel_bound(int x, int y) const {
        const std::size_t at = row_index(grid, x / kOcclusionTileWidth, y);
        return (grid.mask[at] >> (x % kOcclusionTileWidth)) & 1u ? grid.near_depth[at]
                                                                 : grid.far_depth[at];
    }
};

TEST(OcclusionCoarseLevels, BlockMaximaAreTheLargestPixelBoundOfEachBlock) {
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        const test::SimdTargetScope scope(target);
        SCOPED_TRACE(hwy::TargetName(target));
        Grid simd(7, 5, 3), scalar(7, 5, 3);
        refresh_coarse_levels(simd.grid, 0, 0, 6, 4);
        refresh_coarse_levels_scalar(scalar.grid, 0, 0, 6, 4);
        ASSERT_EQ(std::memcmp(simd.coarse.data(), scalar.coarse.data(),
                              simd.coarse.size() * sizeof(float)),
                  0);
        ASSERT_EQ(std::memcmp(simd.block_max.data(), scalar.block_max.data(),
                              simd.block_max.size() * sizeof(float)),
                  0);
        const std::size_t block_row = 2 * 7;
        for (int by = 0; by < 10; ++by)
            for (int bx = 0; bx < 14; ++bx) {
                float largest = -1.0f;
                for (int y = by * 8; y < by * 8 + 8; ++y)
                    for (int x = bx * 8; x < bx * 8 + 8; ++x)
                        largest = std::max(largest, simd.pixel_bound(x, y));
                ASSERT_EQ(simd.block_max[by * block_row + bx], largest) << bx << "," << by;
            }
        // Only the tiles asked for: a refresh of one tile leaves its neighbours' blocks alone.
        Grid part(7, 5, 3);
        refresh_coarse_levels(part.grid, 2, 1, 2, 1);
        EXPECT_EQ(part.block_max[2 * block_row + 4], simd.block_max[2 * block_row + 4]);
        EXPECT_EQ(part.block_max[3 * block_row + 5], simd.block_max[3 * block_row + 5]);
        EXPECT_EQ(part.block_max[2 * block_row + 3], -1.0f);
        EXPECT_EQ(part.block_max[4 * block_row + 4], -1.0f);
    }
}

// Every rectangle, small and large, at the grid's far edges too, against the pixels.
TEST(OcclusionCoarseLevels, RectangleTestsGiveThePixelAnswer) {
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        const test::SimdTargetScope scope(target);
        SCOPED_TRACE(hwy::TargetName(target));
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            Grid g(6, 4, seed);
            refresh_coarse_levels(g.grid, 0, 0, 5, 3);
            SplitMix64 rng{seed * 77};
            int occluded = 0, visible = 0;
            for (int k = 0; k < 4000; ++k) {
                const int w = static_cast<int>(rng.uniform(1, k % 4 == 0 ? 96 : 24));
                const int h = static_cast<int>(rng.uniform(1, k % 4 == 0 ? 64 : 24));
                int x0 = static_cast<int>(rng.uniform(0, g.grid.width));
                int y0 = static_cast<int>(rng.uniform(0, g.grid.height));
                if (k % 5 == 0) y0 = g.grid.height - h;  // flush with the last row of pixels
                if (k % 7 == 0) x0 = g.grid.width - w;
                x0 = std::max(x0, 0);
                y0 = std::max(y0, 0);
                const int x1 = std::min(x0 + w - 1, g.grid.width - 1);
                const int y1 = std::min(y0 + h - 1, g.grid.height - 1);
                const float depth = static_cast<float>(rng.uniform(0.0, 1.1));
                bool expected = true;
                for (int y = y0; y <= y1 && expected; ++y)
                    for (int x = x0; x <= x1 && expected; ++x)
                        expected = g.pixel_bound(x, y) < depth;
                ASSERT_EQ(rect_occluded(g.grid, x0, y0, x1, y1, depth), expected)
                    << x0 << "," << y0 << " .. " << x1 << "," << y1 << " at " << depth;
                ASSERT_EQ(rect_occluded_scalar(g.grid, x0, y0, x1, y1, depth), expected);
                (expected ? occluded : visible) += 1;
            }
            EXPECT_GT(occluded, 400);
            EXPECT_GT(visible, 400);
        }
    }
}

}  // namespace
}  // namespace zraster::detail
