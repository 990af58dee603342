// See occlusion_kernel.hpp. Rasterization follows the idea of Masked Software Occlusion Culling
// (Andersson, Hasselgren, Akenine-Möller 2015): coverage is computed for a whole 16-pixel strip
// at once as a bit mask between the left and right edge crossings of the row (two shifts), one
// SIMD lane per pixel row, and merged into the two depth layers of each row:
//  - a triangle that is not nearer than the far layer anywhere in the row teaches nothing;
//  - the working layer is dropped when the triangle is further in front of it than the working
//    layer is in front of the far layer (a new, nearer surface starts);
//  - the triangle's coverage joins the mask, the near layer takes the larger (further) depth;
//  - a full mask becomes the new far layer.
// Highway's foreach_target re-includes this file once per instruction set; the scalar twins
// and the dispatchers are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "occlusion/occlusion_kernel.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "occlusion/occluder_setup.hpp"
#include "occlusion/occlusion_kernel.hpp"
#include "simd/compress_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::CappedTag<float, kOcclusionTileHeight>;
using DI = hn::RebindToSigned<DF>;
using DU = hn::RebindToUnsigned<DF>;

// ~0u << n for n in [0, 32], 0 for n = 32. x86's variable shifts (AVX2 and later) already give
// 0 for counts past 31; elsewhere a shift by 32 is not portable and is handled apart.
HWY_INLINE hn::Vec<DU> ones_shifted_left(hn::Vec<DI> n) {
    const DU du;
    const auto ones = hn::Set(du, ~0u);
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
    return hn::Shl(ones, hn::BitCast(du, n));
#else
    const DI di;
    const auto shifted = hn::Shl(ones, hn::BitCast(du, hn::Min(n, hn::Set(di, 31))));
    return hn::IfThenZeroElse(hn::RebindMask(du, hn::Eq(n, hn::Set(di, 32))), shifted);
#endif
}

// Float to int, rounding toward zero, for lanes known to be in int range: Highway's ConvertTo
// spends four more instructions per vector on saturating out-of-range lanes.
HWY_INLINE hn::Vec<DI> TruncInRange(hn::Vec<DF> v) {
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX3
    static_assert(hn::MaxLanes(DF()) == 16);
    return hn::Vec<DI>{_mm512_cvttps_epi32(v.raw)};
#elif HWY_ARCH_X86 && HWY_TARGET == HWY_AVX2
    static_assert(hn::MaxLanes(DF()) == 8);
    return hn::Vec<DI>{_mm256_cvttps_epi32(v.raw)};
#elif HWY_ARCH_X86 && (HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3)
    static_assert(hn::MaxLanes(DF()) == 4);
    return hn::Vec<DI>{_mm_cvttps_epi32(v.raw)};
#else
    return hn::ConvertTo(DI(), v);
#endif
}

void RasterizeOccluders(const OccluderBatch& b, std::size_t count, TileGrid grid) {
    namespace k = occluder_setup;
    const DF df;
    const DI di;
    const DU du;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const auto zero_i = hn::Zero(di);
    const auto zero_u = hn::Zero(du);
    const auto full_mask = hn::Set(du, kOcclusionFullMask);
    const auto width_i = hn::Set(di, kOcclusionTileWidth);
    const auto one_i = hn::Set(di, 1);
    const auto half = hn::Set(df, 0.5f);
    for (std::size_t i = 0; i < count; ++i) {
        const int x0 = b.x0[i], x1 = b.x1[i], y0 = b.y0[i], y1 = b.y1[i];
        const auto field = [&](int f) { return hn::Set(df, b.field[f][i]); };
        const int tx0 = x0 / kOcclusionTileWidth, tx1 = x1 / kOcclusionTileWidth;
        const float dx = b.field[k::kZDx][i], kx = b.field[k::kZKx][i];
        // Rows y0.. a vector at a time, each vector of rows one load per strip (see TileGrid).
        // Most triangles are one vector of rows: the triangle's values are broadcast in the
        // loop, where they are used once (hoisted, they did not fit the registers and spilled).
        for (int y_first = y0; y_first <= y1; y_first += lanes) {
            const auto left_x0 = field(k::kLeftX), left_step0 = field(k::kLeftStep);
            const auto left_x1 = field(k::kLeftX + 1), left_step1 = field(k::kLeftStep + 1);
            const auto right_x0 = field(k::kRightX), right_step0 = field(k::kRightStep);
            const auto right_x1 = field(k::kRightX + 1), right_step1 = field(k::kRightStep + 1);
            const auto span_lo = hn::Set(df, static_cast<float>(x0));
            const auto span_hi = hn::Set(df, static_cast<float>(x1 + 1));
            const auto origin_x = hn::Set(di, x0);
            const auto z_origin = field(k::kZOrigin), z_dx = hn::Set(df, dx);
            const auto z_dy = field(k::kZDy), z_kx = hn::Set(df, kx);
            const auto z_ky = field(k::kZKy), z_bias = field(k::kZBias);
            const auto z_max = field(k::kZMax);
            const auto z_dx_positive = hn::RebindMask(di, hn::Gt(z_dx, hn::Zero(df)));
            const auto y = hn::Iota(di, y_first);
            const auto row_valid = hn::Lt(y, hn::Set(di, y1 + 1));
            const auto yf = hn::ConvertTo(df, hn::Sub(y, hn::Set(di, y0)));
            const auto l0 = hn::Add(left_x0, hn::Mul(yf, left_step0));
            const auto l1 = hn::Add(left_x1, hn::Mul(yf, left_step1));
            const auto r0 = hn::Add(right_x0, hn::Mul(yf, right_step0));
            const auto r1 = hn::Add(right_x1, hn::Mul(yf, right_step1));
            const auto xl = hn::IfThenElse(hn::Gt(l0, l1), l0, l1);
            const auto xr = hn::IfThenElse(hn::Lt(r0, r1), r0, r1);
            // First covered column and one past the last, clamped to the bounding box.
            auto lo = hn::Add(xl, half);
            lo = hn::IfThenElse(hn::Lt(lo, span_lo), span_lo, lo);
            lo = hn::IfThenElse(hn::Gt(lo, span_hi), span_hi, lo);
            auto hi = hn::Sub(xr, half);
            hi = hn::IfThenElse(hn::Lt(hi, span_lo), span_lo, hi);
            hi = hn::IfThenElse(hn::Gt(hi, span_hi), span_hi, hi);
            // lo >= 0: truncation is its floor.
            const auto first = TruncInRange(lo);
            const auto end = hn::IfThenElse(row_valid, TruncInRange(hn::Ceil(hi)), first);
            // The bound is taken at the extreme covered column of the whole row and at the
            // tile's extreme column; the plane being affine, the smaller of the two bounds
            // the covered pixels of the row inside the tile.
            const auto row_depth =
                hn::Add(hn::Add(z_origin, hn::Mul(z_dy, hn::Add(yf, z_ky))), z_bias);
            // A select, not a branch: the sign of z_dx is a coin toss per triangle.
            const auto row_extreme =
                hn::Sub(hn::IfThenElse(z_dx_positive, hn::Sub(end, one_i), first), origin_x);
            auto row_bound =
                hn::Add(row_depth, hn::Mul(z_dx, hn::Add(hn::ConvertTo(df, row_extreme), z_kx)));
            row_bound = hn::IfThenElse(hn::Lt(row_bound, z_max), row_bound, z_max);
            // tile_depth_step's column - x0, stepped a tile at a time (exact in float).
            float column = static_cast<float>(tx0 * kOcclusionTileWidth +
                                              (dx > 0.0f ? kOcclusionTileWidth - 1 : 0) - x0);
            for (int tx = tx0; tx <= tx1; ++tx, column += static_cast<float>(kOcclusionTileWidth)) {
                const std::size_t at = row_index(grid, tx, y_first);
                const auto tile_x = hn::Set(di, tx * kOcclusionTileWidth);
                auto s = hn::Sub(first, tile_x);
                s = hn::Min(hn::Max(s, zero_i), width_i);
                auto e = hn::Sub(end, tile_x);
                e = hn::Min(hn::Max(e, zero_i), width_i);
                // Columns s..e-1: (~0 << s) & ~(~0 << e).
                const auto coverage = hn::AndNot(ones_shifted_left(e), ones_shifted_left(s));
                const auto tile_bound = hn::Add(row_depth, hn::Set(df, dx * (column + kx)));
                const auto z = hn::IfThenElse(hn::Lt(row_bound, tile_bound), row_bound, tile_bound);

                const auto mask = hn::LoadU(du, grid.mask + at);
                const auto far_depth = hn::LoadU(df, grid.far_depth + at);
                const auto near_depth = hn::LoadU(df, grid.near_depth + at);
                const auto live =
                    hn::And(hn::RebindMask(df, hn::Ne(coverage, zero_u)), hn::Lt(z, far_depth));
                const auto discard = hn::Gt(hn::Sub(near_depth, z), hn::Sub(far_depth, near_depth));
                auto merged_mask = hn::IfThenZeroElse(hn::RebindMask(du, discard), mask);
                auto merged_near = hn::IfThenZeroElse(discard, near_depth);
                merged_mask = hn::Or(merged_mask, coverage);
                merged_near = hn::IfThenElse(hn::Lt(merged_near, z), z, merged_near);
                const auto full_u = hn::Eq(merged_mask, full_mask);
                const auto full = hn::RebindMask(df, full_u);
                const auto covers_row = hn::RebindMask(df, hn::Eq(coverage, full_mask));
                const auto new_far =
                    hn::IfThenElse(full, hn::IfThenElse(covers_row, z, merged_near), far_depth);
                const auto new_mask = hn::IfThenZeroElse(full_u, merged_mask);
                const auto new_near = hn::IfThenZeroElse(full, merged_near);
                const auto live_u = hn::RebindMask(du, live);
                hn::StoreU(hn::IfThenElse(live_u, new_mask, mask), du, grid.mask + at);
                hn::StoreU(hn::IfThenElse(live, new_far, far_depth), df, grid.far_depth + at);
                hn::StoreU(hn::IfThenElse(live, new_near, near_depth), df, grid.near_depth + at);
            }
        }
    }
}

