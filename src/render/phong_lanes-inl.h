// The SIMD Phong lighting of one vector of pixels, shared by the deferred row shader
// (shade_kernel.cpp) and the visibility kernel's forward shading (visibility_kernel.cpp). It
// reproduces the scalar path (unit normal, two-sided flip, evaluate_lighting, combine, 8-bit
// rounding) operation for operation.
//
// Highway "-inl" header: included once per instruction set by files that use foreach_target.
#if defined(ZRASTER_RENDER_PHONG_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef ZRASTER_RENDER_PHONG_LANES_INL_H_
#undef ZRASTER_RENDER_PHONG_LANES_INL_H_
#else
#define ZRASTER_RENDER_PHONG_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include "render/shade_kernel.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D, class V>
HWY_INLINE V dot3(D, V ax, V ay, V az, V bx, V by, V bz) {
    return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
}

template <class D, class V>
HWY_INLINE V positive_part(D d, V x) {
    return hn::IfThenElse(hn::Gt(x, hn::Zero(d)), x, hn::Zero(d));
}

template <class D, class V>
HWY_INLINE V power(D d, V x, int n) {
    V result = hn::Set(d, 1.0f), base = x;
    for (int e = n; e > 0; e >>= 1) {
        if (e & 1) result = hn::Mul(result, base);
        base = hn::Mul(base, base);
    }
    return result;
}

template <class D, class V>
HWY_INLINE hn::Vec<hn::RebindToSigned<D>> to_unorm8(D d, V v) {
    v = hn::IfThenElse(hn::Gt(v, hn::Zero(d)), v, hn::Zero(d));
    v = hn::IfThenElse(hn::Lt(v, hn::Set(d, 1.0f)), v, hn::Set(d, 1.0f));
    return hn::ConvertTo(hn::RebindToSigned<D>(),
                         hn::Add(hn::Mul(v, hn::Set(d, 255.0f)), hn::Set(d, 0.5f)));
}

// 8-bit channels (0..255) of a vector of pixels.
template <class DI>
struct RgbLanes {
    hn::Vec<DI> r, g, b;
};

// One vector of pixels: the normal (not yet unit), the world position, and the lanes whose
// normal is negated.
template <class D, class V, class M>
HWY_INLINE RgbLanes<hn::RebindToSigned<D>> shade_lanes(D d, const PhongConstants& k, V nx, V ny,
                                                       V nz, V px, V py, V pz, M flip) {
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    // Unit normal, or (0, 1, 0); negated for back faces.
    const auto len = hn::Sqrt(dot3(d, nx, ny, nz, nx, ny, nz));
    const auto has_length = hn::Gt(len, zero);
    nx = hn::IfThenElse(has_length, hn::Div(nx, len), zero);
    ny = hn::IfThenElse(has_length, hn::Div(ny, len), one);
    nz = hn::IfThenElse(has_length, hn::Div(nz, len), zero);
    nx = hn::IfThenElse(flip, hn::Neg(nx), nx);
    ny = hn::IfThenElse(flip, hn::Neg(ny), ny);
    nz = hn::IfThenElse(flip, hn::Neg(nz), nz);

    V vx, vy, vz;
    if (k.local_viewer) {
        vx = hn::Sub(hn::Set(d, k.eye.x), px);
        vy = hn::Sub(hn::Set(d, k.eye.y), py);
        vz = hn::Sub(hn::Set(d, k.eye.z), pz);
        const auto inv = hn::Div(one, hn::Sqrt(dot3(d, vx, vy, vz, vx, vy, vz)));
        vx = hn::Mul(vx, inv);
        vy = hn::Mul(vy, inv);
        vz = hn::Mul(vz, inv);
    } else {
        vx = hn::Set(d, k.view_axis.x);
        vy = hn::Set(d, k.view_axis.y);
        vz = hn::Set(d, k.view_axis.z);
    }

    auto dr = zero, dg = zero, db = zero, sr = zero, sg = zero, sb = zero;
    for (int l = 0; l < k.light_count; ++l) {
        const glm::vec3 L = k.light_direction[l], c = k.light_color[l];
        const auto lx = hn::Set(d, L.x), ly = hn::Set(d, L.y), lz = hn::Set(d, L.z);
        const auto n_dot_l = dot3(d, nx, ny, nz, lx, ly, lz);
        const auto lambert = positive_part(d, n_dot_l);
        dr = hn::Add(dr, hn::Mul(hn::Set(d, c.x), lambert));
        dg = hn::Add(dg, hn::Mul(hn::Set(d, c.y), lambert));
        db = hn::Add(db, hn::Mul(hn::Set(d, c.z), lambert));
        V cos_lobe;
        if (k.reflection == ReflectionModel::BlinnPhong) {
            const auto hx = hn::Add(lx, vx), hy = hn::Add(ly, vy), hz = hn::Add(lz, vz);
            const auto len2 = dot3(d, hx, hy, hz, hx, hy, hz);
            const auto inv = hn::Div(one, hn::Sqrt(len2));
            cos_lobe = dot3(d, nx, ny, nz, hn::Mul(hx, inv), hn::Mul(hy, inv), hn::Mul(hz, inv));
            cos_lobe = hn::IfThenElse(hn::Gt(len2, zero), cos_lobe, zero);
        } else {
            const auto twice = hn::Mul(n_dot_l, hn::Set(d, 2.0f));
            const auto rx = hn::Sub(hn::Mul(nx, twice), lx);
            const auto ry = hn::Sub(hn::Mul(ny, twice), ly);
            const auto rz = hn::Sub(hn::Mul(nz, twice), lz);
            cos_lobe = dot3(d, rx, ry, rz, vx, vy, vz);
        }
        const auto spec = power(d, positive_part(d, cos_lobe), k.shininess);
        sr = hn::Add(sr, hn::Mul(hn::Set(d, c.x), spec));
        sg = hn::Add(sg, hn::Mul(hn::Set(d, c.y), spec));
        sb = hn::Add(sb, hn::Mul(hn::Set(d, c.z), spec));
    }
    // diffuse = ambient + kd * sum; specular = ks * sum; color = base * diffuse + specular.
    const auto ambient = hn::Set(d, k.ambient), kd = hn::Set(d, k.diffuse);
    const auto red = hn::Add(hn::Mul(hn::Set(d, k.base_color.x), hn::Add(ambient, hn::Mul(kd, dr))),
                             hn::Mul(hn::Set(d, k.specular.x), sr));
    const auto green =
        hn::Add(hn::Mul(hn::Set(d, k.base_color.y), hn::Add(ambient, hn::Mul(kd, dg))),
                hn::Mul(hn::Set(d, k.specular.y), sg));
    const auto blue =
        hn::Add(hn::Mul(hn::Set(d, k.base_color.z), hn::Add(ambient, hn::Mul(kd, db))),
                hn::Mul(hn::Set(d, k.specular.z), sb));
    return {to_unorm8(d, red), to_unorm8(d, green), to_unorm8(d, blue)};
}

// RGBA8 words (R in the low byte, alpha 255) of shaded lanes.
template <class DU, class DI>
HWY_INLINE hn::Vec<DU> pack_rgba(DU du, const RgbLanes<DI>& c) {
    return hn::Or(hn::Or(hn::BitCast(du, c.r), hn::ShiftLeft<8>(hn::BitCast(du, c.g))),
                  hn::Or(hn::ShiftLeft<16>(hn::BitCast(du, c.b)), hn::Set(du, 0xff000000u)));
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // include guard (per target)
