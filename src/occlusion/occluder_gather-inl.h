// Reading a vector of occluder triangles from the index list, for SetupOccluders
// (occluder_setup_kernel.cpp): their indices (checked against the vertex count), the indices of
// their neighbours in the list and the interior edges found with them, and the clip-space
// corners.
//
// Highway "-inl" header: included once per instruction set by files that use foreach_target.
#if defined(ZRASTER_OCCLUSION_OCCLUDER_GATHER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ZRASTER_OCCLUSION_OCCLUDER_GATHER_INL_H_
#undef ZRASTER_OCCLUSION_OCCLUDER_GATHER_INL_H_
#else
#define ZRASTER_OCCLUSION_OCCLUDER_GATHER_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "occlusion/occluder_setup.hpp"
#include "occlusion/occlusion_kernel.hpp"
#include "occlusion/occlusion_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Fillers of the index arrays of IndexLanes; they never equal each other nor a valid index.
constexpr std::uint32_t kNoTriangle = 0xfffffffeu, kNoNeighbour = 0xffffffffu;

// A vector of triangles as read from the index list.
struct IndexLanes {
    // The corners of each lane's triangle and of its neighbours in the list (kNoTriangle and
    // kNoNeighbour where there is none), for FindInteriorEdges.
    alignas(64) std::uint32_t own[3][kMaxLanes], previous[3][kMaxLanes], next[3][kMaxLanes];
    // The vertex each corner reads: vertex 0 (there is one) in lanes with no valid triangle,
    // whose results are dropped.
    alignas(64) std::uint32_t read[3][kMaxLanes];
    // Bit e of interior[l]: edge e of lane l's triangle is interior (see interior_edges).
    alignas(64) std::int32_t interior[kMaxLanes];
    std::uint32_t valid;  // bit l: lane l holds a triangle whose three indices are valid
};

// Triangles i0.. (a whole vector, with both neighbours in the list): the indices as vectors.
HWY_INLINE void GatherWholeVector(const OccluderSource& src, std::size_t i0, IndexLanes& lanes) {
    const DU du;
    const std::size_t n = hn::Lanes(du);
    const std::uint32_t* t = src.indices + 3 * i0;
    // The first corner of each triangle a setup group ahead: the vertex loads waited on memory
    // (the others are usually on the same or the next line).
    if (i0 + kSetupGroup + n <= src.triangle_count) {
        const std::uint32_t* ahead = t + 3 * kSetupGroup;
        const auto last = static_cast<std::uint32_t>(src.vertex_count - 1);
        for (std::size_t l = 0; l < n; ++l)
            __builtin_prefetch(src.clip + 4 * std::size_t{std::min(ahead[3 * l], last)});
    }
    const auto limit = hn::Set(du, static_cast<std::uint32_t>(src.vertex_count));
    hn::Vec<DU> a, b, c;
    hn::LoadInterleaved3(du, t, a, b, c);
    const auto ok = hn::And(hn::And(hn::Lt(a, limit), hn::Lt(b, limit)), hn::Lt(c, limit));
    const hn::Vec<DU> corner[3] = {a, b, c};
    for (auto* other : {&lanes.previous, &lanes.next}) {
        hn::Vec<DU> d, e, f;
        hn::LoadInterleaved3(du, other == &lanes.previous ? t - 3 : t + 3, d, e, f);
        const auto filler = hn::Set(du, kNoNeighbour);
        hn::Store(hn::IfThenElse(ok, d, filler), du, (*other)[0]);
        hn::Store(hn::IfThenElse(ok, e, filler), du, (*other)[1]);
        hn::Store(hn::IfThenElse(ok, f, filler), du, (*other)[2]);
    }
    for (int v = 0; v < 3; ++v)
        hn::Store(hn::IfThenElse(ok, corner[v], hn::Set(du, kNoTriangle)), du, lanes.own[v]);
    alignas(64) std::uint8_t bits[8] = {};
    hn::StoreMaskBits(du, ok, bits);
    std::memcpy(&lanes.valid, bits, sizeof(lanes.valid));  // lanes <= 16: little endian bytes
    lanes.valid &= n >= 32 ? ~0u : (1u << n) - 1u;
    for (int v = 0; v < 3; ++v) hn::Store(hn::IfThenElseZero(ok, corner[v]), du, lanes.read[v]);
}

// Triangles i0..i0 + m - 1 one at a time (the last vector, or the first or last triangle of
// the list); lanes from m on hold no triangle.
HWY_INLINE void GatherLaneByLane(const OccluderSource& src, std::size_t i0, std::size_t m,
                                 IndexLanes& lanes) {
    lanes.valid = 0;
    for (std::size_t l = 0; l < hn::Lanes(DU()); ++l) {
        for (int v = 0; v < 3; ++v) {
            lanes.own[v][l] = kNoTriangle;
            lanes.previous[v][l] = lanes.next[v][l] = kNoNeighbour;
            lanes.read[v][l] = 0;
        }
        const std::size_t i = i0 + l;
        const std::uint32_t* t = l < m ? src.indices + 3 * i : nullptr;
        if (!t || t[0] >= src.vertex_count || t[1] >= src.vertex_count || t[2] >= src.vertex_count)
            continue;
        lanes.valid |= 1u << l;
        for (int v = 0; v < 3; ++v) {
            lanes.read[v][l] = lanes.own[v][l] = t[v];
            if (i > 0) lanes.previous[v][l] = t[v - 3];
            if (i + 1 < src.triangle_count) lanes.next[v][l] = t[v + 3];
        }
    }
}