// Per tile of columns tx0..tx1 and rows ty0..ty1, the smallest bound and the largest far layer
// (TileGrid::coarse) and the largest bound of each quarter (TileGrid::block_max): one tile per
// vector loop. A half row's largest bound is its near layer when the mask covers all 8 pixels,
// else its far layer (near <= far).
void RefreshCoarseLevels(TileGrid grid, int tx0, int ty0, int tx1, int ty1) {
    const DF df;
    const DU du;
    const int lanes = static_cast<int>(hn::Lanes(df));
    constexpr int kHalf = kOcclusionBlockSide;
    const auto left_bits = hn::Set(du, (1u << kHalf) - 1u);
    const auto right_bits = hn::Set(du, ((1u << kHalf) - 1u) << kHalf);
    const auto none = hn::Set(df, -HUGE_VALF);
    const std::size_t block_row = 2 * static_cast<std::size_t>(grid.tiles_x);
    for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx) {
            const std::size_t i = static_cast<std::size_t>(ty) * grid.tiles_x + tx;
            const TileRows t = tile_rows(grid, tx, ty);
            auto hi = none, lo = hn::Set(df, HUGE_VALF);
            // Block maxima: top left, top right, bottom left, bottom right.
            auto tl = none, tr = none, bl = none, br = none;
            for (int r = 0; r < kOcclusionTileHeight; r += lanes) {
                const auto far_depth = hn::Load(df, t.far_depth + r);
                const auto near_depth = hn::Load(df, t.near_depth + r);
                const auto mask = hn::Load(du, t.mask + r);
                const auto masked = hn::RebindMask(df, hn::Ne(mask, hn::Zero(du)));
                hi = hn::Max(hi, far_depth);
                lo = hn::Min(lo, hn::IfThenElse(masked, near_depth, far_depth));
                const auto left =
                    hn::IfThenElse(hn::RebindMask(df, hn::Eq(hn::And(mask, left_bits), left_bits)),
                                   near_depth, far_depth);
                const auto right = hn::IfThenElse(
                    hn::RebindMask(df, hn::Eq(hn::And(mask, right_bits), right_bits)), near_depth,
                    far_depth);
                if (lanes >= kOcclusionTileHeight) {  // top rows in the low lanes
                    const auto top = hn::FirstN(df, kHalf);
                    tl = hn::IfThenElse(top, left, none);
                    tr = hn::IfThenElse(top, right, none);
                    bl = hn::IfThenElse(top, none, left);
                    br = hn::IfThenElse(top, none, right);
                } else if (r < kHalf) {
                    tl = hn::Max(tl, left);
                    tr = hn::Max(tr, right);
                } else {
                    bl = hn::Max(bl, left);
                    br = hn::Max(br, right);
                }
            }
            // As the scalar twin: far_depth[0] takes part (near <= far makes it moot).
            const float lo_lanes = hn::GetLane(hn::MinOfLanes(df, lo));
            grid.coarse[2 * i] = lo_lanes < t.far_depth[0] ? lo_lanes : t.far_depth[0];
            grid.coarse[2 * i + 1] = hn::GetLane(hn::MaxOfLanes(df, hi));
            float* blocks = grid.block_max + 2 * static_cast<std::size_t>(ty) * block_row + 2 * tx;
            blocks[0] = hn::GetLane(hn::MaxOfLanes(df, tl));
            blocks[1] = hn::GetLane(hn::MaxOfLanes(df, tr));
            blocks[block_row] = hn::GetLane(hn::MaxOfLanes(df, bl));
            blocks[block_row + 1] = hn::GetLane(hn::MaxOfLanes(df, br));
        }
}

// One tile of a rectangle test: true when the rectangle's pixels in it (columns x0..x1 and
// rows y0..y1, clipped to the tile) all hold a bound in front of `depth`.
HWY_INLINE bool TileOccluded(const TileGrid& grid, int tx, int ty, int x0, int y0, int x1, int y1,
                             float depth) {
    const DF df;
    const DI di;
    const DU du;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const TileRows tile = tile_rows(grid, tx, ty);
    const int s = std::max(x0 - tx * kOcclusionTileWidth, 0);
    const int e = std::min(x1 + 1 - tx * kOcclusionTileWidth, kOcclusionTileWidth);
    const std::uint32_t high = e >= 32 ? ~0u : (1u << e) - 1u;  // e <= tile width
    const std::uint32_t rect_mask = high & ~((1u << s) - 1u);   // s <= 31 here
    // A full mask never stays in a tile, so over whole rows the far layer decides, and the
    // caller saw that one of them is not in front.
    const bool all_rows = ty * kOcclusionTileHeight >= y0 &&
                          ty * kOcclusionTileHeight + kOcclusionTileHeight - 1 <= y1;
    if (all_rows && rect_mask == kOcclusionFullMask) return false;
    const auto d = hn::Set(df, depth);
    const auto rect = hn::Set(du, rect_mask);
    const auto row_lo = hn::Set(di, y0 - 1), row_hi = hn::Set(di, y1 + 1);
    for (int r = 0; r < kOcclusionTileHeight; r += lanes) {
        const auto y = hn::Iota(di, ty * kOcclusionTileHeight + r);
        const auto row_valid = hn::RebindMask(df, hn::And(hn::Gt(y, row_lo), hn::Lt(y, row_hi)));
        const auto uncovered =
            hn::RebindMask(df, hn::Ne(hn::AndNot(hn::Load(du, tile.mask + r), rect), hn::Zero(du)));
        const auto bound = hn::IfThenElse(uncovered, hn::Load(df, tile.far_depth + r),
                                          hn::Load(df, tile.near_depth + r));
        if (!hn::AllTrue(df, hn::Or(hn::Lt(bound, d), hn::Not(row_valid)))) return false;
    }
    return true;
}

// The coarse levels settle most tiles: a row of tiles at a time, a tile's smallest and largest
// bound in two neighbouring lanes (the array is padded for the whole vector loads); only tiles
// whose largest bound is not in front but whose smallest is are read.
#if HWY_TARGET != HWY_SCALAR
// The 8x8 blocks entirely inside columns x0..x1, rows y0..y1 (x0, y0 >= 0): bx0..bx1,
// by0..by1, empty when bx0 > bx1 or by0 > by1. bx0 and by0 are at most one past the last block.
struct CoveredBlocks {
    int bx0, by0, bx1, by1;
    CoveredBlocks(int x0, int y0, int x1, int y1) {
        constexpr unsigned kSide = kOcclusionBlockSide;
        bx0 = static_cast<int>((static_cast<unsigned>(x0) + kSide - 1) / kSide);
        by0 = static_cast<int>((static_cast<unsigned>(y0) + kSide - 1) / kSide);
        bx1 = static_cast<int>((static_cast<unsigned>(x1) + 1) / kSide) - 1;
        by1 = static_cast<int>((static_cast<unsigned>(y1) + 1) / kSide) - 1;
    }
};

