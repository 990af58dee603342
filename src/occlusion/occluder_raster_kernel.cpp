// Rasterizing set-up occluder triangles into the buffer's strips (see occlusion_kernel.hpp),
// after Masked Software Occlusion Culling (Andersson, Hasselgren, Akenine-Möller 2015):
// coverage is computed for a whole 16-pixel strip at once as a bit mask between the left and
// right edge crossings of the row (two shifts), one SIMD lane per pixel row, and merged into the
// two depth layers of each row:
//  - a triangle that is not nearer than the far layer anywhere in the row teaches nothing;
//  - the working layer is dropped when the triangle is further in front of it than the working
//    layer is in front of the far layer (a new, nearer surface starts);
//  - the triangle's coverage joins the mask, the near layer takes the larger (further) depth;
//  - a full mask becomes the new far layer.
// Highway's foreach_target re-includes this file once per instruction set; the scalar twin and
// the dispatchers are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "occlusion/occluder_raster_kernel.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "occlusion/occlusion_kernel.hpp"
#include "occlusion/occlusion_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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

// What triangle i covers in a vector of rows (y_first..): each row's first covered column and
// one past its last (equal when none), its depth at the start of the bounding box and the bound
// at its extreme covered column (see OccluderTriangle).
struct RowSpans {
    hn::Vec<DI> first, end;
    hn::Vec<DF> row_depth, row_bound;
};

// The values of triangle i read once, before its rows: the stores into the grid may alias the
// batch, so a value read in the loop over vectors of rows is read again in each.
struct TriangleBox {
    int x0, x1, y0, y1;
    float z_dx, z_kx;
};

// The triangle's other values are broadcast here, where they are used once: hoisted out of the
// loop over vectors of rows (most triangles are one), they did not fit the registers and spilled.
HWY_INLINE RowSpans CoveredRows(const OccluderBatch& b, std::size_t i, const TriangleBox& box,
                                int y_first) {
    namespace k = occluder_setup;
    const DF df;
    const DI di;
    const int x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
    const auto field = [&](int f) { return hn::Set(df, b.field[f][i]); };
    const auto half = hn::Set(df, 0.5f);
    const auto left_x0 = field(k::kLeftX), left_step0 = field(k::kLeftStep);
    const auto left_x1 = field(k::kLeftX + 1), left_step1 = field(k::kLeftStep + 1);
    const auto right_x0 = field(k::kRightX), right_step0 = field(k::kRightStep);
    const auto right_x1 = field(k::kRightX + 1), right_step1 = field(k::kRightStep + 1);
    const auto span_lo = hn::Set(df, static_cast<float>(x0));
    const auto span_hi = hn::Set(df, static_cast<float>(x1 + 1));
    const auto origin_x = hn::Set(di, x0);
    const auto z_origin = field(k::kZOrigin), z_dx = hn::Set(df, box.z_dx);
    const auto z_dy = field(k::kZDy), z_kx = hn::Set(df, box.z_kx);
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
    const auto xl = GreaterOf(l0, l1);
    const auto xr = LessOf(r0, r1);
    // First covered column and one past the last, clamped to the bounding box.
    const auto lo = LessOf(span_hi, GreaterOf(span_lo, hn::Add(xl, half)));
    const auto hi = LessOf(span_hi, GreaterOf(span_lo, hn::Sub(xr, half)));
    RowSpans rows;
    rows.first = TruncInRange(lo);  // lo >= 0: truncation is its floor
    rows.end = hn::IfThenElse(row_valid, TruncInRange(hn::Ceil(hi)), rows.first);
    // The bound is taken at the extreme covered column of the whole row and at the tile's
    // extreme column; the plane being affine, the smaller of the two bounds the covered pixels
    // of the row inside the tile.
    rows.row_depth = hn::Add(hn::Add(z_origin, hn::Mul(z_dy, hn::Add(yf, z_ky))), z_bias);
    // A select, not a branch: the sign of z_dx is a coin toss per triangle.
    const auto row_extreme = hn::Sub(
        hn::IfThenElse(z_dx_positive, hn::Sub(rows.end, hn::Set(di, 1)), rows.first), origin_x);
    const auto row_bound =
        hn::Add(rows.row_depth, hn::Mul(z_dx, hn::Add(hn::ConvertTo(df, row_extreme), z_kx)));
    rows.row_bound = LessOf(row_bound, z_max);
    return rows;
}

// Merges columns s..e-1 of a vector of rows of one strip (from element `at` of the grid's
// arrays), at depth bound z, into the two layers (the rules at the top of this file).
HWY_INLINE void MergeIntoRows(const TileGrid& grid, std::size_t at, hn::Vec<DI> s, hn::Vec<DI> e,
                              hn::Vec<DF> z) {
    const DF df;
    const DU du;
    const auto zero_u = hn::Zero(du);
    const auto full_mask = hn::Set(du, kOcclusionFullMask);
    // Columns s..e-1: (~0 << s) & ~(~0 << e).
    const auto coverage = hn::AndNot(ones_shifted_left(e), ones_shifted_left(s));
    const auto mask = hn::LoadU(du, grid.mask + at);
    const auto far_depth = hn::LoadU(df, grid.far_depth + at);
    const auto near_depth = hn::LoadU(df, grid.near_depth + at);
    const auto live = hn::And(hn::RebindMask(df, hn::Ne(coverage, zero_u)), hn::Lt(z, far_depth));
    const auto discard = hn::Gt(hn::Sub(near_depth, z), hn::Sub(far_depth, near_depth));
    auto merged_mask = hn::IfThenZeroElse(hn::RebindMask(du, discard), mask);
    auto merged_near = hn::IfThenZeroElse(discard, near_depth);
    merged_mask = hn::Or(merged_mask, coverage);
    merged_near = GreaterOf(z, merged_near);
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

// The rows a triangle touches are wherever it lies on the screen: at 1920x1080 the strips
// outgrow the L2 cache, and the raster waited on their loads. Their first and last rows in each
// strip are fetched a few triangles ahead (the triangle's rows span at most two lines an array).
constexpr std::size_t kPrefetchAhead = 4;
HWY_INLINE void PrefetchRows(const OccluderBatch& b, std::size_t i, const TileGrid& grid) {
    const int tx0 = b.x0[i] / kOcclusionTileWidth, tx1 = b.x1[i] / kOcclusionTileWidth;
    const int y0 = b.y0[i], y1 = std::max(b.y0[i], b.y1[i]);
    for (int tx = tx0; tx <= tx1; ++tx) {
        const std::size_t first = row_index(grid, tx, y0), last = row_index(grid, tx, y1);
        hwy::Prefetch(grid.mask + first);
        hwy::Prefetch(grid.mask + last);
        hwy::Prefetch(grid.far_depth + first);
        hwy::Prefetch(grid.far_depth + last);
        hwy::Prefetch(grid.near_depth + first);
        hwy::Prefetch(grid.near_depth + last);
    }
}

void RasterizeOccluders(const OccluderBatch& b, std::size_t count, TileGrid grid) {
    namespace k = occluder_setup;
    const DF df;
    const DI di;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const auto zero_i = hn::Zero(di);
    const auto width_i = hn::Set(di, kOcclusionTileWidth);
    for (std::size_t i = 0; i < std::min(count, kPrefetchAhead); ++i) PrefetchRows(b, i, grid);
    for (std::size_t i = 0; i < count; ++i) {
        if (i + kPrefetchAhead < count) PrefetchRows(b, i + kPrefetchAhead, grid);
        const TriangleBox box{
            b.x0[i], b.x1[i], b.y0[i], b.y1[i], b.field[k::kZDx][i], b.field[k::kZKx][i]};
        const int x0 = box.x0, tx0 = box.x0 / kOcclusionTileWidth;
        const int tx1 = box.x1 / kOcclusionTileWidth;
        const float dx = box.z_dx, kx = box.z_kx;
        // Rows y0.. a vector at a time, each vector of rows one load per strip (see TileGrid).
        for (int y_first = box.y0; y_first <= box.y1; y_first += lanes) {
            const RowSpans rows = CoveredRows(b, i, box, y_first);
            // tile_depth_step's column - x0, stepped a tile at a time (exact in float).
            float column = static_cast<float>(tx0 * kOcclusionTileWidth +
                                              (dx > 0.0f ? kOcclusionTileWidth - 1 : 0) - x0);
            for (int tx = tx0; tx <= tx1; ++tx, column += static_cast<float>(kOcclusionTileWidth)) {
                const auto tile_x = hn::Set(di, tx * kOcclusionTileWidth);
                const auto s = hn::Min(hn::Max(hn::Sub(rows.first, tile_x), zero_i), width_i);
                const auto e = hn::Min(hn::Max(hn::Sub(rows.end, tile_x), zero_i), width_i);
                const auto tile_bound = hn::Add(rows.row_depth, hn::Set(df, dx * (column + kx)));
                const auto z = LessOf(rows.row_bound, tile_bound);
                MergeIntoRows(grid, row_index(grid, tx, y_first), s, e, z);
            }
        }
    }
}

const char* OcclusionTargetName() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(RasterizeOccluders);
HWY_EXPORT(OcclusionTargetName);

void rasterize_occluders(const OccluderBatch& triangles, std::size_t count, TileGrid grid) {
    HWY_DYNAMIC_DISPATCH(RasterizeOccluders)(triangles, count, grid);
}

// The instruction set the occlusion kernels run on: the same in every kernel's dispatch (one
// list of targets, one CPU).
const char* occlusion_kernel_target() {
    return HWY_DYNAMIC_DISPATCH(OcclusionTargetName)();
}

namespace {

OccluderTriangle batch_triangle(const OccluderBatch& b, std::size_t i) {
    namespace k = occluder_setup;
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
    return t;
}

// MergeIntoRows for one row.
void merge_into_row(const TileGrid& grid, std::size_t at, std::uint32_t coverage, float z) {
    const std::uint32_t mask = grid.mask[at];
    const float far_depth = grid.far_depth[at], near_depth = grid.near_depth[at];
    if (!(z < far_depth)) return;
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

}  // namespace

// Row by row, the operations of RasterizeOccluders in the same order.
void rasterize_occluders_scalar(const OccluderBatch& b, std::size_t count, TileGrid grid) {
    for (std::size_t i = 0; i < count; ++i) {
        const OccluderTriangle t = batch_triangle(b, i);
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
                const int s =
                    std::min(std::max(first - tx * kOcclusionTileWidth, 0), kOcclusionTileWidth);
                const int e =
                    std::min(std::max(end - tx * kOcclusionTileWidth, 0), kOcclusionTileWidth);
                const std::uint32_t coverage = ~low_bits(s) & low_bits(e);
                if (coverage == 0) continue;
                const float tile_bound = row_depth + tile_depth_step(t.z_dx, t.z_kx, t.x0, tx);
                const float z = row_bound < tile_bound ? row_bound : tile_bound;
                merge_into_row(grid, row_index(grid, tx, y), coverage, z);
            }
        }
    }
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
