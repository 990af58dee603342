// See classify_kernel.hpp. Highway's foreach_target re-includes this file once per instruction
// set; the scalar reference and the dispatcher are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/classify_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <bit>
#include <cstddef>

#include "render/classify_kernel.hpp"
#include "simd/compress_lanes-inl.h"

namespace zraster::detail {
// ScreenVertex is gathered as 64-bit words: (x, y) is word 0 of 3, x in its low half.
static_assert(sizeof(ScreenVertex) == 24 && offsetof(ScreenVertex, x) == 0 &&
              offsetof(ScreenVertex, y) == 4 && std::endian::native == std::endian::little);
}  // namespace zraster::detail

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// How far ahead the classifier prefetches screen vertices, in triangles.
constexpr std::size_t kPrefetchAhead = 64;

void ClassifyTriangles(const ClassifyInput& in, std::size_t first, std::size_t count,
                       ClassifyOutput& out) {
    // Lanes of doubles (the area must be exact), and 32-bit lanes of the same count.
    const hn::CappedTag<double, 8> dd;
    const hn::Rebind<std::int32_t, decltype(dd)> di;
    const hn::Rebind<std::uint32_t, decltype(dd)> du;
    const std::size_t lanes = hn::Lanes(dd);
    const hn::Rebind<std::uint64_t, decltype(dd)> d64;
    const hn::Rebind<std::int64_t, decltype(dd)> di64;
    const auto* pairs = reinterpret_cast<const std::uint64_t*>(in.screen);
    const SetupSettings& s = in.settings;
    const bool ccw = s.front_face == FrontFace::CounterClockwise;
    const auto limit = hn::Set(di, kClassifyCoordinateLimit);
    const auto neg_limit = hn::Set(di, -kClassifyCoordinateLimit);
    const auto half = hn::Set(di, std::int32_t{kSubpixelScale / 2});
    const auto zero_i = hn::Zero(di);
    const auto last_x = hn::Set(di, s.viewport.width - 1);
    const auto last_y = hn::Set(di, s.viewport.height - 1);
    const auto total = hn::Set(du, in.vertex_total);
    const auto base = hn::Set(du, in.first_vertex);
    out.count = 0;
    // The gathers wait on memory when the frame's screen vertices do not fit in the caches (a
    // soup of a million triangles): each vector of triangles prefetches the first vertex of each
    // triangle kPrefetchAhead triangles further on. Only the first: a triangle's other vertices
    // are either cached already (dense meshes) or next to it (soups).
    const std::size_t prefetch_end =
        in.triangle_total >= kPrefetchAhead ? in.triangle_total - kPrefetchAhead : 0;
    const std::uint32_t last_vertex = in.vertex_total == 0 ? 0 : in.vertex_total - 1;
    const ScreenVertex* mesh_screen = in.screen + in.first_vertex;
    std::size_t t = 0;
    for (; t + lanes <= count; t += lanes) {
        const std::size_t tri = first + t;
        if (tri + lanes <= prefetch_end) {
            const std::uint32_t* ahead =
                in.indices + 3 * (tri + kPrefetchAhead - in.first_triangle);
            for (std::size_t i = 0; i < lanes; ++i)
                __builtin_prefetch(mesh_screen + std::min(ahead[3 * i], last_vertex));
        }
        hn::Vec<decltype(du)> i0, i1, i2;
        hn::LoadInterleaved3(du, in.indices + 3 * (tri - in.first_triangle), i0, i1, i2);
        const auto in_range =
            hn::And(hn::And(hn::Lt(i0, total), hn::Lt(i1, total)), hn::Lt(i2, total));
        // Lanes with a bad index gather vertex 0 instead (and go the slow way).
        const auto zero_u = hn::Zero(du);
        const auto g0 = hn::BitCast(di, hn::Add(base, hn::IfThenElse(in_range, i0, zero_u)));
        const auto g1 = hn::BitCast(di, hn::Add(base, hn::IfThenElse(in_range, i1, zero_u)));
        const auto g2 = hn::BitCast(di, hn::Add(base, hn::IfThenElse(in_range, i2, zero_u)));
        // Each vertex's (x, y) in one 64-bit gather (3 per ScreenVertex; x in the low half):
        // gathers cost per element, so half the elements of gathering x and y apart.
        const auto pair = [&](hn::Vec<decltype(di)> g) {
            const auto g64 = hn::PromoteTo(di64, g);
            return hn::GatherIndex(d64, pairs, hn::Add(hn::ShiftLeft<1>(g64), g64));
        };
        const auto low = [&](hn::Vec<decltype(d64)> p) {
            return hn::BitCast(di, hn::TruncateTo(du, p));
        };
        const auto high = [&](hn::Vec<decltype(d64)> p) {
            return hn::BitCast(di, hn::TruncateTo(du, hn::ShiftRight<32>(p)));
        };
        const auto p0 = pair(g0), p1 = pair(g1), p2 = pair(g2);
        const auto x0 = low(p0), y0 = high(p0);
        const auto x1 = low(p1), y1 = high(p1);
        const auto x2 = low(p2), y2 = high(p2);
        const auto one = hn::Set(di, 1);
        const auto lo_x = hn::Min(hn::Min(x0, x1), x2), hi_x = hn::Max(hn::Max(x0, x1), x2);
        const auto lo_y = hn::Min(hn::Min(y0, y1), y2), hi_y = hn::Max(hn::Max(y0, y1), y2);
        const auto small = hn::And(hn::And(hn::Gt(lo_x, neg_limit), hn::Lt(hi_x, limit)),
                                   hn::And(hn::Gt(lo_y, neg_limit), hn::Lt(hi_y, limit)));
        // (Vertices outside the view volume have x = kOutsideScreenX: not small.)
        const auto fast_i = hn::And(hn::RebindMask(di, in_range), small);
        // Twice the signed area, exact in double for these coordinates.
        const auto dx1 = hn::PromoteTo(dd, hn::Sub(x1, x0)),
                   dy1 = hn::PromoteTo(dd, hn::Sub(y1, y0));
        const auto dx2 = hn::PromoteTo(dd, hn::Sub(x2, x0)),
                   dy2 = hn::PromoteTo(dd, hn::Sub(y2, y0));
        const auto area = hn::Sub(hn::Mul(dx1, dy2), hn::Mul(dx2, dy1));
        // Its sign as -1, 0, 1 in 32-bit lanes (masks of 64-bit lanes do not convert to 32-bit
        // ones): the rest of the decisions work on those.
        const auto sign =
            hn::DemoteTo(di, hn::Min(hn::Max(area, hn::Set(dd, -1.0)), hn::Set(dd, 1.0)));
        const auto fast = fast_i;
        const auto degenerate = hn::And(fast, hn::Eq(sign, zero_i));
        const auto front = ccw ? hn::Lt(sign, zero_i) : hn::Gt(sign, zero_i);
        auto culled = hn::AndNot(degenerate, fast);
        if (s.cull == CullMode::Back)
            culled = hn::AndNot(front, culled);
        else if (s.cull == CullMode::Front)
            culled = hn::And(front, culled);
        else
            culled = hn::AndNot(fast, fast);
        // Pixel box of covered centers (ceil and floor by arithmetic shifts).
        const auto px0 =
            hn::Max(zero_i, hn::Neg(hn::ShiftRight<kSubpixelBits>(hn::Sub(half, lo_x))));
        const auto py0 =
            hn::Max(zero_i, hn::Neg(hn::ShiftRight<kSubpixelBits>(hn::Sub(half, lo_y))));
        const auto px1 = hn::Min(last_x, hn::ShiftRight<kSubpixelBits>(hn::Sub(hi_x, half)));
        const auto py1 = hn::Min(last_y, hn::ShiftRight<kSubpixelBits>(hn::Sub(hi_y, half)));
        const auto empty_i = hn::Or(hn::Gt(px0, px1), hn::Gt(py0, py1));
        const auto decided = hn::Or(degenerate, culled);  // before the box, as classify_triangle
        const auto no_cover = hn::AndNot(decided, hn::And(fast, empty_i));
        out.degenerate += hn::CountTrue(di, degenerate);
        out.culled += hn::CountTrue(di, culled);
        out.no_coverage += hn::CountTrue(di, no_cover);
        // Kept: slow lanes, and fast lanes none of the three rejected.
        const auto keep = hn::Not(hn::Or(decided, no_cover));
        if (hn::AllFalse(di, keep)) continue;
        const auto slow = hn::Not(fast_i);
        const auto front_fast = hn::And(front, fast_i);
        const auto flags = hn::Or(hn::IfThenElseZero(front_fast, one),
                                  hn::IfThenElseZero(slow, hn::Set(di, ClassifyOutput::kSlow)));
        const auto tri_index = hn::Iota(di, static_cast<std::int32_t>(tri));
        const std::size_t n = out.count;
        // Compressed in registers and stored whole (the arrays have room past the last entry):
        // Highway's CompressStore is AVX-512's compress-to-memory instruction, slower than a
        // compress and a store on AMD processors.
        const auto append = [&](auto v, auto* to) {
            hn::StoreU(CompressLanes(di, v, keep), di, to + n);
        };
        append(tri_index, reinterpret_cast<std::int32_t*>(out.triangle));
        append(hn::IfThenElseZero(fast_i, px0), out.min_x);
        append(hn::IfThenElseZero(fast_i, py0), out.min_y);
        append(hn::IfThenElseZero(fast_i, px1), out.max_x);
        append(hn::IfThenElseZero(fast_i, py1), out.max_y);
        append(flags, out.flags);
        out.count += static_cast<std::uint32_t>(hn::CountTrue(di, keep));
    }
    // The tail (fewer than a vector of triangles): the scalar reference, appended.
    if (t < count) {
        ClassifyOutput tail;
        classify_triangles_scalar(in, first + t, count - t, tail);
        for (std::uint32_t k = 0; k < tail.count; ++k, ++out.count) {
            out.triangle[out.count] = tail.triangle[k];
            out.min_x[out.count] = tail.min_x[k];
            out.min_y[out.count] = tail.min_y[k];
            out.max_x[out.count] = tail.max_x[k];
            out.max_y[out.count] = tail.max_y[k];
            out.flags[out.count] = tail.flags[k];
        }
        out.degenerate += tail.degenerate;
        out.culled += tail.culled;
        out.no_coverage += tail.no_coverage;
    }
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(ClassifyTriangles);

void classify_triangles(const ClassifyInput& in, std::size_t first, std::size_t count,
                        ClassifyOutput& out) {
    HWY_DYNAMIC_DISPATCH(ClassifyTriangles)(in, first, count, out);
}

void classify_triangles_scalar(const ClassifyInput& in, std::size_t first, std::size_t count,
                               ClassifyOutput& out) {
    out.count = 0;
    for (std::size_t t = first; t < first + count; ++t) {
        const std::uint32_t* corner = in.indices + 3 * (t - in.first_triangle);
        const std::uint32_t i0 = corner[0], i1 = corner[1], i2 = corner[2];
        bool fast = i0 < in.vertex_total && i1 < in.vertex_total && i2 < in.vertex_total;
        TriangleBounds bounds{0, 0, 0, 0, false};
        if (fast) {
            const std::uint32_t g0 = in.first_vertex + i0, g1 = in.first_vertex + i1,
                                g2 = in.first_vertex + i2;
            const ScreenVertex &a = in.screen[g0], &b = in.screen[g1], &c = in.screen[g2];
            // (Vertices outside the view volume have x = kOutsideScreenX: not small.)
            for (const ScreenVertex* v : {&a, &b, &c})
                fast &= v->x > -kClassifyCoordinateLimit && v->x < kClassifyCoordinateLimit &&
                        v->y > -kClassifyCoordinateLimit && v->y < kClassifyCoordinateLimit;
            if (fast) {
                switch (classify_triangle(a, b, c, in.settings, bounds)) {
                    case SetupResult::Degenerate:
                        ++out.degenerate;
                        continue;
                    case SetupResult::Culled:
                        ++out.culled;
                        continue;
                    case SetupResult::NoCoverage:
                        ++out.no_coverage;
                        continue;
                    case SetupResult::Visible:
                        break;
                }
            }
        }
        const std::uint32_t k = out.count++;
        out.triangle[k] = static_cast<std::uint32_t>(t);
        out.min_x[k] = fast ? bounds.min_x : 0;
        out.min_y[k] = fast ? bounds.min_y : 0;
        out.max_x[k] = fast ? bounds.max_x : 0;
        out.max_y[k] = fast ? bounds.max_y : 0;
        out.flags[k] =
            fast ? (bounds.front_facing ? ClassifyOutput::kFront : 0) : ClassifyOutput::kSlow;
    }
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