// True when a covered 8x8 block (above) has a bound not in front of `depth`: the rectangle is
// visible there.
HWY_INLINE bool BlockSeen(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth) {
    const DF df;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const CoveredBlocks b(x0, y0, x1, y1);
    const auto d = hn::Set(df, depth);
    const std::size_t block_row = 2 * static_cast<std::size_t>(grid.tiles_x);
    for (int by = b.by0; by <= b.by1; ++by) {
        const float* row = grid.block_max + static_cast<std::size_t>(by) * block_row;
        for (int bx = b.bx0; bx <= b.bx1; bx += lanes) {
            // Lanes past bx1 read the next blocks or the padding; FirstN masks them out.
            const auto in_rect = hn::FirstN(df, static_cast<std::size_t>(b.bx1 + 1 - bx));
            if (!hn::AllFalse(df, hn::AndNot(hn::Lt(hn::LoadU(df, row + bx), d), in_rect)))
                return true;
        }
    }
    return false;
}

// The covered blocks of the first row of covered blocks whose bound is not in front of d (the
// lanes of blocks bx0..); none when the rectangle covers no block.
HWY_INLINE hn::Mask<DF> FirstBlocksSeen(const TileGrid& grid, int x0, int y0, int x1, int y1,
                                        hn::Vec<DF> d) {
    const DF df;
    const CoveredBlocks b(x0, y0, x1, y1);
    // Arithmetic, not branches; with no covered block the row read is at most the one past the
    // last, which the padding of block_max covers.
    const int covered = std::max(b.bx1 + 1 - b.bx0, 0) * static_cast<int>(b.by0 <= b.by1);
    const float* row =
        grid.block_max +
        static_cast<std::size_t>(b.by0) * (2 * static_cast<std::size_t>(grid.tiles_x)) + b.bx0;
    return hn::AndNot(hn::Lt(hn::LoadU(df, row), d),
                      hn::FirstN(df, static_cast<std::size_t>(covered)));
}

// Tiles tx.. of row ty whose coarse levels are not in front (the lanes of not_in_front, a
// tile's smallest bound in an even lane, its largest in the next): false when the rectangle is
// seen there. `blocks_read`: whether the covered blocks were scanned (once per test).
HWY_NOINLINE bool SettleTiles(const TileGrid& grid, hn::Mask<DF> not_in_front, int tx, int ty,
                              int x0, int y0, int x1, int y1, float depth, bool& blocks_read) {
    const DF df;
    const DU du;
    const auto largest = hn::RebindMask(df, hn::Ne(hn::And(hn::Iota(du, 0), hn::Set(du, 1u)),
                                                   hn::Zero(du)));  // odd lanes
    // A tile with no bound in front: the rectangle is seen there.
    if (!hn::AllFalse(df, hn::AndNot(largest, not_in_front))) return false;
    // Before the first tile's rows, the blocks the rectangle covers: one of them not in front
    // settles the test without reading tiles (32 times more memory than the block maxima).
    if (!blocks_read) {
        blocks_read = true;
        if (BlockSeen(grid, x0, y0, x1, y1, depth)) return false;
    }
    auto open = not_in_front;  // odd lanes only
    do {
        const auto lane = hn::FindFirstTrue(df, open);
        if (!TileOccluded(grid, tx + static_cast<int>(lane / 2), ty, x0, y0, x1, y1, depth))
            return false;
        open = hn::AndNot(hn::FirstN(df, static_cast<std::size_t>(lane) + 1), open);
    } while (!hn::AllFalse(df, open));
    return true;
}

HWY_INLINE bool RectOccludedImpl(const TileGrid& grid, int x0, int y0, int x1, int y1,
                                 float depth) {
    const DF df;
    const int tiles_per_vector = static_cast<int>(hn::Lanes(df)) / 2;
    const auto d = hn::Set(df, depth);
    const int tx0 = x0 / kOcclusionTileWidth, tx1 = x1 / kOcclusionTileWidth;
    const int ty0 = y0 / kOcclusionTileHeight, ty1 = y1 / kOcclusionTileHeight;
    const std::size_t row_stride = 2 * static_cast<std::size_t>(grid.tiles_x);
    const float* levels = grid.coarse + static_cast<std::size_t>(ty0) * row_stride + 2 * tx0;
    bool blocks_read = false;
    if (tx1 - tx0 < tiles_per_vector) {  // one vector per row of tiles (the usual case)
        // Lanes past tx1 read the next tiles or the padding; in_rect masks them out.
        const auto in_rect = hn::FirstN(df, 2 * static_cast<std::size_t>(tx1 + 1 - tx0));
        // The first row with a tile whose largest bound is not in front (a short loop: the
        // rectangles behind everything are decided here).
        int ty = ty0;
        auto not_in_front = hn::FirstN(df, 0);
        for (; ty <= ty1; ++ty, levels += row_stride) {
            not_in_front = hn::AndNot(hn::Lt(hn::LoadU(df, levels), d), in_rect);
            if (!hn::AllFalse(df, not_in_front)) break;
        }
        if (ty > ty1) return true;
        // A tile of that row with no bound in front, or a covered block of the first row of
        // blocks with none, settles most visible rectangles. Both read, one branch: on random
        // rectangles a branch on either alone is unpredictable, and a mispredicted one costs
        // more than both loads.
        const DU du;
        const auto smallest = hn::RebindMask(
            df, hn::Eq(hn::And(hn::Iota(du, 0), hn::Set(du, 1u)), hn::Zero(du)));  // even lanes
        if (!hn::AllFalse(df, hn::Or(hn::And(not_in_front, smallest),
                                     FirstBlocksSeen(grid, x0, y0, x1, y1, d))))
            return false;
        for (; ty <= ty1; ++ty, levels += row_stride) {
            not_in_front = hn::AndNot(hn::Lt(hn::LoadU(df, levels), d), in_rect);
            if (!hn::AllFalse(df, not_in_front) &&
                !SettleTiles(grid, not_in_front, tx0, ty, x0, y0, x1, y1, depth, blocks_read))
                return false;
        }
        return true;
    }
    for (int ty = ty0; ty <= ty1; ++ty, levels += row_stride) {
        for (int tx = tx0; tx <= tx1; tx += tiles_per_vector) {
            const auto in_rect = hn::FirstN(df, 2 * static_cast<std::size_t>(tx1 + 1 - tx));
            const auto not_in_front =
                hn::AndNot(hn::Lt(hn::LoadU(df, levels + 2 * (tx - tx0)), d), in_rect);
            if (!hn::AllFalse(df, not_in_front) &&
                !SettleTiles(grid, not_in_front, tx, ty, x0, y0, x1, y1, depth, blocks_read))
                return false;
        }
    }
    return true;
}
#endif

bool RectOccluded(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth) {
#if HWY_TARGET == HWY_SCALAR
    return rect_occluded_scalar(grid, x0, y0, x1, y1, depth);  // one lane: no tile pairs
#else
    return RectOccludedImpl(grid, x0, y0, x1, y1, depth);
#endif
}

// Float to int, rounding toward zero, for values known to be in int range (see TruncInRange).
template <class D4>
HWY_INLINE hn::Vec<hn::RebindToSigned<D4>> TruncInRange4(D4 d4, hn::Vec<D4> v) {
    (void)d4;  // only the vector's type matters
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_SSSE3
    return hn::Vec<hn::RebindToSigned<D4>>{_mm_cvttps_epi32(v.raw)};
#else
    return hn::ConvertTo(hn::RebindToSigned<D4>(), v);
#endif
}

