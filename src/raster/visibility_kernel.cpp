// See visibility_kernel.hpp. Highway's foreach_target re-includes this file once per
// instruction set; the scalar reference and the dispatcher are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/visibility_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "raster/visibility_kernel.hpp"

// Per target, like this file.
#include "shade/phong_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D, class V>
HWY_INLINE auto depth_passes(D d, V z, V stored, CompareFunc compare) {
    switch (compare) {
        case CompareFunc::Never:
            return hn::FirstN(d, 0);
        case CompareFunc::Less:
            return hn::Lt(z, stored);
        case CompareFunc::LessEqual:
            return hn::Le(z, stored);
        case CompareFunc::Equal:
            return hn::Eq(z, stored);
        case CompareFunc::NotEqual:
            return hn::Ne(z, stored);
        case CompareFunc::GreaterEqual:
            return hn::Ge(z, stored);
        case CompareFunc::Greater:
            return hn::Gt(z, stored);
        case CompareFunc::Always:
            break;
    }
    return hn::Eq(z, z);  // all lanes (z is never NaN)
}

// The job's depth test: kCompare when it is one (a kernel compiled for it, where the test's
// switch folds away), else the job's, switched on in every step.
template <int kCompare>
HWY_INLINE CompareFunc depth_test(const BlockJob& job) {
    return kCompare < 0 ? job.compare : static_cast<CompareFunc>(kCompare);
}

// Edge k at the block's first pixel of row y (inside the block, so it fits 32 bits; the
// product alone need not).
inline std::int32_t edge_at_row(const BlockJob& job, int k, int y) {
    return static_cast<std::int32_t>(std::int64_t{job.e[k]} + std::int64_t{job.step_y[k]} * y);
}

// The corner attributes interpolated at barycentrics (b1, b2), as interpolation_weights and
// interpolate_corners do it, operation for operation. With forward shading the fragments are
// lit and store(color, TileBuffers::color) writes them; otherwise store(value, array) writes
// each attribute.
template <class D, class V, class Store>
HWY_INLINE void interpolate_attributes(D d, const BlockJob& job, V b1, V b2, TileBuffers& tile,
                                       const Store& store) {
    const CornerAttributes& a = *job.corners;
    auto w0 = hn::Sub(hn::Sub(hn::Set(d, 1.0f), b1), b2), w1 = b1, w2 = b2;
    if (const glm::vec3* piece = job.piece; piece != nullptr) {
        const auto remap = [&](int c) {
            return hn::Add(
                hn::Add(hn::Mul(w0, hn::Set(d, piece[0][c])), hn::Mul(w1, hn::Set(d, piece[1][c]))),
                hn::Mul(w2, hn::Set(d, piece[2][c])));
        };
        const auto r0 = remap(0), r1 = remap(1), r2 = remap(2);
        w0 = r0;
        w1 = r1;
        w2 = r2;
    }
    const auto interpolate = [&](const glm::vec3* corner, int c) {
        return hn::Add(
            hn::Add(hn::Mul(hn::Set(d, corner[0][c]), w0), hn::Mul(hn::Set(d, corner[1][c]), w1)),
            hn::Mul(hn::Set(d, corner[2][c]), w2));
    };
    if (job.shade_constants != nullptr) {
        const auto flip =
            (a.tag & kShadeFlip) != 0 ? hn::FirstN(d, hn::Lanes(d)) : hn::FirstN(d, 0);
        const hn::RebindToUnsigned<D> du;
        const auto color =
            pack_rgba(du, shade_lanes(d, *job.shade_constants, interpolate(a.normal, 0),
                                      interpolate(a.normal, 1), interpolate(a.normal, 2),
                                      interpolate(a.world, 0), interpolate(a.world, 1),
                                      interpolate(a.world, 2), flip));
        store(hn::BitCast(d, color), reinterpret_cast<float*>(tile.color));
        return;
    }
    store(interpolate(a.normal, 0), tile.nx);
    store(interpolate(a.normal, 1), tile.ny);
    store(interpolate(a.normal, 2), tile.nz);
    store(interpolate(a.world, 0), tile.wx);
    store(interpolate(a.world, 1), tile.wy);
    store(interpolate(a.world, 2), tile.wz);
}

