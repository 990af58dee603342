// The SIMD Phong lighting of vectors of pixels, shared by the deferred row shader
// (render/shade_kernel.cpp), the batch shader (phong_kernel.cpp) and the visibility kernel's
// forward shading (visibility_kernel.cpp). It reproduces the scalar path (unit normal, two-sided
// flip, evaluate_lighting, combine, 8-bit rounding) operation for operation.
//
// Highway "-inl" header: included once per instruction set by files that use foreach_target.
#if defined(ZRASTER_SHADE_PHONG_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ZRASTER_SHADE_PHONG_LANES_INL_H_
#undef ZRASTER_SHADE_PHONG_LANES_INL_H_
#else
#define ZRASTER_SHADE_PHONG_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include "shade/phong_kernel.hpp"
#include "simd/lane_pairs-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Vectors shaded together (see Pair): four lit the fastest on AVX2 and AVX-512 (eight spill).
constexpr int kShadeGroup = 4;

// The lighting works on one vector of pixels (X = hn::Vec<D>) or on a Pair of them (see
// lane_pairs-inl.h): one vector's lighting is a long dependency chain (square root, division,
// square root, division, the specular power), and the FP scheduler holds too few operations to
// overlap it with the next vector's by itself: one, two or four lanes wide (SSE4, AVX2,
// AVX-512), a vector took the same ~50 ns. Four at a time shade AVX2 2x faster (eight spill
// registers and are slower).

template <class D, class X>
HWY_INLINE X positive_part(D d, const X& x) {
    return select(greater(x, hn::Zero(d)), x, hn::Zero(d));
}

// x^n by squaring, the multiplications of specular_power (lighting.cpp) minus its exact ones:
// the first factor is taken as it is instead of multiplied by 1, and no square is formed after
// the highest bit.
template <class D, class X>
HWY_INLINE X power(D d, const X& x, int n) {
    if (n == 0) return broadcast(d, 1.0f, x);
    X result{}, base = x;
    bool have_result = false;
    for (int e = n;;) {
        if (e & 1) {
            result = have_result ? mul(result, base) : base;
            have_result = true;
        }
        e >>= 1;
        if (e == 0) return result;
        base = mul(base, base);
    }
}

template <class D, class X>
HWY_INLINE auto to_unorm8(D d, X v) {
    v = select(greater(v, hn::Zero(d)), v, hn::Zero(d));
    v = select(less(v, hn::Set(d, 1.0f)), v, hn::Set(d, 1.0f));
    const auto scaled = add(mul(v, hn::Set(d, 255.0f)), hn::Set(d, 0.5f));
    return lanewise([](const auto& a) { return hn::ConvertTo(hn::RebindToSigned<D>(), a); },
                    scaled);
}

// 8-bit channels (0..255) of a vector of pixels (or of a Pair of vectors).
template <class VI>
struct RgbLanes {
    VI r, g, b;
};

// One vector of pixels (X = hn::Vec<D>), or two (X = Pair): the normal (not yet unit), the
// world position, and the lanes whose normal is negated.
template <class D, class X, class M>
HWY_INLINE auto shade_lanes(D d, const PhongConstants& k, X nx, X ny, X nz, const X& px,
                            const X& py, const X& pz, const M& flip) {
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    // Unit normal, or (0, 1, 0); negated for back faces.
    const X len = sqrt(dot3(nx, ny, nz, nx, ny, nz));
    const auto has_length = greater(len, zero);
    nx = select(has_length, div(nx, len), zero);
    ny = select(has_length, div(ny, len), one);
    nz = select(has_length, div(nz, len), zero);
    nx = select(flip, neg(nx), nx);
    ny = select(flip, neg(ny), ny);
    nz = select(flip, neg(nz), nz);

    X vx, vy, vz;
    if (k.local_viewer) {
        vx = sub(hn::Set(d, k.eye.x), px);
        vy = sub(hn::Set(d, k.eye.y), py);
        vz = sub(hn::Set(d, k.eye.z), pz);
        const X inv = div(one, sqrt(dot3(vx, vy, vz, vx, vy, vz)));
        vx = mul(vx, inv);
        vy = mul(vy, inv);
        vz = mul(vz, inv);
    } else {
        vx = broadcast(d, k.view_axis.x, px);
        vy = broadcast(d, k.view_axis.y, px);
        vz = broadcast(d, k.view_axis.z, px);
    }

    X dr = broadcast(d, 0.0f, px), dg = dr, db = dr, sr = dr, sg = dr, sb = dr;
    for (int l = 0; l < k.light_count; ++l) {
        const glm::vec3 L = k.light_direction[l], c = k.light_color[l];
        const auto lx = hn::Set(d, L.x), ly = hn::Set(d, L.y), lz = hn::Set(d, L.z);
        const X n_dot_l = dot3(nx, ny, nz, lx, ly, lz);
        const X lambert = positive_part(d, n_dot_l);
        dr = add(dr, mul(hn::Set(d, c.x), lambert));
        dg = add(dg, mul(hn::Set(d, c.y), lambert));
        db = add(db, mul(hn::Set(d, c.z), lambert));
        X cos_lobe;
        if (k.reflection == ReflectionModel::BlinnPhong) {
            const X hx = add(lx, vx), hy = add(ly, vy), hz = add(lz, vz);
            const X len2 = dot3(hx, hy, hz, hx, hy, hz);
            const X inv = div(one, sqrt(len2));
            cos_lobe = dot3(nx, ny, nz, mul(hx, inv), mul(hy, inv), mul(hz, inv));
            cos_lobe = select(greater(len2, zero), cos_lobe, zero);
        } else {
            const X twice = mul(n_dot_l, hn::Set(d, 2.0f));
            const X rx = sub(mul(nx, twice), lx);
            const X ry = sub(mul(ny, twice), ly);
            const X rz = sub(mul(nz, twice), lz);
            cos_lobe = dot3(rx, ry, rz, vx, vy, vz);
        }
        const X spec = power(d, positive_part(d, cos_lobe), k.shininess);
        sr = add(sr, mul(hn::Set(d, c.x), spec));
        sg = add(sg, mul(hn::Set(d, c.y), spec));
        sb = add(sb, mul(hn::Set(d, c.z), spec));
    }
    // diffuse = ambient + kd * sum; specular = ks * sum; color = base * diffuse + specular.
    const auto ambient = hn::Set(d, k.ambient), kd = hn::Set(d, k.diffuse);
    const X red = add(mul(hn::Set(d, k.base_color.x), add(ambient, mul(kd, dr))),
                      mul(hn::Set(d, k.specular.x), sr));
    const X green = add(mul(hn::Set(d, k.base_color.y), add(ambient, mul(kd, dg))),
                        mul(hn::Set(d, k.specular.y), sg));
    const X blue = add(mul(hn::Set(d, k.base_color.z), add(ambient, mul(kd, db))),
                       mul(hn::Set(d, k.specular.z), sb));
    using VI = decltype(to_unorm8(d, red));
    return RgbLanes<VI>{to_unorm8(d, red), to_unorm8(d, green), to_unorm8(d, blue)};
}

// RGBA8 words (R in the low byte, alpha 255) of shaded lanes.
template <class DU, class VI>
HWY_INLINE auto pack_rgba(DU du, const RgbLanes<VI>& c) {
    return lanewise(
        [du](const auto& r, const auto& g, const auto& b) {
            return hn::Or(hn::Or(hn::BitCast(du, r), hn::ShiftLeft<8>(hn::BitCast(du, g))),
                          hn::Or(hn::ShiftLeft<16>(hn::BitCast(du, b)), hn::Set(du, 0xff000000u)));
        },
        c.r, c.g, c.b);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard (per target)