// The window-to-pixel conversion of window_rect_test_scalar, four coordinates in one vector
// (xmin, ymin, xmax, ymax), the same operations on each.
WindowRectResult WindowRectTest(const TileGrid& grid, float xmin, float xmax, float ymin,
                                float ymax, float nearest) {
#if HWY_TARGET == HWY_SCALAR
    return window_rect_test_scalar(grid, xmin, xmax, ymin, ymax, nearest);  // no 4-lane vectors
#else
    const hn::Full128<float> d4;
    const hn::RebindToSigned<decltype(d4)> i4;
    const auto v =
        hn::ConcatLowerLower(d4, hn::InterleaveLower(d4, hn::Set(d4, xmax), hn::Set(d4, ymax)),
                             hn::InterleaveLower(d4, hn::Set(d4, xmin), hn::Set(d4, ymin)));
    const auto a = hn::Abs(v);
    const auto a2 = hn::Max(a, hn::Shuffle1032(a));
    const auto max_abs = hn::Max(a2, hn::Shuffle2301(a2));
    const auto margin = hn::Add(hn::Set(d4, 0x1p-6f), hn::Mul(max_abs, hn::Set(d4, 0x1p-17f)));
    // Minima move down, maxima up; then the pixel centers, clamped as in the scalar twin.
    const auto grown = hn::Add(v, hn::ConcatUpperLower(d4, margin, hn::Neg(margin)));
    const auto limit = hn::InterleaveLower(d4, hn::Set(d4, static_cast<float>(grid.width) + 1.0f),
                                           hn::Set(d4, static_cast<float>(grid.height) + 1.0f));
    const auto centers =
        hn::Min(hn::Max(hn::Sub(grown, hn::Set(d4, 0.5f)), hn::Set(d4, -2.0f)), limit);
    const auto p =
        TruncInRange4(d4, hn::ConcatUpperLower(d4, hn::Floor(centers), hn::Ceil(centers)));
    // Between pixel centers: test the neighbours instead of calling it hidden (a swap).
    const auto swapped = hn::Shuffle1032(p);
    auto q = hn::ConcatUpperLower(i4, hn::Max(p, swapped), hn::Min(p, swapped));
    const auto last =
        hn::InterleaveLower(i4, hn::Set(i4, grid.width - 1), hn::Set(i4, grid.height - 1));
    q = hn::Max(q, hn::ConcatUpperLower(i4, hn::Set(i4, -(1 << 30)), hn::Zero(i4)));
    q = hn::Min(q, hn::ConcatUpperLower(i4, last, hn::Set(i4, 1 << 30)));
    const auto empty = hn::And(hn::Gt(q, hn::Shuffle1032(q)), hn::FirstN(i4, 2));
    if (!hn::AllFalse(i4, empty)) return WindowRectResult::kOutsideView;
    const int x0 = hn::GetLane(q), y0 = hn::ExtractLane(q, 1);
    const int x1 = hn::ExtractLane(q, 2), y1 = hn::ExtractLane(q, 3);
    return RectOccludedImpl(grid, x0, y0, x1, y1, nearest - 0x1p-20f) ? WindowRectResult::kOccluded
                                                                      : WindowRectResult::kVisible;
#endif
}

// Triangle setup, many triangles at once (one per lane), in float. The error margins are those
// of occluder_setup.cpp, which explains them; in float the depth plane's own error is measured
// at the vertices (the plane and the true interpolant are both affine, so inside the triangle
// they differ by at most the larger residual) and added to the bias.
// Lanes that need clipping (or hold NaN/Inf) go through setup_occluder in submission order.

// AVX2 and AVX-512 vectors hold two or four whole vertices: LoadCorners reads them.
#undef ZRASTER_TRANSPOSE_CORNERS
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
#define ZRASTER_TRANSPOSE_CORNERS 1
// x, y, z, w of vertex index[l] for each lane l, as LoadInterleaved4 of the vertices copied
// side by side would give: each vertex read as one 128-bit block, the blocks combined and
// transposed in registers. (Copies through the stack stalled: wide loads of narrow stores.)
template <class DF>
HWY_INLINE void LoadCorners(DF df, const float* clip, const std::uint32_t* index, hn::Vec<DF>& x,
                            hn::Vec<DF>& y, hn::Vec<DF>& z, hn::Vec<DF>& w) {
    constexpr std::size_t kLanes = hn::MaxLanes(DF());
    static_assert(kLanes == 8 || kLanes == 16, "two or four vertices per vector");
    const hn::Full128<float> d4;
    const auto block = [&](std::size_t l) {
        return hn::LoadU(d4, clip + 4 * std::size_t{index[l]});
    };
    hn::Vec<DF> v[4];  // v[j]: the vertices of lanes j * kLanes / 4 ..., x y z w each
    for (std::size_t j = 0; j < 4; ++j) {
        if constexpr (kLanes == 16) {
            const hn::Half<DF> dh;
            v[j] = hn::Combine(df, hn::Combine(dh, block(4 * j + 3), block(4 * j + 2)),
                               hn::Combine(dh, block(4 * j + 1), block(4 * j)));
        } else {
            v[j] = hn::Combine(df, block(2 * j + 1), block(2 * j));
        }
    }
    // (x z) and (y w) pairs of each half, then the components in lane order.
    const auto xz_lo = hn::ConcatEven(df, v[1], v[0]), yw_lo = hn::ConcatOdd(df, v[1], v[0]);
    const auto xz_hi = hn::ConcatEven(df, v[3], v[2]), yw_hi = hn::ConcatOdd(df, v[3], v[2]);
    x = hn::ConcatEven(df, xz_hi, xz_lo);
    z = hn::ConcatOdd(df, xz_hi, xz_lo);
    y = hn::ConcatEven(df, yw_hi, yw_lo);
    w = hn::ConcatOdd(df, yw_hi, yw_lo);
}
#else
#define ZRASTER_TRANSPOSE_CORNERS 0
#endif

std::size_t SetupOccluders(const OccluderSource& src, std::size_t first, std::size_t count,
                           OccluderBatch& out) {
    namespace k = occluder_setup;
    if (src.vertex_count == 0) return 0;
    const DF df;
    const DI di;
    const DU du;
    constexpr std::size_t kMaxLanes = kOcclusionTileHeight;
    const std::size_t lanes = hn::Lanes(df);
    alignas(64) float corners[3][kMaxLanes * 4];  // x, y, z, w of each lane's corner v
    alignas(64) std::int32_t box[4][kMaxLanes];
    alignas(64) float fields[k::kFloatFields][kMaxLanes];  // for vectors with a clipped lane
    alignas(64) float keep_lanes[kMaxLanes], fast_lanes[kMaxLanes];
    alignas(64) std::int32_t interior[kMaxLanes];
    // Corner indices of each lane's triangle and of its neighbours in the index list; the two
    // fillers never equal each other nor a valid index.
    constexpr std::uint32_t kNoTriangle = 0xfffffffeu, kNoNeighbour = 0xffffffffu;
    alignas(64) std::uint32_t own[3][kMaxLanes], previous[3][kMaxLanes], next[3][kMaxLanes];
    const float guard_x = 1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.width);
    const float guard_y = 1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.height);
    const auto zero = hn::Zero(df), half = hn::Set(df, 0.5f), one = hn::Set(df, 1.0f);
    const auto width = hn::Set(df, static_cast<float>(src.width));
    const auto height = hn::Set(df, static_cast<float>(src.height));
    const auto max_x = hn::Set(df, static_cast<float>(src.width - 1));
    const auto max_y = hn::Set(df, static_cast<float>(src.height - 1));
    const auto margin_base = hn::Set(df, k::kMarginBase + src.subpixel_margin);
    const auto float_margin_base = hn::Set(df, k::kMarginBase);
    const auto margin_per = hn::Set(df, k::kMarginPerCoordinate);
    const auto slack = hn::Set(df, k::kDepthSlack);
    const auto no_edge = hn::Set(df, kNoEdge), minus_no_edge = hn::Set(df, -kNoEdge);
    const auto min_f = [](auto a, auto b) { return hn::IfThenElse(hn::Lt(a, b), a, b); };
    const auto max_f = [](auto a, auto b) { return hn::IfThenElse(hn::Gt(a, b), a, b); };
    OccluderOptions options;
    options.cull = src.cull_back    ? OccluderCull::Back
                   : src.cull_front ? OccluderCull::Front
                                    : OccluderCull::None;
    options.front_face_clockwise = src.front_face_clockwise;
    options.subpixel_margin = src.subpixel_margin;
    std::size_t n = 0;
    for (std::size_t base = 0; base < count; base += lanes) {
        const std::size_t m = std::min(lanes, count - base);
        std::uint32_t valid = 0;
        // The corners' x, y, z, w, when the vector path loaded them straight into registers.
        hn::Vec<DF> cx[3], cy[3], cz[3], cw[3];
        bool loaded = false;
        const std::size_t i0 = first + base;
        if (m == lanes && i0 > 0 && i0 + lanes < src.triangle_count &&
            src.vertex_count <= 0xffffffffu) {
            // A whole vector with both neighbours in the list: the indices as vectors.
            const std::uint32_t* t = src.indices + 3 * i0;
            // The first corner of each triangle a setup group ahead: the vertex loads waited
            // on memory (the others are usually on the same or the next line).
            if (i0 + kSetupGroup + lanes <= src.triangle_count) {
                const std::uint32_t* ahead = t + 3 * kSetupGroup;
                const auto last = static_cast<std::uint32_t>(src.vertex_count - 1);
                for (std::size_t l = 0; l < lanes; ++l)
                    __builtin_prefetch(src.clip + 4 * std::size_t{std::min(ahead[3 * l], last)});
            }
            const auto limit = hn::Set(du, static_cast<std::uint32_t>(src.vertex_count));
            hn::Vec<DU> a, b, c;
            hn::LoadInterleaved3(du, t, a, b, c);
            const auto ok = hn::And(hn::And(hn::Lt(a, limit), hn::Lt(b, limit)), hn::Lt(c, limit));
            const hn::Vec<DU> corner[3] = {a, b, c};
            for (auto* other : {&previous, &next}) {
                hn::Vec<DU> d, e, f;
                hn::LoadInterleaved3(du, other == &previous ? t - 3 : t + 3, d, e, f);
                const auto filler = hn::Set(du, kNoNeighbour);
                hn::Store(hn::IfThenElse(ok, d, filler), du, (*other)[0]);
                hn::Store(hn::IfThenElse(ok, e, filler), du, (*other)[1]);
                hn::Store(hn::IfThenElse(ok, f, filler), du, (*other)[2]);
            }
            for (int v = 0; v < 3; ++v)
                hn::Store(hn::IfThenElse(ok, corner[v], hn::Set(du, kNoTriangle)), du, own[v]);
            hn::Store(hn::Zero(di), di, interior);
            alignas(64) std::uint8_t bits[8] = {};
            hn::StoreMaskBits(du, ok, bits);
            std::memcpy(&valid, bits, sizeof(valid));  // lanes <= 16: the low bytes, little endian
            valid &= lanes >= 32 ? ~0u : (1u << lanes) - 1u;
            // Lanes with a bad index read vertex 0 (there is one); their results are dropped.
            alignas(64) std::uint32_t read[3][kMaxLanes];
            for (int v = 0; v < 3; ++v) hn::Store(hn::IfThenElseZero(ok, corner[v]), du, read[v]);
#if ZRASTER_TRANSPOSE_CORNERS
            for (int v = 0; v < 3; ++v)
                LoadCorners(df, src.clip, read[v], cx[v], cy[v], cz[v], cw[v]);
            loaded = true;
#else
            for (std::size_t l = 0; l < lanes; ++l)
                for (int v = 0; v < 3; ++v)
                    std::memcpy(corners[v] + 4 * l, src.clip + 4 * std::size_t{read[v][l]},
                                4 * sizeof(float));
#endif
        } else {
            for (std::size_t l = 0; l < lanes; ++l) {
                interior[l] = 0;
                for (int v = 0; v < 3; ++v) {
                    own[v][l] = kNoTriangle;
                    previous[v][l] = next[v][l] = kNoNeighbour;
                }
                const std::size_t i = first + base + l;
                const std::uint32_t* t = l < m ? src.indices + 3 * i : nullptr;
                if (!t || t[0] >= src.vertex_count || t[1] >= src.vertex_count ||
                    t[2] >= src.vertex_count) {
                    for (int v = 0; v < 3; ++v) std::fill_n(corners[v] + 4 * l, 4, 0.0f);
                    continue;
                }
                valid |= 1u << l;
                for (int v = 0; v < 3; ++v) {
                    std::memcpy(corners[v] + 4 * l, src.clip + 4 * std::size_t{t[v]},
                                4 * sizeof(float));
                    own[v][l] = t[v];
                    if (i > 0) previous[v][l] = t[v - 3];
                    if (i + 1 < src.triangle_count) next[v][l] = t[v + 3];
                }
            }
        }
        // Interior edges: a quick vector search for an edge shared (reversed) with either
        // neighbour; only lanes that have one ask interior_edges, which also checks facing.
        {
            const hn::Vec<DU> a = hn::Load(du, own[0]), b = hn::Load(du, own[1]),
                              c = hn::Load(du, own[2]);
            auto found = hn::Ne(a, a);
            for (const auto* other : {&previous, &next}) {
                const hn::Vec<DU> d = hn::Load(du, (*other)[0]), e = hn::Load(du, (*other)[1]),
                                  f = hn::Load(du, (*other)[2]);
                const auto reversed = [&](hn::Vec<DU> x, hn::Vec<DU> y) {
                    return hn::Or(hn::Or(hn::And(hn::Eq(x, e), hn::Eq(y, d)),
                                         hn::And(hn::Eq(x, f), hn::Eq(y, e))),
                                  hn::And(hn::Eq(x, d), hn::Eq(y, f)));
                };
                found =
                    hn::Or(found, hn::Or(hn::Or(reversed(a, b), reversed(b, c)), reversed(c, a)));
            }
            if (!hn::AllFalse(du, found)) {
                hn::Store(hn::IfThenElseZero(found, hn::Set(du, 1u)), du, own[0]);
                for (std::size_t l = 0; l < m; ++l)
                    if (own[0][l] != 0)
                        interior[l] =
                            static_cast<std::int32_t>(interior_edges(src, first + base + l));
            }
        }
        hn::Vec<DF> X[3], Y[3], Z[3];
        auto fast = hn::Eq(zero, zero);
        for (int v = 0; v < 3; ++v) {
            hn::Vec<DF> x = cx[v], y = cy[v], z = cz[v], w = cw[v];
            if (!loaded) hn::LoadInterleaved4(df, corners[v], x, y, z, w);
            // In front of the near plane, before the far plane, inside the guard band (false
            // for NaN): no clipping needed.
            fast = hn::And(fast, hn::And(hn::Gt(w, zero), hn::Lt(w, hn::Set(df, k::kMaxW))));
            fast = hn::And(fast, hn::And(hn::Ge(z, hn::Neg(w)), hn::Le(z, w)));
            fast = hn::And(fast, hn::Le(hn::Abs(x), hn::Mul(hn::Set(df, guard_x), w)));
            fast = hn::And(fast, hn::Le(hn::Abs(y), hn::Mul(hn::Set(df, guard_y), w)));
            const auto inv_w = hn::Div(one, w);
            X[v] = hn::Mul(hn::Add(hn::Mul(hn::Mul(x, inv_w), half), half), width);
            Y[v] = hn::Mul(hn::Sub(half, hn::Mul(hn::Mul(y, inv_w), half)), height);
            Z[v] = hn::Add(hn::Mul(hn::Mul(z, inv_w), half), half);
        }
        const auto area2 = hn::Sub(hn::Mul(hn::Sub(X[1], X[0]), hn::Sub(Y[2], Y[0])),
                                   hn::Mul(hn::Sub(Y[1], Y[0]), hn::Sub(X[2], X[0])));
        const auto counter_clockwise = hn::Lt(area2, zero);
        const auto front =
            src.front_face_clockwise ? hn::Not(counter_clockwise) : counter_clockwise;
        auto keep = hn::And(fast, hn::Ne(area2, zero));
        if (src.cull_back) keep = hn::And(keep, front);
        if (src.cull_front) keep = hn::AndNot(front, keep);

        auto max_abs = hn::Abs(X[0]);
        max_abs = max_f(max_abs, hn::Abs(Y[0]));
        auto xmin = X[0], xmax = X[0], ymin = Y[0], ymax = Y[0], zmax = Z[0];
        for (int v = 1; v < 3; ++v) {
            max_abs = max_f(max_abs, hn::Abs(X[v]));
            max_abs = max_f(max_abs, hn::Abs(Y[v]));
            xmin = min_f(xmin, X[v]);
            xmax = max_f(xmax, X[v]);
            ymin = min_f(ymin, Y[v]);
            ymax = max_f(ymax, Y[v]);
            zmax = max_f(zmax, Z[v]);
        }
        const auto float_margin = hn::Add(float_margin_base, hn::Mul(max_abs, margin_per));
        const auto margin = hn::Add(margin_base, hn::Mul(max_abs, margin_per));
        const auto interior_bits = hn::Load(di, interior);
        const auto x0 = max_f(hn::Ceil(hn::Sub(xmin, half)), zero);
        const auto x1 = min_f(hn::Floor(hn::Sub(xmax, half)), max_x);
        const auto y0 = max_f(hn::Ceil(hn::Sub(hn::Add(ymin, margin), half)), zero);
        const auto y1 = min_f(hn::Floor(hn::Sub(hn::Sub(ymax, margin), half)), max_y);
        keep = hn::And(keep, hn::And(hn::Le(x0, x1), hn::Le(y0, y1)));

        const auto row0 = hn::Add(y0, half);
        hn::Vec<DF> left_x[3], left_step[3], right_x[3], right_step[3];
        hn::Mask<DF> left[3], right[3];
        for (int e = 0; e < 3; ++e) {
            const hn::Vec<DF>&ax = X[e], &ay = Y[e], &bx = X[(e + 1) % 3], &by = Y[(e + 1) % 3];
            const auto dy = hn::Sub(by, ay);
            const auto slanted = hn::Ge(hn::Abs(dy), hn::Set(df, k::kHorizontal));
            const auto step = hn::Div(hn::Sub(bx, ax), hn::IfThenElse(slanted, dy, one));
            const auto x = hn::Add(ax, hn::Mul(hn::Sub(row0, ay), step));
            // Interior edges move outwards by the float error instead (see interior_edges).
            const auto is_interior = hn::RebindMask(
                df, hn::Ne(hn::And(interior_bits, hn::Set(di, 1 << e)), hn::Zero(di)));
            const auto inset = hn::Mul(hn::Add(one, hn::Abs(step)),
                                       hn::IfThenElse(is_interior, hn::Neg(float_margin), margin));
            // The inside is to the right of the edge when area2 * dy < 0.
            const auto left_side = hn::Xor(counter_clockwise, hn::Lt(dy, zero));
            const auto is_left = hn::And(slanted, left_side);
            const auto is_right = hn::AndNot(left_side, slanted);
            left[e] = is_left;
            right[e] = is_right;
            left_x[e] = hn::IfThenElse(is_left, hn::Add(x, inset), minus_no_edge);
            left_step[e] = hn::IfThenElseZero(is_left, step);
            right_x[e] = hn::IfThenElse(is_right, hn::Sub(x, inset), no_edge);
            right_step[e] = hn::IfThenElseZero(is_right, step);
        }
        // At most two edges per side (their dy share a sign): two slots each (see kEdgeSlots).
        // Slot 0 takes the first edge of the side, slot 1 the second (or the last edge again).
        const auto pack = [&](const hn::Vec<DF>* v, const hn::Mask<DF>* is, int slot) {
            return slot == 0 ? hn::IfThenElse(is[0], v[0], hn::IfThenElse(is[1], v[1], v[2]))
                             : hn::IfThenElse(hn::And(is[0], is[1]), v[1], v[2]);
        };
        hn::Vec<DF> f[k::kFloatFields];
        for (int slot = 0; slot < kEdgeSlots; ++slot) {
            f[k::kLeftX + slot] = pack(left_x, left, slot);
            f[k::kLeftStep + slot] = pack(left_step, left, slot);
            f[k::kRightX + slot] = pack(right_x, right, slot);
            f[k::kRightStep + slot] = pack(right_step, right, slot);
        }

        const auto e1x = hn::Sub(X[1], X[0]), e1y = hn::Sub(Y[1], Y[0]), e1z = hn::Sub(Z[1], Z[0]);
        const auto e2x = hn::Sub(X[2], X[0]), e2y = hn::Sub(Y[2], Y[0]), e2z = hn::Sub(Z[2], Z[0]);
        const auto gx = hn::Div(hn::Sub(hn::Mul(e1z, e2y), hn::Mul(e2z, e1y)), area2);
        const auto gy = hn::Div(hn::Sub(hn::Mul(e1x, e2z), hn::Mul(e2x, e1z)), area2);
        const auto err1 = hn::Abs(hn::Sub(hn::Add(hn::Mul(gx, e1x), hn::Mul(gy, e1y)), e1z));
        const auto err2 = hn::Abs(hn::Sub(hn::Add(hn::Mul(gx, e2x), hn::Mul(gy, e2y)), e2z));
        const auto residual = max_f(err1, err2);
        const auto extent = hn::Add(hn::Add(max_abs, hn::Sub(x1, x0)), hn::Sub(y1, y0));
        auto spread =
            hn::Mul(hn::Add(hn::Abs(gx), hn::Abs(gy)), hn::Add(extent, hn::Set(df, 4.0f)));
        spread = hn::Add(hn::Add(one, spread), hn::Add(hn::Abs(e1z), hn::Abs(e2z)));
        // Pixels up to a margin outside the triangle (interior edges) see the plane extended.
        const auto reach = hn::Mul(hn::Add(hn::Abs(gx), hn::Abs(gy)), hn::Add(margin, margin));
        const auto bias =
            hn::Add(hn::Add(hn::Add(residual, residual), hn::Mul(slack, spread)), reach);
        const auto sane = hn::And(hn::Lt(hn::Abs(gx), hn::Set(df, k::kHugeGradient)),
                                  hn::Lt(hn::Abs(gy), hn::Set(df, k::kHugeGradient)));
        const auto z_max = hn::Add(zmax, slack);
        f[k::kZOrigin] = hn::IfThenElse(sane, Z[0], z_max);
        f[k::kZDx] = hn::IfThenElseZero(sane, gx);
        f[k::kZDy] = hn::IfThenElseZero(sane, gy);
        f[k::kZKx] = hn::IfThenElseZero(sane, hn::Sub(hn::Add(x0, half), X[0]));
        f[k::kZKy] = hn::IfThenElseZero(sane, hn::Sub(row0, Y[0]));
        f[k::kZBias] = hn::IfThenElseZero(sane, bias);
        f[k::kZMax] = z_max;
        // Integral and inside the guard band in kept lanes (the others are dropped).
        const hn::Vec<DI> bounds[4] = {TruncInRange(x0), TruncInRange(x1), TruncInRange(y0),
                                       TruncInRange(y1)};
        std::int32_t* const out_bounds[4] = {out.x0, out.x1, out.y0, out.y1};

        alignas(8) std::uint8_t valid_bytes[8] = {};
        std::memcpy(valid_bytes, &valid, sizeof(valid));  // little endian, as StoreMaskBits
        const auto valid_lanes = hn::LoadMaskBits(df, valid_bytes);
        if (hn::AllFalse(df, hn::AndNot(fast, valid_lanes))) {
            // No lane to clip (the usual case): the kept lanes go out in order, straight into
            // the batch, one register compress and store per field.
            const auto take = hn::And(keep, valid_lanes);
            const auto take_i = hn::RebindMask(di, take);
            for (int field = 0; field < k::kFloatFields; ++field)
                hn::StoreU(CompressLanes(df, f[field], take), df, out.field[field] + n);
            for (int b = 0; b < 4; ++b)
                hn::StoreU(CompressLanes(di, bounds[b], take_i), di, out_bounds[b] + n);
            n += hn::CountTrue(df, take);
            continue;
        }
        // Some lane needs clipping: lane by lane, in submission order.
        for (int field = 0; field < k::kFloatFields; ++field)
            hn::Store(f[field], df, fields[field]);
        for (int b = 0; b < 4; ++b) hn::Store(bounds[b], di, box[b]);
        hn::Store(hn::IfThenElseZero(keep, one), df, keep_lanes);
        hn::Store(hn::IfThenElseZero(fast, one), df, fast_lanes);
        for (std::size_t l = 0; l < m; ++l) {
            if (!((valid >> l) & 1u)) continue;
            if (fast_lanes[l] == 0.0f) {
                const std::uint32_t* t = src.indices + 3 * (first + base + l);
                const auto vertex = [&](std::uint32_t i) {
                    const float* p = src.clip + 4 * std::size_t{i};
                    return glm::vec4(p[0], p[1], p[2], p[3]);
                };
                OccluderTriangle pieces[kMaxOccluderPieces];
                const int made = setup_occluder(vertex(t[0]), vertex(t[1]), vertex(t[2]), src.width,
                                                src.height, options, pieces);
                for (int p = 0; p < made; ++p) out.set(n++, pieces[p]);
                continue;
            }
            if (keep_lanes[l] == 0.0f) continue;
            for (int b = 0; b < 4; ++b) out_bounds[b][n] = box[b][l];
            for (int field = 0; field < k::kFloatFields; ++field)
                out.field[field][n] = fields[field][l];
            ++n;
        }
    }
    return n;
}

const char* OcclusionTargetName() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(RasterizeOccluders);
HWY_EXPORT(SetupOccluders);
HWY_EXPORT(RectOccluded);
HWY_EXPORT(WindowRectTest);
HWY_EXPORT(RefreshCoarseLevels);
HWY_EXPORT(OcclusionTargetName);

void rasterize_occluders(const OccluderBatch& triangles, std::size_t count, TileGrid grid) {
    HWY_DYNAMIC_DISPATCH(RasterizeOccluders)(triangles, count, grid);
}

std::size_t setup_occluders(const OccluderSource& source, std::size_t first, std::size_t count,
                            OccluderBatch& out) {
    return HWY_DYNAMIC_DISPATCH(SetupOccluders)(source, first, count, out);
}

bool rect_occluded(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth) {
    return HWY_DYNAMIC_DISPATCH(RectOccluded)(grid, x0, y0, x1, y1, depth);
}

WindowRectResult window_rect_test(const TileGrid& grid, float xmin, float xmax, float ymin,
                                  float ymax, float nearest) {
    return HWY_DYNAMIC_DISPATCH(WindowRectTest)(grid, xmin, xmax, ymin, ymax, nearest);
}

void refresh_coarse_levels(TileGrid grid, int tx0, int ty0, int tx1, int ty1) {
    HWY_DYNAMIC_DISPATCH(RefreshCoarseLevels)(grid, tx0, ty0, tx1, ty1);
}

void refresh_coarse_levels_scalar(TileGrid grid, int tx0, int ty0, int tx1, int ty1) {
    for (int ty = ty0; ty <= ty1; ++ty)
        for (int tx = tx0; tx <= tx1; ++tx) {
            const std::size_t i = static_cast<std::size_t>(ty) * grid.tiles_x + tx;
            const TileRows t = tile_rows(grid, tx, ty);
            float hi = t.far_depth[0], lo = t.far_depth[0];
            for (int r = 0; r < kOcclusionTileHeight; ++r) {
                const float bound = t.mask[r] != 0 ? t.near_depth[r] : t.far_depth[r];
                hi = t.far_depth[r] > hi ? t.far_depth[r] : hi;
                lo = bound < lo ? bound : lo;
            }
            grid.coarse[2 * i] = lo;
            grid.coarse[2 * i + 1] = hi;
            const std::size_t block_row = 2 * static_cast<std::size_t>(grid.tiles_x);
            float* blocks = grid.block_max + 2 * static_cast<std::size_t>(ty) * block_row + 2 * tx;
            for (int by = 0; by < 2; ++by)
                for (int bx = 0; bx < 2; ++bx) {
                    const std::uint32_t half = ((1u << kOcclusionBlockSide) - 1u)
                                               << (bx * kOcclusionBlockSide);
                    float largest = -HUGE_VALF;
                    for (int r = by * kOcclusionBlockSide; r < (by + 1) * kOcclusionBlockSide;
                         ++r) {
                        const float bound =
                            (t.mask[r] & half) == half ? t.near_depth[r] : t.far_depth[r];
                        largest = bound > largest ? bound : largest;
                    }
                    blocks[by * block_row + bx] = largest;
                }
        }
}

const char* occlusion_kernel_target() {
    return HWY_DYNAMIC_DISPATCH(OcclusionTargetName)();
}

namespace {

std::uint32_t low_bits_scalar(int n) {
    return n >= 32 ? ~0u : ~(~0u << n);
}

}  // namespace

// Lane by lane, the operations of RasterizeOccluders in the same order.
void rasterize_occluders_scalar(const OccluderBatch& b, std::size_t count, TileGrid grid) {
    namespace k = occluder_setup;
    for (std::size_t i = 0; i < count; ++i) {
        OccluderTriangle t;
        t.x0 = b.x0[i];
        t.x1 = b.x1[i];
        t.y0 = b.y0[i];
        t.y1 = b.y1[i];
        for (int e = 0; e < kEdgeSlots; ++e) {
            t.left_x[e] = b.field[k::kLeftX + e][i];
            t.left_step[e] = b.field[k::kLeftStep + e][i];
            t.right_x[e] = b.field[k::kRightX + e][i];
            t.right_step[e] = b.field[k::kRightStep + e][i];
        }
        t.z_origin = b.field[k::kZOrigin][i];
        t.z_dx = b.field[k::kZDx][i];
        t.z_dy = b.field[k::kZDy][i];
        t.z_kx = b.field[k::kZKx][i];
        t.z_ky = b.field[k::kZKy][i];
        t.z_bias = b.field[k::kZBias][i];
        t.z_max = b.field[k::kZMax][i];
        const float span_lo = static_cast<float>(t.x0), span_hi = static_cast<float>(t.x1 + 1);
        for (int y = t.y0; y <= t.y1; ++y) {
            const float yf = static_cast<float>(y - t.y0);
            const float l0 = t.left_x[0] + yf * t.left_step[0];
            const float l1 = t.left_x[1] + yf * t.left_step[1];
            const float r0 = t.right_x[0] + yf * t.right_step[0];
            const float r1 = t.right_x[1] + yf * t.right_step[1];
            const float xl = l0 > l1 ? l0 : l1;
            const float xr = r0 < r1 ? r0 : r1;
            float lo = xl + 0.5f;
            lo = lo < span_lo ? span_lo : lo;
            lo = lo > span_hi ? span_hi : lo;
            float hi = xr - 0.5f;
            hi = hi < span_lo ? span_lo : hi;
            hi = hi > span_hi ? span_hi : hi;
            const int first = static_cast<int>(std::floor(lo));
            const int end = static_cast<int>(std::ceil(hi));
            const float row_depth = (t.z_origin + t.z_dy * (yf + t.z_ky)) + t.z_bias;
            const int row_extreme = t.z_dx > 0.0f ? (end - 1) - t.x0 : first - t.x0;
            float row_bound = row_depth + t.z_dx * (static_cast<float>(row_extreme) + t.z_kx);
            row_bound = row_bound < t.z_max ? row_bound : t.z_max;
            for (int tx = t.x0 / kOcclusionTileWidth; tx <= t.x1 / kOcclusionTileWidth; ++tx) {
                const std::size_t at = row_index(grid, tx, y);
                const int s =
                    std::min(std::max(first - tx * kOcclusionTileWidth, 0), kOcclusionTileWidth);
                const int e =
                    std::min(std::max(end - tx * kOcclusionTileWidth, 0), kOcclusionTileWidth);
                const std::uint32_t coverage = ~low_bits_scalar(s) & low_bits_scalar(e);
                if (coverage == 0) continue;
                const float tile_bound = row_depth + tile_depth_step(t.z_dx, t.z_kx, t.x0, tx);
                const float z = row_bound < tile_bound ? row_bound : tile_bound;

                const std::uint32_t mask = grid.mask[at];
                const float far_depth = grid.far_depth[at], near_depth = grid.near_depth[at];
                if (!(z < far_depth)) continue;
                const bool discard = near_depth - z > far_depth - near_depth;
                std::uint32_t merged_mask = discard ? 0u : mask;
                float merged_near = discard ? 0.0f : near_depth;
                merged_mask |= coverage;
                merged_near = merged_near < z ? z : merged_near;
                const bool full = merged_mask == kOcclusionFullMask;
                const bool covers_row = coverage == kOcclusionFullMask;
                grid.far_depth[at] = full ? (covers_row ? z : merged_near) : far_depth;
                grid.mask[at] = full ? 0u : merged_mask;
                grid.near_depth[at] = full ? 0.0f : merged_near;
            }
        }
    }
}

// Lane by lane, the operations of SetupOccluders in the same order.
std::size_t setup_occluders_scalar(const OccluderSource& src, std::size_t first, std::size_t count,
                                   OccluderBatch& batch) {
    namespace k = occluder_setup;
    const float guard_x = 1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.width);
    const float guard_y = 1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.height);
    const float width = static_cast<float>(src.width), height = static_cast<float>(src.height);
    const float max_x = static_cast<float>(src.width - 1);
    const float max_y = static_cast<float>(src.height - 1);
    const auto min_f = [](float a, float b) { return a < b ? a : b; };
    const auto max_f = [](float a, float b) { return a > b ? a : b; };
    OccluderOptions options;
    options.cull = src.cull_back    ? OccluderCull::Back
                   : src.cull_front ? OccluderCull::Front
                                    : OccluderCull::None;
    options.front_face_clockwise = src.front_face_clockwise;
    options.subpixel_margin = src.subpixel_margin;
    std::size_t n = 0;
    for (std::size_t i = first; i < first + count; ++i) {
        const std::uint32_t* t = src.indices + 3 * i;
        if (t[0] >= src.vertex_count || t[1] >= src.vertex_count || t[2] >= src.vertex_count)
            continue;
        const std::uint32_t interior = interior_edges(src, i);
        float X[3], Y[3], Z[3];
        bool fast = true;
        for (int v = 0; v < 3; ++v) {
            const float* p = src.clip + 4 * std::size_t{t[v]};
            const float x = p[0], y = p[1], z = p[2], w = p[3];
            fast = fast && (w > 0.0f && w < k::kMaxW);
            fast = fast && (z >= -w && z <= w);
            fast = fast && std::fabs(x) <= guard_x * w;
            fast = fast && std::fabs(y) <= guard_y * w;
            const float inv_w = 1.0f / w;
            X[v] = ((x * inv_w) * 0.5f + 0.5f) * width;
            Y[v] = (0.5f - (y * inv_w) * 0.5f) * height;
            Z[v] = (z * inv_w) * 0.5f + 0.5f;
        }
        if (!fast) {
            const auto vertex = [&](std::uint32_t j) {
                const float* p = src.clip + 4 * std::size_t{j};
                return glm::vec4(p[0], p[1], p[2], p[3]);
            };
            OccluderTriangle pieces[kMaxOccluderPieces];
            const int made = setup_occluder(vertex(t[0]), vertex(t[1]), vertex(t[2]), src.width,
                                            src.height, options, pieces);
            for (int p = 0; p < made; ++p) batch.set(n++, pieces[p]);
            continue;
        }
        const float area2 = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
        const bool counter_clockwise = area2 < 0.0f;
        const bool front = src.front_face_clockwise ? !counter_clockwise : counter_clockwise;
        bool keep = area2 != 0.0f;
        if (src.cull_back) keep = keep && front;
        if (src.cull_front) keep = keep && !front;
        float max_abs = std::fabs(X[0]);
        max_abs = max_f(max_abs, std::fabs(Y[0]));
        float xmin = X[0], xmax = X[0], ymin = Y[0], ymax = Y[0], zmax = Z[0];
        for (int v = 1; v < 3; ++v) {
            max_abs = max_f(max_abs, std::fabs(X[v]));
            max_abs = max_f(max_abs, std::fabs(Y[v]));
            xmin = min_f(xmin, X[v]);
            xmax = max_f(xmax, X[v]);
            ymin = min_f(ymin, Y[v]);
            ymax = max_f(ymax, Y[v]);
            zmax = max_f(zmax, Z[v]);
        }
        const float float_margin = k::kMarginBase + max_abs * k::kMarginPerCoordinate;
        const float margin =
            (k::kMarginBase + src.subpixel_margin) + max_abs * k::kMarginPerCoordinate;
        const float x0 = max_f(std::ceil(xmin - 0.5f), 0.0f);
        const float x1 = min_f(std::floor(xmax - 0.5f), max_x);
        const float y0 = max_f(std::ceil((ymin + margin) - 0.5f), 0.0f);
        const float y1 = min_f(std::floor((ymax - margin) - 0.5f), max_y);
        keep = keep && x0 <= x1 && y0 <= y1;
        if (!keep) continue;
        OccluderTriangle o;
        const float row0 = y0 + 0.5f;
        float left_x[3], left_step[3], right_x[3], right_step[3];
        bool left[3], right[3];
        for (int e = 0; e < 3; ++e) {
            const float ax = X[e], ay = Y[e], bx = X[(e + 1) % 3], by = Y[(e + 1) % 3];
            const float dy = by - ay;
            const bool slanted = std::fabs(dy) >= k::kHorizontal;
            const float step = (bx - ax) / (slanted ? dy : 1.0f);
            const float x = ax + (row0 - ay) * step;
            const bool is_interior = (interior >> e) & 1u;
            const float inset = (1.0f + std::fabs(step)) * (is_interior ? -float_margin : margin);
            const bool left_side = counter_clockwise != (dy < 0.0f);
            const bool is_left = slanted && left_side, is_right = slanted && !left_side;
            left[e] = is_left;
            right[e] = is_right;
            left_x[e] = is_left ? x + inset : -kNoEdge;
            left_step[e] = is_left ? step : 0.0f;
            right_x[e] = is_right ? x - inset : kNoEdge;
            right_step[e] = is_right ? step : 0.0f;
        }
        const auto pack = [](const float* v, const bool* is, int slot) {
            return slot == 0 ? (is[0] ? v[0] : (is[1] ? v[1] : v[2]))
                             : (is[0] && is[1] ? v[1] : v[2]);
        };
        for (int slot = 0; slot < kEdgeSlots; ++slot) {
            o.left_x[slot] = pack(left_x, left, slot);
            o.left_step[slot] = pack(left_step, left, slot);
            o.right_x[slot] = pack(right_x, right, slot);
            o.right_step[slot] = pack(right_step, right, slot);
        }
        const float e1x = X[1] - X[0], e1y = Y[1] - Y[0], e1z = Z[1] - Z[0];
        const float e2x = X[2] - X[0], e2y = Y[2] - Y[0], e2z = Z[2] - Z[0];
        const float gx = (e1z * e2y - e2z * e1y) / area2;
        const float gy = (e1x * e2z - e2x * e1z) / area2;
        const float err1 = std::fabs((gx * e1x + gy * e1y) - e1z);
        const float err2 = std::fabs((gx * e2x + gy * e2y) - e2z);
        const float residual = max_f(err1, err2);
        const float extent = (max_abs + (x1 - x0)) + (y1 - y0);
        float spread = (std::fabs(gx) + std::fabs(gy)) * (extent + 4.0f);
        spread = (1.0f + spread) + (std::fabs(e1z) + std::fabs(e2z));
        const float reach = (std::fabs(gx) + std::fabs(gy)) * (margin + margin);
        const float bias = ((residual + residual) + k::kDepthSlack * spread) + reach;
        const bool sane = std::fabs(gx) < k::kHugeGradient && std::fabs(gy) < k::kHugeGradient;
        const float z_max = zmax + k::kDepthSlack;
        o.z_origin = sane ? Z[0] : z_max;
        o.z_dx = sane ? gx : 0.0f;
        o.z_dy = sane ? gy : 0.0f;
        o.z_kx = sane ? (x0 + 0.5f) - X[0] : 0.0f;
        o.z_ky = sane ? row0 - Y[0] : 0.0f;
        o.z_bias = sane ? bias : 0.0f;
        o.z_max = z_max;
        o.x0 = static_cast<int>(x0);
        o.x1 = static_cast<int>(x1);
        o.y0 = static_cast<int>(y0);
        o.y1 = static_cast<int>(y1);
        batch.set(n++, o);
    }
    return n;
}

bool rect_occluded_scalar(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth) {
    for (int y = y0; y <= y1; ++y) {
        const int ty = y / kOcclusionTileHeight, r = y % kOcclusionTileHeight;
        for (int tx = x0 / kOcclusionTileWidth; tx <= x1 / kOcclusionTileWidth; ++tx) {
            const TileRows tile = tile_rows(grid, tx, ty);
            const int s = std::max(x0 - tx * kOcclusionTileWidth, 0);
            const int e = std::min(x1 + 1 - tx * kOcclusionTileWidth, kOcclusionTileWidth);
            const std::uint32_t rect_mask = ~low_bits_scalar(s) & low_bits_scalar(e);
            const bool uncovered = (rect_mask & ~tile.mask[r]) != 0;
            const float bound = uncovered ? tile.far_depth[r] : tile.near_depth[r];
            if (!(bound < depth)) return false;
        }
    }
    return true;
}

WindowRectResult window_rect_test_scalar(const TileGrid& grid, float xmin, float xmax, float ymin,
                                         float ymax, float nearest) {
    const float w = static_cast<float>(grid.width), h = static_cast<float>(grid.height);
    // Values, not references (std::max): branch-free minss/maxss.
    const auto max_f = [](float a, float b) { return a > b ? a : b; };
    const auto min_f = [](float a, float b) { return a < b ? a : b; };
    const float max_abs =
        max_f(max_f(std::abs(xmin), std::abs(xmax)), max_f(std::abs(ymin), std::abs(ymax)));
    // Grow by more than the snapping of an exact rasterizer and the float error of the corners.
    const float margin = 0x1p-6f + max_abs * 0x1p-17f;
    // Pixels whose center may be inside [min - margin, max + margin]; clamped first so that the
    // conversions stay in range (floor and ceil by hand: no libm call per test).
    const auto clamped = [&](float v, float limit) { return min_f(max_f(v - 0.5f, -2.0f), limit); };
    const auto floor_int = [](float v) {
        const int i = static_cast<int>(v);
        return i - (v < static_cast<float>(i));
    };
    const auto ceil_int = [](float v) {
        const int i = static_cast<int>(v);
        return i + (v > static_cast<float>(i));
    };
    int x0 = ceil_int(clamped(xmin - margin, w + 1.0f));
    int x1 = floor_int(clamped(xmax + margin, w + 1.0f));
    int y0 = ceil_int(clamped(ymin - margin, h + 1.0f));
    int y1 = floor_int(clamped(ymax + margin, h + 1.0f));
    // Between pixel centers: test the neighbours instead of calling it hidden.
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, grid.width - 1);
    y1 = std::min(y1, grid.height - 1);
    if (x0 > x1 || y0 > y1) return WindowRectResult::kOutsideView;
    return rect_occluded_scalar(grid, x0, y0, x1, y1, nearest - 0x1p-20f)
               ? WindowRectResult::kOccluded
               : WindowRectResult::kVisible;
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