// Stores the lanes of v (float or uint32 lanes of df's count) where `pass` is true, for the
// arrays the kernel only writes (ref, tag, barycentrics, attributes, color; the deferred pass
// reads them after the tile): AVX-512 has masked stores, so no load is needed. Depth is read
// back by the next triangle and is blended and stored whole instead: a load that overlaps a
// masked store waits for it. Elsewhere masked stores are slow (AVX2 on AMD) or emulated.
template <class DF, class M, class V, class T>
HWY_INLINE void store_where(DF df, M pass, V v, T* to) {
    const hn::Rebind<T, DF> dt;
    const auto vt = hn::BitCast(dt, v);
#if HWY_TARGET <= HWY_AVX3
    hn::BlendedStore(vt, hn::RebindMask(dt, pass), dt, to);
#else
    hn::StoreU(hn::IfThenElse(hn::RebindMask(dt, pass), vt, hn::LoadU(dt, to)), dt, to);
#endif
    (void)df;
}

// One row of up to Lanes(df) pixels per step.
template <int kCompare, class DF>
int VisibilityRows(DF df, const BlockJob& job, TileBuffers& tile) {
    const JobPlanes& t = job.planes;
    // (Flags in locals: see VisibilityRowGroups.)
    const bool attributes = job.attributes, write_depth = job.write_depth;
    const CompareFunc compare = depth_test<kCompare>(job);
    const hn::RebindToSigned<decltype(df)> di;
    const hn::RebindToUnsigned<decltype(df)> du;
    const int lanes = static_cast<int>(hn::Lanes(df));
    const auto zero_i = hn::Zero(di);
    const auto zero_f = hn::Zero(df);
    const auto one_f = hn::Set(df, 1.0f);
    const auto ref = hn::Set(du, job.ref);
    int passed = 0;
    for (int x = 0; x < job.width; x += lanes) {
        const auto valid = hn::FirstN(di, static_cast<std::size_t>(job.width - x));
        const auto iota = hn::Iota(di, x);
        const auto off0 = hn::Mul(iota, hn::Set(di, job.step_x[0]));
        const auto off1 = hn::Mul(iota, hn::Set(di, job.step_x[1]));
        const auto off2 = hn::Mul(iota, hn::Set(di, job.step_x[2]));
        const auto dx = hn::ConvertTo(df, hn::Iota(di, job.plane_dx + x));
        // The planes as PlaneEquation::at computes them, (c + a * dx) + (b * dy): the first
        // sum is the same in every row (read in the loop, the planes were loaded again after
        // each row's stores, which may alias them).
        const auto along = [&](const PlaneEquation& p) {
            return hn::Add(hn::Set(df, p.c), hn::Mul(hn::Set(df, p.a), dx));
        };
        const bool perspective = job.barycentrics && job.perspective;
        const bool linear = job.barycentrics && !job.perspective;
        const auto depth_x = along(t.depth);
        const auto q_x = perspective ? along(t.q) : zero_f;
        const auto b1_x = perspective ? along(t.p1) : linear ? along(t.l1) : zero_f;
        const auto b2_x = perspective ? along(t.p2) : linear ? along(t.l2) : zero_f;
        for (int y = 0; y < job.height; ++y) {
            auto covered = valid;
            if (!job.full) {
                const auto e0 = hn::Add(hn::Set(di, edge_at_row(job, 0, y)), off0);
                const auto e1 = hn::Add(hn::Set(di, edge_at_row(job, 1, y)), off1);
                const auto e2 = hn::Add(hn::Set(di, edge_at_row(job, 2, y)), off2);
                covered = hn::AndNot(hn::Lt(hn::Or(e0, hn::Or(e1, e2)), zero_i), valid);
            }
            const float dy = static_cast<float>(job.plane_dy + y);
            const auto at_row = [&](hn::Vec<DF> row_x, const PlaneEquation& p) {
                return hn::Add(row_x, hn::Set(df, p.b * dy));
            };
            auto z = at_row(depth_x, t.depth);
            z = hn::Add(hn::Min(hn::Max(z, zero_f), one_f), zero_f);
            const std::size_t at =
                static_cast<std::size_t>((job.y0 + y) * kTileStride + job.x0 + x);
            const auto stored = hn::LoadU(df, tile.depth + at);
            const auto pass =
                hn::And(hn::RebindMask(df, covered), depth_passes(df, z, stored, compare));
            // Depth only: no branch (see VisibilityRowGroups).
            if (attributes && hn::AllFalse(df, pass)) continue;
            passed += static_cast<int>(hn::CountTrue(df, pass));
            if (write_depth) hn::StoreU(hn::IfThenElse(pass, z, stored), df, tile.depth + at);
            if (!attributes) continue;
            // Arrays only written here: see store_where.
            const auto store = [&](auto v, auto* to) { store_where(df, pass, v, to + at); };
            store(ref, tile.ref);
            if (!job.barycentrics) continue;
            hn::Vec<decltype(df)> b1, b2;
            if (job.perspective) {
                const auto q = at_row(q_x, t.q);
                b1 = hn::Div(at_row(b1_x, t.p1), q);
                b2 = hn::Div(at_row(b2_x, t.p2), q);
            } else {
                b1 = at_row(b1_x, t.l1);
                b2 = at_row(b2_x, t.l2);
            }
            store(hn::Set(du, job.corners ? job.corners->tag : 0u), tile.shade_tag);
            if (job.corners == nullptr) {
                store(b1, tile.b1);
                store(b2, tile.b2);
                continue;
            }
            interpolate_attributes(df, job, b1, b2, tile, store);
        }
    }
    return passed;
}

// kRows rows of a block at a time in one vector, each row in kRows-th of the lanes: rows of up
// to 8 pixels in pairs or of up to 4 in fours (16 lanes, AVX-512), rows of up to 4 in pairs (8
// lanes, AVX2). Small triangles span few rows, so this cuts the steps; the same operations
// per lane as VisibilityRows.
#if HWY_MAX_BYTES >= 32 && HWY_TARGET != HWY_SCALAR
// The kRows rows of a tile buffer from `at` (row r at at + r * kStride) in one vector, and
// back. The rows past the block (or the tile: TileBuffers has room) go back unchanged.
template <int kRows, class D, class T>
HWY_INLINE hn::Vec<D> LoadRows(D d, const T* from) {
    constexpr std::size_t kNext = kTileStride;
    const hn::Half<D> dh;
    if constexpr (kRows == 2) {
        return hn::Combine(d, hn::LoadU(dh, from + kNext), hn::LoadU(dh, from));
    } else {
        const hn::Half<decltype(dh)> dq;
        return hn::Combine(
            d, hn::Combine(dh, hn::LoadU(dq, from + 3 * kNext), hn::LoadU(dq, from + 2 * kNext)),
            hn::Combine(dh, hn::LoadU(dq, from + kNext), hn::LoadU(dq, from)));
    }
}
// Calls part(row, v) with the lanes of each row of v.
template <int kRows, class D, class Part>
HWY_INLINE void ForEachRow(D d, hn::Vec<D> v, const Part& part) {
    const hn::Half<D> dh;
    const auto low = hn::LowerHalf(dh, v), high = hn::UpperHalf(dh, v);
    if constexpr (kRows == 2) {
        part(0, low);
        part(1, high);
    } else {
        const hn::Half<decltype(dh)> dq;
        part(0, hn::LowerHalf(dq, low));
        part(1, hn::UpperHalf(dq, low));
        part(2, hn::LowerHalf(dq, high));
        part(3, hn::UpperHalf(dq, high));
    }
    (void)d;
}

template <int kRows, int kCompare, class D16>
int VisibilityRowGroups(D16 d, const BlockJob& job, TileBuffers& tile) {
    constexpr int kRowLanes = static_cast<int>(hn::MaxLanes(D16())) / kRows;
    static_assert(kRowLanes == 8 || kRowLanes == 4, "rows of 8 or 4 lanes");
    constexpr int kRowShift = kRowLanes == 8 ? 3 : 2;
    using RowTag = std::conditional_t<kRows == 2, hn::Half<D16>, hn::Half<hn::Half<D16>>>;
    const RowTag dr;
    const JobPlanes& t = job.planes;
    // The flags the loop tests, in locals: the tile stores could alias the job, so read
    // through it they were loaded again in every step. (A copy of the whole job and setup was
    // slower: wide loads of what the caller just wrote in narrow stores stall.)
    const bool attributes = job.attributes, write_depth = job.write_depth;
    const CompareFunc compare = depth_test<kCompare>(job);
    const hn::RebindToSigned<D16> di;
    const hn::RebindToUnsigned<D16> du;
    const auto zero_i = hn::Zero(di);
    const auto zero_f = hn::Zero(d);
    const auto one_f = hn::Set(d, 1.0f);
    const auto lane = hn::Iota(di, 0);
    const auto column = hn::And(lane, hn::Set(di, kRowLanes - 1));
    const auto row_in_group = hn::ShiftRight<kRowShift>(lane);  // 0 .. kRows - 1
    const auto in_width = hn::Lt(column, hn::Set(di, job.width));
    hn::Vec<decltype(di)> off[3];
    for (int k = 0; k < 3; ++k)
        off[k] = hn::Add(hn::Mul(column, hn::Set(di, job.step_x[k])),
                         hn::Mul(row_in_group, hn::Set(di, job.step_y[k])));
    const auto dx = hn::ConvertTo(d, hn::Add(column, hn::Set(di, job.plane_dx)));
    const auto ref = hn::Set(du, job.ref);
    int passed = 0;
    for (int y = 0; y < job.height; y += kRows) {
        auto covered = hn::And(in_width, hn::Lt(row_in_group, hn::Set(di, job.height - y)));
        if (!job.full) {
            // Row y's edge values fit 32 bits (it is inside the block); a running sum would
            // step past the block's last row, where they need not.
            const auto row = [&](int k) { return hn::Set(di, edge_at_row(job, k, y)); };
            const auto e0 = hn::Add(row(0), off[0]);
            const auto e1 = hn::Add(row(1), off[1]);
            const auto e2 = hn::Add(row(2), off[2]);
            covered = hn::AndNot(hn::Lt(hn::Or(e0, hn::Or(e1, e2)), zero_i), covered);
        }
        const auto dy = hn::ConvertTo(d, hn::Add(row_in_group, hn::Set(di, job.plane_dy + y)));
        // PlaneEquation::at with a per-lane dy: (c + a * dx) + (b * dy).
        const auto plane = [&](const PlaneEquation& p) {
            return hn::Add(hn::Add(hn::Set(d, p.c), hn::Mul(hn::Set(d, p.a), dx)),
                           hn::Mul(hn::Set(d, p.b), dy));
        };
        auto z = plane(t.depth);
        z = hn::Add(hn::Min(hn::Max(z, zero_f), one_f), zero_f);
        const std::size_t at = static_cast<std::size_t>((job.y0 + y) * kTileStride + job.x0);
        const auto stored = LoadRows<kRows>(d, tile.depth + at);
        const auto pass = hn::And(hn::RebindMask(d, covered), depth_passes(d, z, stored, compare));
        // Depth only, the rows go through without a branch: whether a group has pixels
        // covered or passing is data the branch predictor cannot guess, and a mispredicted
        // branch costs more than the loads and stores it saves. With
        // attributes, the work a failing group skips is worth that branch, not the coverage one.
        if (attributes && hn::AllFalse(d, pass)) continue;
        passed += static_cast<int>(hn::CountTrue(d, pass));
        if (write_depth)
            ForEachRow<kRows>(d, hn::IfThenElse(pass, z, stored), [&](int r, auto v) {
                hn::StoreU(v, dr, tile.depth + at + std::size_t(r) * kTileStride);
            });
        if (!attributes) continue;
        // Arrays only written here (see store_where), a row at a time.
        hn::Mask<RowTag> row_pass[kRows];
        ForEachRow<kRows>(d, hn::VecFromMask(d, pass),
                          [&](int r, auto v) { row_pass[r] = hn::MaskFromVec(v); });
        const auto store = [&](auto v, auto* to) {
            ForEachRow<kRows>(d, hn::BitCast(d, v), [&](int r, auto row) {
                store_where(dr, row_pass[r], row, to + at + std::size_t(r) * kTileStride);
            });
        };
        store(ref, tile.ref);
        if (!job.barycentrics) continue;
        hn::Vec<D16> b1, b2;
        if (job.perspective) {
            const auto q = plane(t.q);
            b1 = hn::Div(plane(t.p1), q);
            b2 = hn::Div(plane(t.p2), q);
        } else {
            b1 = plane(t.l1);
            b2 = plane(t.l2);
        }
        store(hn::Set(du, job.corners ? job.corners->tag : 0u), tile.shade_tag);
        if (job.corners == nullptr) {
            store(b1, tile.b1);
            store(b2, tile.b2);
            continue;
        }
        interpolate_attributes(d, job, b1, b2, tile, store);
    }
    return passed;
}
#endif

template <int kCompare>
int VisibilityBlockWith(const BlockJob& job, TileBuffers& tile) {
#if HWY_MAX_BYTES >= 64 && HWY_TARGET != HWY_SCALAR
    const hn::CappedTag<float, 16> d16;
    if (hn::Lanes(d16) == 16 && job.width <= 4 && job.height > 2)
        return VisibilityRowGroups<4, kCompare>(d16, job, tile);
    if (hn::Lanes(d16) == 16 && job.width <= 8)
        return VisibilityRowGroups<2, kCompare>(d16, job, tile);
    if (hn::Lanes(d16) == 16) return VisibilityRows<kCompare>(d16, job, tile);
#endif
    const hn::CappedTag<float, 8> d8;
#if HWY_MAX_BYTES >= 32 && HWY_TARGET != HWY_SCALAR
    if (hn::Lanes(d8) == 8 && job.width <= 4)
        return VisibilityRowGroups<2, kCompare>(d8, job, tile);
#endif
    return VisibilityRows<kCompare>(d8, job, tile);
}

// The depth tests of ordinary and reversed depth get kernels of their own; the rest share one.
template <class Run>
HWY_INLINE auto WithCompare(CompareFunc compare, const Run& run) {
    switch (compare) {
        case CompareFunc::Less:
            return run.template operator()<static_cast<int>(CompareFunc::Less)>();
        case CompareFunc::LessEqual:
            return run.template operator()<static_cast<int>(CompareFunc::LessEqual)>();
        case CompareFunc::Greater:
            return run.template operator()<static_cast<int>(CompareFunc::Greater)>();
        case CompareFunc::GreaterEqual:
            return run.template operator()<static_cast<int>(CompareFunc::GreaterEqual)>();
        default:
            return run.template operator()<-1>();
    }
}

int VisibilityBlock(const BlockJob& job, TileBuffers& tile) {
    return WithCompare(job.compare,
                       [&]<int kCompare>() { return VisibilityBlockWith<kCompare>(job, tile); });
}

LaneJobsDone VisibilityLanes(const LaneJobs& jobs, int first, int count, const BlockJob& shared,
                             TileBuffers& tile) {
    return WithCompare(shared.compare, [&]<int kCompare>() {
        return run_lane_jobs(jobs, first, count, shared, [&](const BlockJob& job) {
            return VisibilityBlockWith<kCompare>(job, tile);
        });
    });
}

float BlockFarthestDepth(const TileBuffers& tile, int block_x, int block_y, bool largest) {
    const hn::CappedTag<float, kBlockSize> df;
    const float* row = tile.depth + tile_index(block_x * kBlockSize, block_y * kBlockSize);
    // kBlockSize rows of kBlockSize floats; narrower vectors take each row in several steps.
    auto acc = hn::LoadU(df, row);
    for (int y = 0; y < kBlockSize; ++y)
        for (int x = 0; x < kBlockSize; x += static_cast<int>(hn::Lanes(df))) {
            const auto v = hn::LoadU(df, row + y * kTileStride + x);
            acc = largest ? hn::Max(acc, v) : hn::Min(acc, v);
        }
    return hn::GetLane(largest ? hn::MaxOfLanes(df, acc) : hn::MinOfLanes(df, acc));
}

const char* TargetName() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(VisibilityBlock);
HWY_EXPORT(VisibilityLanes);
HWY_EXPORT(TargetName);
HWY_EXPORT(BlockFarthestDepth);

float block_farthest_depth(const TileBuffers& tile, int block_x, int block_y, bool largest) {
    return HWY_DYNAMIC_DISPATCH(BlockFarthestDepth)(tile, block_x, block_y, largest);
}

float block_farthest_depth_scalar(const TileBuffers& tile, int block_x, int block_y, bool largest) {
    const float* row = tile.depth + tile_index(block_x * kBlockSize, block_y * kBlockSize);
    float farthest = row[0];
    for (int y = 0; y < kBlockSize; ++y)
        for (int x = 0; x < kBlockSize; ++x) {
            const float v = row[y * kTileStride + x];
            farthest = largest ? (v > farthest ? v : farthest) : (v < farthest ? v : farthest);
        }
    return farthest;
}

int visibility_block(const BlockJob& job, TileBuffers& tile) {
    return HWY_DYNAMIC_DISPATCH(VisibilityBlock)(job, tile);
}

LaneJobsDone visibility_lanes(const LaneJobs& jobs, int first, int count, const BlockJob& shared,
                              TileBuffers& tile) {
    return HWY_DYNAMIC_DISPATCH(VisibilityLanes)(jobs, first, count, shared, tile);
}

LaneJobsDone visibility_lanes_scalar(const LaneJobs& jobs, int first, int count,
                                     const BlockJob& shared, TileBuffers& tile) {
    return run_lane_jobs(jobs, first, count, shared,
                         [&](const BlockJob& job) { return visibility_block_scalar(job, tile); });
}

const char* visibility_kernel_target() {
    return HWY_DYNAMIC_DISPATCH(TargetName)();
}

int visibility_block_scalar(const BlockJob& job, TileBuffers& tile) {
    const JobPlanes& t = job.planes;
    int passed = 0;
    for (int y = 0; y < job.height; ++y)
        for (int x = 0; x < job.width; ++x) {
            if (!job.full) {
                bool inside = true;
                for (int k = 0; k < 3; ++k)
                    inside &= std::int64_t{job.e[k]} + std::int64_t{job.step_x[k]} * x +
                                  std::int64_t{job.step_y[k]} * y >=
                              0;
                if (!inside) continue;
            }
            const int dx = job.plane_dx + x, dy = job.plane_dy + y;
            const float z = std::min(std::max(t.depth.at(dx, dy), 0.0f), 1.0f) + 0.0f;
            const std::size_t at =
                static_cast<std::size_t>((job.y0 + y) * kTileStride + job.x0 + x);
            if (!DepthBuffer::passes(z, tile.depth[at], job.compare)) continue;
            ++passed;
            if (job.write_depth) tile.depth[at] = z;
            if (!job.attributes) continue;
            tile.ref[at] = job.ref;
            if (!job.barycentrics) continue;
            float b1, b2;
            if (job.perspective) {
                const float q = t.q.at(dx, dy);
                b1 = t.p1.at(dx, dy) / q;
                b2 = t.p2.at(dx, dy) / q;
            } else {
                b1 = t.l1.at(dx, dy);
                b2 = t.l2.at(dx, dy);
            }
            tile.shade_tag[at] = job.corners ? job.corners->tag : 0u;
            if (job.corners == nullptr) {
                tile.b1[at] = b1;
                tile.b2[at] = b2;
                continue;
            }
            if (job.shade_constants != nullptr) {
                tile.color[at] = shade_interpolated_scalar(*job.shade_constants, *job.corners,
                                                           job.piece, b1, b2);
                continue;
            }
            store_interpolated(*job.corners, job.piece, b1, b2, tile, at);
        }
    return passed;
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
