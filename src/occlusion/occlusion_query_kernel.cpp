// Queries of the occlusion buffer (see occlusion_kernel.hpp): the coarse levels that settle
// most of a test (each tile's smallest and largest depth bound, each 8x8 block's largest), and
// the test of a pixel rectangle, or of a rectangle in window coordinates, against the tiles.
// OcclusionBuffer (occlusion_buffer.cpp) tests boxes and triangles as the window rectangles
// that bound them.
// Highway's foreach_target re-includes this file once per instruction set; the scalar twins
// and the dispatchers are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "occlusion/occlusion_query_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "occlusion/occlusion_kernel.hpp"
#include "occlusion/occlusion_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
// whose largest bound is not in front but whose smallest is are read. A tile's two levels take
// two lanes: the one-lane HWY_SCALAR target uses the scalar twin instead.
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
    // Pixel bounds are inside the grid (>= 0): tiles by unsigned shifts, without the signed
    // division's rounding fix-up on the way to the first load.
    const auto tile_of = [](int p, unsigned side) {
        return static_cast<int>(static_cast<unsigned>(p) / side);
    };
    const int tx0 = tile_of(x0, kOcclusionTileWidth), tx1 = tile_of(x1, kOcclusionTileWidth);
    const int ty0 = tile_of(y0, kOcclusionTileHeight), ty1 = tile_of(y1, kOcclusionTileHeight);
    const std::size_t row_stride = 2 * static_cast<std::size_t>(grid.tiles_x);
    const float* levels = grid.coarse + static_cast<std::size_t>(ty0) * row_stride + 2 * tx0;
    bool blocks_read = false;
    const DU du;
    const auto smallest = hn::RebindMask(
        df, hn::Eq(hn::And(hn::Iota(du, 0), hn::Set(du, 1u)), hn::Zero(du)));  // even lanes
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
            if (hn::AllFalse(df, not_in_front)) continue;
            // A tile with no bound in front: seen there (most visible rectangles end here,
            // without the call).
            if (!hn::AllFalse(df, hn::And(not_in_front, smallest))) return false;
            if (!SettleTiles(grid, not_in_front, tx, ty, x0, y0, x1, y1, depth, blocks_read))
                return false;
        }
    }
    return true;
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
#endif  // HWY_TARGET != HWY_SCALAR

bool RectOccluded(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth) {
#if HWY_TARGET == HWY_SCALAR
    return rect_occluded_scalar(grid, x0, y0, x1, y1, depth);  // one lane: no tile pairs
#else
    return RectOccludedImpl(grid, x0, y0, x1, y1, depth);
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

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(RefreshCoarseLevels);
HWY_EXPORT(RectOccluded);
HWY_EXPORT(WindowRectTest);

void refresh_coarse_levels(TileGrid grid, int tx0, int ty0, int tx1, int ty1) {
    HWY_DYNAMIC_DISPATCH(RefreshCoarseLevels)(grid, tx0, ty0, tx1, ty1);
}

bool rect_occluded(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth) {
    return HWY_DYNAMIC_DISPATCH(RectOccluded)(grid, x0, y0, x1, y1, depth);
}

WindowRectResult window_rect_test(const TileGrid& grid, float xmin, float xmax, float ymin,
                                  float ymax, float nearest) {
    return HWY_DYNAMIC_DISPATCH(WindowRectTest)(grid, xmin, xmax, ymin, ymax, nearest);
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

bool rect_occluded_scalar(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth) {
    for (int y = y0; y <= y1; ++y) {
        const int ty = y / kOcclusionTileHeight, r = y % kOcclusionTileHeight;
        for (int tx = x0 / kOcclusionTileWidth; tx <= x1 / kOcclusionTileWidth; ++tx) {
            const TileRows tile = tile_rows(grid, tx, ty);
            const int s = std::max(x0 - tx * kOcclusionTileWidth, 0);
            const int e = std::min(x1 + 1 - tx * kOcclusionTileWidth, kOcclusionTileWidth);
            const std::uint32_t rect_mask = ~low_bits(s) & low_bits(e);
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
