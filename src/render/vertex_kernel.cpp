// See vertex_kernel.hpp. Highway's foreach_target re-includes this file once per instruction
// set; the scalar reference and the dispatcher are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/vertex_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "render/frame.hpp"
#include "render/vertex_kernel.hpp"

namespace zraster::detail {
// The SIMD version stores a ScreenVertex as three 64-bit words: (x, y), (z, 1/w), (window x, y).
static_assert(sizeof(ScreenVertex) == 24 && offsetof(ScreenVertex, x) == 0 &&
              offsetof(ScreenVertex, y) == 4 && offsetof(ScreenVertex, z) == 8 &&
              offsetof(ScreenVertex, inv_w) == 12 && offsetof(ScreenVertex, window_x) == 16 &&
              offsetof(ScreenVertex, window_y) == 20);
}  // namespace zraster::detail

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void TransformVertices(const VertexJob& job) {
    // Lanes of doubles for the snap; floats and 32-bit integers of the same lane count.
    const hn::CappedTag<double, 8> dd;
    const hn::Rebind<float, decltype(dd)> df;
    const hn::Rebind<std::int32_t, decltype(dd)> di;
    const std::size_t lanes = hn::Lanes(dd);
    const glm::mat4& m = job.mvp;
    const bool zero_to_one_clip = job.clip.depth_range == ClipDepthRange::ZeroToOne;
    const auto bit = [&](std::uint32_t b) { return hn::Set(di, static_cast<std::int32_t>(b)); };
    const auto zero_i = hn::Zero(di);
    const double width = job.setup.viewport.width, height = job.setup.viewport.height;
    const auto one_d = hn::Set(dd, 1.0), half_d = hn::Set(dd, 0.5);
    const auto limit = hn::Set(dd, kGuardBand + double(kMaxViewport));
    const auto scale = hn::Set(dd, double(kSubpixelScale));
    const bool zero_to_one_window = job.setup.depth_range != ClipDepthRange::NegativeOneToOne;
    const hn::Rebind<std::uint32_t, decltype(dd)> du;
    const hn::Rebind<std::uint64_t, decltype(dd)> dw;
    // (r0 x + r1 y) + (r2 z + r3) for a matrix row r broadcast to vectors: clip_position()'s
    // operations, and world_attributes()'s for the world position.
    const auto affine = [](const auto& r, const auto& x, const auto& y, const auto& z) {
        return hn::Add(hn::Add(hn::Mul(r[0], x), hn::Mul(r[1], y)),
                       hn::Add(hn::Mul(r[2], z), r[3]));
    };
    // The model and normal matrices' rows, broadcast to vectors of tag d.
    const auto attribute_rows = [&](auto d) {
        const glm::mat4& w = job.model;
        const glm::mat3& n = job.normal_matrix;
        const auto world_row = [&](int r) {
            return std::array{hn::Set(d, w[0][r]), hn::Set(d, w[1][r]), hn::Set(d, w[2][r]),
                              hn::Set(d, w[3][r])};
        };
        const auto normal_row = [&](int r) {
            return std::array{hn::Set(d, n[0][r]), hn::Set(d, n[1][r]), hn::Set(d, n[2][r])};
        };
        return std::pair{std::array{world_row(0), world_row(1), world_row(2)},
                         std::array{normal_row(0), normal_row(1), normal_row(2)}};
    };
    // World positions and unit world normals of the vertices at k (positions x, y, z: vectors
    // of tag d; rows: attribute_rows(d)).
    const auto attributes = [&](auto d, const auto& rows, std::size_t k, const auto& x,
                                const auto& y, const auto& z) {
        // (Not a structured binding: Clang before 16 does not let lambdas capture those.)
        const auto& wr = rows.first;
        const auto& nr = rows.second;
        hn::StoreInterleaved3(affine(wr[0], x, y, z), affine(wr[1], x, y, z),
                              affine(wr[2], x, y, z), d, &job.world_out[k].x);
        if (job.normal_out == nullptr) return;
        const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
        auto nx = zero, ny = one, nz = zero;
        if (job.normals != nullptr) hn::LoadInterleaved3(d, &job.normals[k].x, nx, ny, nz);
        // (n0 x + n1 y) + n2 z per row, then n / |n| or (0, 1, 0), as world_attributes.
        const auto rotate = [&](int r) {
            return hn::Add(hn::Add(hn::Mul(nr[r][0], nx), hn::Mul(nr[r][1], ny)),
                           hn::Mul(nr[r][2], nz));
        };
        const auto tx = rotate(0), ty = rotate(1), tz = rotate(2);
        const auto len =
            hn::Sqrt(hn::Add(hn::Add(hn::Mul(tx, tx), hn::Mul(ty, ty)), hn::Mul(tz, tz)));
        const auto has_length = hn::Gt(len, zero);
        hn::StoreInterleaved3(hn::IfThenElse(has_length, hn::Div(tx, len), zero),
                              hn::IfThenElse(has_length, hn::Div(ty, len), one),
                              hn::IfThenElse(has_length, hn::Div(tz, len), zero), d,
                              &job.normal_out[k].x);
    };
    const auto rows_f = attribute_rows(df);
    // The mvp's rows, broadcast to vectors of tag d.
    const auto clip_rows = [&](auto d) {
        const auto row = [&](int r) {
            return std::array{hn::Set(d, m[0][r]), hn::Set(d, m[1][r]), hn::Set(d, m[2][r]),
                              hn::Set(d, m[3][r])};
        };
        return std::array{row(0), row(1), row(2), row(3)};
    };
    // Clip positions (cx, cy, cz, cw) of positions x, y, z (vectors of tag d), as
    // clip_position(); their frustum_outcode() (the same expressions) and whether all four
    // are finite (~0 or 0), in 32-bit lanes.
    const auto clip = [&](auto d, const auto& rows, const auto& x, const auto& y, const auto& z) {
        const hn::RebindToSigned<decltype(d)> ds;
        const auto cx = affine(rows[0], x, y, z), cy = affine(rows[1], x, y, z),
                   cz = affine(rows[2], x, y, z), cw = affine(rows[3], x, y, z);
        const auto finite = hn::VecFromMask(
            ds, hn::RebindMask(ds, hn::And(hn::And(hn::IsFinite(cx), hn::IsFinite(cy)),
                                           hn::And(hn::IsFinite(cz), hn::IsFinite(cw)))));
        const auto zero = hn::Zero(d);
        const auto depth_min = zero_to_one_clip ? cz : hn::Add(cz, cw);
        const auto gx = hn::Mul(hn::Set(d, job.clip.guard_x), cw);
        const auto gy = hn::Mul(hn::Set(d, job.clip.guard_y), cw);
        const auto outside = [&](auto distance, std::uint32_t b) {
            return hn::IfThenZeroElse(hn::RebindMask(ds, hn::Ge(distance, zero)),
                                      hn::Set(ds, static_cast<std::int32_t>(b)));
        };
        const auto code = hn::Or(
            hn::Or(outside(depth_min, kClipDepthMin), outside(hn::Sub(cw, cz), kClipDepthMax)),
            hn::Or(
                hn::Or(outside(hn::Add(cx, gx), kClipLeft), outside(hn::Sub(gx, cx), kClipRight)),
                hn::Or(outside(hn::Add(cy, gy), kClipBottom), outside(hn::Sub(gy, cy), kClipTop))));
        return std::array{cx, cy, cz, cw, hn::BitCast(d, code), hn::BitCast(d, finite)};
    };
    // The outcodes and screen vertices of the vertices at k from clip (float lanes of df).
    const auto snap = [&](std::size_t k, const std::array<hn::Vec<decltype(df)>, 6>& c) {
        const auto& [cx, cy, cz, cw, code_f, finite_f] = c;
        auto code = hn::BitCast(di, code_f);
        const auto finite = hn::Ne(hn::BitCast(di, finite_f), zero_i);
        // to_screen() in double lanes.
        const auto w = hn::PromoteTo(dd, cw);
        const auto rw = hn::Div(one_d, w);
        const auto wx = hn::Mul(hn::Mul(hn::Add(hn::Mul(hn::PromoteTo(dd, cx), rw), one_d), half_d),
                                hn::Set(dd, width));
        const auto wy = hn::Mul(hn::Mul(hn::Sub(one_d, hn::Mul(hn::PromoteTo(dd, cy), rw)), half_d),
                                hn::Set(dd, height));
        const auto neg_limit = hn::Neg(limit);
        const auto representable = hn::And(
            hn::And(hn::Gt(w, hn::Zero(dd)), hn::And(hn::Ge(wx, neg_limit), hn::Le(wx, limit))),
            hn::And(hn::Ge(wy, neg_limit), hn::Le(wy, limit)));
        const auto inside = hn::Eq(code, zero_i);
        // Inside but not representable: the clipper takes it (kClipLeft).
        // (A mask of double lanes does not convert to 32-bit lanes: go through 0/1 values.)
        const auto representable_i =
            hn::Eq(hn::DemoteTo(di, hn::IfThenElseZero(representable, one_d)), hn::Set(di, 1));
        const auto unrepresentable = hn::AndNot(representable_i, inside);
        code = hn::IfThenElse(unrepresentable, bit(kClipLeft), code);
        code = hn::IfThenElse(finite, code, hn::Set(di, static_cast<std::int32_t>(kNonFinite)));
        hn::StoreU(hn::BitCast(du, code), du, job.outcode_out + k);
        // Screen vertices go out as three 64-bit words each, (x, y), (z, 1/w), (window x, y),
        // every lane written: lanes outside get x = kOutsideScreenX (the rest is unspecified).
        auto* screen_words = reinterpret_cast<std::uint64_t*>(job.screen_out + k);
        const auto now_inside = hn::Eq(code, zero_i);
        if (hn::AllFalse(di, now_inside)) {
            const auto none = hn::Zero(dw);
            hn::StoreInterleaved3(hn::Set(dw, std::uint32_t(kOutsideScreenX)), none, none, dw,
                                  screen_words);
            return;
        }
        // Values outside the representable range are not converted (their lanes are unused).
        const auto safe_x = hn::IfThenElseZero(representable, wx);
        const auto safe_y = hn::IfThenElseZero(representable, wy);
        const auto sx =
            hn::IfThenElse(now_inside, hn::DemoteTo(di, hn::Round(hn::Mul(safe_x, scale))),
                           hn::Set(di, kOutsideScreenX));
        const auto sy = hn::DemoteTo(di, hn::Round(hn::Mul(safe_y, scale)));
        const auto zd = hn::Mul(hn::PromoteTo(dd, cz), rw);
        const auto window_z = zero_to_one_window ? zd : hn::Add(hn::Mul(half_d, zd), half_d);
        // Two 32-bit values as one 64-bit word, the first in the low half (memory order).
        const auto word = [&](auto first, auto second) {
            return hn::Or(hn::PromoteTo(dw, hn::BitCast(du, first)),
                          hn::ShiftLeft<32>(hn::PromoteTo(dw, hn::BitCast(du, second))));
        };
        hn::StoreInterleaved3(word(sx, sy), word(hn::DemoteTo(df, window_z), hn::DemoteTo(df, rw)),
                              word(hn::DemoteTo(df, wx), hn::DemoteTo(df, wy)), dw, screen_words);
    };
    const auto rows_m = clip_rows(df);
    // One step: the vertices at k (float lanes of df) and their attributes.
    const auto step = [&](std::size_t k) {
        hn::Vec<decltype(df)> x, y, z;
        hn::LoadInterleaved3(df, &job.positions[k].x, x, y, z);
        const auto c = clip(df, rows_m, x, y, z);
        if (job.world_out != nullptr) attributes(df, rows_f, k, x, y, z);
        snap(k, c);
    };
    std::size_t k = 0;
    // Where the double lanes hold half the vertices of 8 float lanes (AVX2: 4), 8 vertices a
    // step: the clip positions, outcodes and attributes in the float lanes, the snap in two
    // halves, so the float lanes are never half empty. Elsewhere the attributes go with the
    // step: between its operations, they overlap them (docs/architecture.md).
#if HWY_TARGET == HWY_AVX2 || HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3
    {
        const hn::CappedTag<float, 8> da;
        static_assert(hn::MaxLanes(da) == 2 * hn::MaxLanes(df));
        const auto rows_a = attribute_rows(da);
        const auto rows_ma = clip_rows(da);
        const std::size_t wide = hn::Lanes(da);
        for (; k + wide <= job.count; k += wide) {
            hn::Vec<decltype(da)> x, y, z;
            hn::LoadInterleaved3(da, &job.positions[k].x, x, y, z);
            const auto c = clip(da, rows_ma, x, y, z);
            if (job.world_out != nullptr) attributes(da, rows_a, k, x, y, z);
            std::array<hn::Vec<decltype(df)>, 6> low, high;
            for (std::size_t i = 0; i < 6; ++i) {
                low[i] = hn::LowerHalf(df, c[i]);
                high[i] = hn::UpperHalf(df, c[i]);
            }
            snap(k, low);
            snap(k + lanes, high);
        }
    }
#endif
    for (; k + lanes <= job.count; k += lanes) step(k);
    if (k < job.count) {
        VertexJob tail = job;
        tail.positions += k;
        tail.count -= k;
        tail.screen_out += k;
        tail.outcode_out += k;
        if (tail.normals != nullptr) tail.normals += k;
        if (tail.world_out != nullptr) tail.world_out += k;
        if (tail.normal_out != nullptr) tail.normal_out += k;
        transform_vertices_scalar(tail);
    }
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {
namespace {

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

HWY_EXPORT(TransformVertices);

void transform_vertices(const VertexJob& job) {
    HWY_DYNAMIC_DISPATCH(TransformVertices)(job);
}

void transform_vertices_scalar(const VertexJob& job) {
    for (std::size_t k = 0; k < job.count; ++k) {
        const glm::vec4 clip = clip_position(job.mvp, job.positions[k]);
        std::uint32_t code = kNonFinite;
        if (finite(clip)) {
            code = frustum_outcode(clip, job.clip);
            if (code == 0 && !to_screen(clip, job.setup, job.screen_out[k]))
                code = kClipLeft;  // not representable: let the clipper handle it
        }
        job.outcode_out[k] = code;
        if (code != 0) job.screen_out[k].x = kOutsideScreenX;
        if (job.world_out == nullptr) continue;
        glm::vec3 normal;
        world_attributes(job.model, job.normal_matrix, job.positions[k],
                         job.normals ? job.normals[k] : glm::vec3(0, 1, 0), job.world_out[k],
                         normal);
        if (job.normal_out != nullptr) job.normal_out[k] = normal;
    }
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