// One corner of a vector of triangles, in clip space.
struct ClipCorner {
    hn::Vec<DF> x, y, z, w;
};

// x, y, z, w of vertex index[l] for each lane l, as LoadInterleaved4 of the vertices copied
// side by side gives them.
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
// AVX2 and AVX-512 vectors hold two or four whole vertices: each vertex is read as one 128-bit
// block, the blocks combined and transposed in registers. (Copies through the stack stalled:
// wide loads of narrow stores.)
template <class D>
HWY_INLINE ClipCorner LoadCorner(D df, const float* clip, const std::uint32_t* index) {
    constexpr std::size_t kLanes = hn::MaxLanes(D());
    static_assert(kLanes == 8 || kLanes == 16, "two or four vertices per vector");
    const hn::Full128<float> d4;
    const auto block = [&](std::size_t l) {
        return hn::LoadU(d4, clip + 4 * std::size_t{index[l]});
    };
    hn::Vec<D> v[4];  // v[j]: the vertices of lanes j * kLanes / 4 ..., x y z w each
    for (std::size_t j = 0; j < 4; ++j) {
        if constexpr (kLanes == 16) {
            const hn::Half<D> dh;
            v[j] = hn::Combine(df, hn::Combine(dh, block(4 * j + 3), block(4 * j + 2)),
                               hn::Combine(dh, block(4 * j + 1), block(4 * j)));
        } else {
            v[j] = hn::Combine(df, block(2 * j + 1), block(2 * j));
        }
    }
    // (x z) and (y w) pairs of each half, then the components in lane order.
    const auto xz_lo = hn::ConcatEven(df, v[1], v[0]), yw_lo = hn::ConcatOdd(df, v[1], v[0]);
    const auto xz_hi = hn::ConcatEven(df, v[3], v[2]), yw_hi = hn::ConcatOdd(df, v[3], v[2]);
    return {hn::ConcatEven(df, xz_hi, xz_lo), hn::ConcatEven(df, yw_hi, yw_lo),
            hn::ConcatOdd(df, xz_hi, xz_lo), hn::ConcatOdd(df, yw_hi, yw_lo)};
}
#else
// A vector of at most one vertex: the vertices copied side by side.
template <class D>
HWY_INLINE ClipCorner LoadCorner(D df, const float* clip, const std::uint32_t* index) {
    alignas(64) float copied[4 * kMaxLanes];
    for (std::size_t l = 0; l < hn::Lanes(df); ++l)
        std::memcpy(copied + 4 * l, clip + 4 * std::size_t{index[l]}, 4 * sizeof(float));
    ClipCorner c;
    hn::LoadInterleaved4(df, copied, c.x, c.y, c.z, c.w);
    return c;
}
#endif

// Interior edges: a quick vector search for an edge shared (reversed) with either neighbour;
// only lanes that have one ask interior_edges, which also checks facing.
HWY_INLINE void FindInteriorEdges(const OccluderSource& src, std::size_t i0, std::size_t m,
                                  IndexLanes& lanes) {
    const DI di;
    const DU du;
    hn::Store(hn::Zero(di), di, lanes.interior);
    const hn::Vec<DU> a = hn::Load(du, lanes.own[0]), b = hn::Load(du, lanes.own[1]),
                      c = hn::Load(du, lanes.own[2]);
    auto found = hn::Ne(a, a);
    for (const auto* other : {&lanes.previous, &lanes.next}) {
        const hn::Vec<DU> d = hn::Load(du, (*other)[0]), e = hn::Load(du, (*other)[1]),
                          f = hn::Load(du, (*other)[2]);
        const auto reversed = [&](hn::Vec<DU> x, hn::Vec<DU> y) {
            return hn::Or(
                hn::Or(hn::And(hn::Eq(x, e), hn::Eq(y, d)), hn::And(hn::Eq(x, f), hn::Eq(y, e))),
                hn::And(hn::Eq(x, d), hn::Eq(y, f)));
        };
        found = hn::Or(found, hn::Or(hn::Or(reversed(a, b), reversed(b, c)), reversed(c, a)));
    }
    if (hn::AllFalse(du, found)) return;
    alignas(64) std::uint32_t shares[kMaxLanes];
    hn::Store(hn::IfThenElseZero(found, hn::Set(du, 1u)), du, shares);
    for (std::size_t l = 0; l < m; ++l)
        if (shares[l] != 0)
            lanes.interior[l] = static_cast<std::int32_t>(interior_edges(src, i0 + l));
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard
