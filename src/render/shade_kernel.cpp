// See shade_kernel.hpp. Highway's foreach_target re-includes this file once per instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/shade_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cmath>

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

struct Rgb {
    hn::Vec<hn::ScalableTag<std::int32_t>> r, g, b;
};

// One vector of pixels: the normal (not yet unit), the world position, and the lanes whose
// normal is negated.
template <class D, class V, class M>
HWY_INLINE Rgb shade_lanes(D d, const PhongConstants& k, V nx, V ny, V nz, V px, V py, V pz,
                           M flip) {
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

void ShadePhongBatch(const PhongConstants& k, PhongBatch& batch) {
    const hn::ScalableTag<float> d;
    const hn::RebindToUnsigned<decltype(d)> du;
    const hn::RebindToSigned<decltype(d)> di;
    const std::size_t lanes = hn::Lanes(d);
    for (std::size_t i = 0; i < static_cast<std::size_t>(batch.count); i += lanes) {
        const auto flip = hn::RebindMask(d, hn::Ne(hn::LoadU(du, batch.flip + i), hn::Zero(du)));
        const Rgb c = shade_lanes(d, k, hn::LoadU(d, batch.nx + i), hn::LoadU(d, batch.ny + i),
                                  hn::LoadU(d, batch.nz + i), hn::LoadU(d, batch.px + i),
                                  hn::LoadU(d, batch.py + i), hn::LoadU(d, batch.pz + i), flip);
        hn::StoreU(c.r, di, batch.r + i);
        hn::StoreU(c.g, di, batch.g + i);
        hn::StoreU(c.b, di, batch.b + i);
    }
}

int ShadeTaggedRow(const PhongConstants* constants, const TileBuffers& tile, std::size_t at,
                   int count, std::uint32_t* rgba) {
    const hn::ScalableTag<float> d;
    const hn::RebindToUnsigned<decltype(d)> du;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto flip_bit = hn::Set(du, kShadeFlip);
    int shaded = 0;
    for (int i = 0; i < count; i += lanes) {
        const std::size_t p = at + std::size_t(i);
        const auto tag = hn::LoadU(du, tile.shade_tag + p);
        const auto kernel = hn::AndNot(flip_bit, tag);
        auto pending = hn::And(hn::Ne(kernel, hn::Zero(du)),
                               hn::FirstN(du, static_cast<std::size_t>(count - i)));
        if (hn::AllFalse(du, pending)) continue;
        shaded += static_cast<int>(hn::CountTrue(du, pending));
        const auto flip = hn::RebindMask(d, hn::Ne(hn::And(tag, flip_bit), hn::Zero(du)));
        const auto nx = hn::LoadU(d, tile.nx + p), ny = hn::LoadU(d, tile.ny + p),
                   nz = hn::LoadU(d, tile.nz + p);
        const auto px = hn::LoadU(d, tile.wx + p), py = hn::LoadU(d, tile.wy + p),
                   pz = hn::LoadU(d, tile.wz + p);
        auto out = hn::LoadU(du, rgba + i);
        // Usually one material per vector; otherwise one pass per material present.
        do {
            const auto first = static_cast<std::size_t>(hn::FindFirstTrue(du, pending));
            const std::uint32_t which = hn::ExtractLane(kernel, first);
            const auto mine = hn::And(pending, hn::Eq(kernel, hn::Set(du, which)));
            const Rgb c = shade_lanes(d, constants[which - 1], nx, ny, nz, px, py, pz, flip);
            const auto color =
                hn::Or(hn::Or(hn::BitCast(du, c.r), hn::ShiftLeft<8>(hn::BitCast(du, c.g))),
                       hn::Or(hn::ShiftLeft<16>(hn::BitCast(du, c.b)), hn::Set(du, 0xff000000u)));
            out = hn::IfThenElse(mine, color, out);
            pending = hn::AndNot(mine, pending);
        } while (!hn::AllFalse(du, pending));
        hn::StoreU(out, du, rgba + i);
    }
    return shaded;
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(ShadePhongBatch);
HWY_EXPORT(ShadeTaggedRow);

int shade_tagged_row(const PhongConstants* constants, const TileBuffers& tile, std::size_t at,
                     int count, std::uint32_t* rgba) {
    return HWY_DYNAMIC_DISPATCH(ShadeTaggedRow)(constants, tile, at, count, rgba);
}

int shade_tagged_row_scalar(const PhongConstants* constants, const TileBuffers& tile,
                            std::size_t at, int count, std::uint32_t* rgba) {
    PhongBatch one;
    one.count = 1;
    int shaded = 0;
    for (int i = 0; i < count; ++i) {
        const std::size_t p = at + std::size_t(i);
        const std::uint32_t kernel = tile.shade_tag[p] & ~kShadeFlip;
        if (kernel == 0) continue;
        ++shaded;
        one.nx[0] = tile.nx[p];
        one.ny[0] = tile.ny[p];
        one.nz[0] = tile.nz[p];
        one.px[0] = tile.wx[p];
        one.py[0] = tile.wy[p];
        one.pz[0] = tile.wz[p];
        one.flip[0] = (tile.shade_tag[p] & kShadeFlip) ? ~0u : 0u;
        shade_phong_batch_scalar(constants[kernel - 1], one);
        rgba[i] = std::uint32_t(one.r[0]) | std::uint32_t(one.g[0]) << 8 |
                  std::uint32_t(one.b[0]) << 16 | 0xff000000u;
    }
    return shaded;
}

void shade_phong_batch(const PhongConstants& constants, PhongBatch& batch) {
    HWY_DYNAMIC_DISPATCH(ShadePhongBatch)(constants, batch);
}

glm::vec3 unit_normal(const glm::vec3& n) {
    const float len = std::sqrt((n.x * n.x + n.y * n.y) + n.z * n.z);
    return len > 0.0f ? glm::vec3(n.x / len, n.y / len, n.z / len) : glm::vec3(0, 1, 0);
}

bool phong_kernel_applies(const LightingModel& model, const Material& material) {
    if (model.lights.size() > std::size_t(kMaxKernelLights)) return false;
    for (const Light& light : model.lights)
        if (light.type != Light::Type::Directional) return false;
    // Range first: converting an out-of-range float (1e30, inf, NaN) to int is undefined.
    const float s = material.shininess;
    if (!(s >= 0.0f && s <= static_cast<float>(kMaxIntegerShininess))) return false;
    return static_cast<float>(static_cast<int>(s)) == s;
}

PhongConstants make_phong_constants(const LightingModel& model, const Material& material,
                                    const glm::vec3& eye, const glm::vec3& view_axis) {
    PhongConstants k;
    k.eye = eye;
    k.view_axis = view_axis;
    k.local_viewer = model.local_viewer;
    k.reflection = model.reflection;
    k.light_count = static_cast<int>(model.lights.size());
    for (int i = 0; i < k.light_count; ++i) {
        const glm::vec3 dir = model.lights[std::size_t(i)].direction;
        const float inv = 1.0f / std::sqrt((dir.x * dir.x + dir.y * dir.y) + dir.z * dir.z);
        k.light_direction[i] = {dir.x * inv, dir.y * inv, dir.z * inv};
        k.light_source_direction[i] = dir;
        // evaluate_lighting scales the color by an attenuation of exactly 1 for these lights.
        k.light_color[i] = model.lights[std::size_t(i)].color * 1.0f;
    }
    k.base_color = material.base_color;
    k.ambient = material.ambient;
    k.diffuse = material.diffuse;
    k.specular = material.specular;
    k.shininess = static_cast<int>(material.shininess);
    return k;
}

void shade_phong_batch_scalar(const PhongConstants& k, PhongBatch& batch) {
    LightingModel model;
    model.local_viewer = k.local_viewer;
    model.reflection = k.reflection;
    model.lights.clear();
    for (int i = 0; i < k.light_count; ++i) {
        Light light;
        light.direction = k.light_source_direction[i];
        light.color = k.light_color[i];
        model.lights.push_back(light);
    }
    Material material;
    material.base_color = k.base_color;
    material.ambient = k.ambient;
    material.diffuse = k.diffuse;
    material.specular = k.specular;
    material.shininess = static_cast<float>(k.shininess);
    for (int i = 0; i < batch.count; ++i) {
        glm::vec3 n = unit_normal({batch.nx[i], batch.ny[i], batch.nz[i]});
        if (batch.flip[i]) n = -n;
        const glm::vec3 color =
            combine(evaluate_lighting(model, material, {batch.px[i], batch.py[i], batch.pz[i]}, n,
                                      k.eye, k.view_axis),
                    k.base_color);
        batch.r[i] = to_unorm8_int(color.x);
        batch.g[i] = to_unorm8_int(color.y);
        batch.b[i] = to_unorm8_int(color.z);
    }
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
