// See shade_kernel.hpp. Highway's foreach_target re-includes this file once per instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/shade_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cmath>

#include "render/shade_kernel.hpp"

// Per target, like this file.
#include "render/phong_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Vectors shaded together (see Pair): four lit the fastest on AVX2 and AVX-512 (eight spill).
constexpr int kGroup = 4;

// Shades the N vectors of the batch at i, i + lanes, ...
template <int N, class D>
HWY_INLINE void shade_batch_group(D d, const PhongConstants& k, PhongBatch& batch, std::size_t i) {
    const hn::RebindToUnsigned<D> du;
    const hn::RebindToSigned<D> di;
    const std::size_t lanes = hn::Lanes(d);
    const auto at = [&](const float* v) {
        return group_of<N>([&](int j) { return hn::LoadU(d, v + i + std::size_t(j) * lanes); });
    };
    const auto flip = group_of<N>([&](int j) {
        const auto word = hn::LoadU(du, batch.flip + i + std::size_t(j) * lanes);
        return hn::RebindMask(d, hn::Ne(word, hn::Zero(du)));
    });
    const auto c = shade_lanes(d, k, at(batch.nx), at(batch.ny), at(batch.nz), at(batch.px),
                               at(batch.py), at(batch.pz), flip);
    const auto store = [&](std::int32_t* out, const auto& channel) {
        for_each_of<N>(channel, [&](const auto& v, int j) {
            hn::StoreU(v, di, out + i + std::size_t(j) * lanes);
        });
    };
    store(batch.r, c.r);
    store(batch.g, c.g);
    store(batch.b, c.b);
}

void ShadePhongBatch(const PhongConstants& k, PhongBatch& batch) {
    const hn::ScalableTag<float> d;
    const std::size_t lanes = hn::Lanes(d);
    const auto count = static_cast<std::size_t>(batch.count);
    std::size_t i = 0;
    for (; i + (kGroup - 1) * lanes < count; i += kGroup * lanes)
        shade_batch_group<kGroup>(d, k, batch, i);
    for (; i < count; i += lanes) shade_batch_group<1>(d, k, batch, i);
}

// The tagged pixels of the N vectors of a row at the offsets `starts` (all of one material,
// constants `k`), written over rgba.
template <int N, class D>
HWY_INLINE void shade_row_group(D d, const PhongConstants& k, const TileBuffers& tile,
                                std::size_t at, int count, const int* starts, std::uint32_t* rgba) {
    const hn::RebindToUnsigned<D> du;
    const auto flip_bit = hn::Set(du, kShadeFlip);
    const auto from = [&](const float* v) {
        return group_of<N>([&](int j) { return hn::LoadU(d, v + at + std::size_t(starts[j])); });
    };
    const auto flip = group_of<N>([&](int j) {
        const auto tag = hn::LoadU(du, tile.shade_tag + at + std::size_t(starts[j]));
        return hn::RebindMask(d, hn::Ne(hn::And(tag, flip_bit), hn::Zero(du)));
    });
    const auto color =
        pack_rgba(du, shade_lanes(d, k, from(tile.nx), from(tile.ny), from(tile.nz), from(tile.wx),
                                  from(tile.wy), from(tile.wz), flip));
    for_each_of<N>(color, [&](const auto& c, int j) {
        const auto start = static_cast<std::size_t>(starts[j]);
        const auto tag = hn::LoadU(du, tile.shade_tag + at + start);
        const auto pending = hn::And(hn::Ne(hn::AndNot(flip_bit, tag), hn::Zero(du)),
                                     hn::FirstN(du, std::size_t(count) - start));
        hn::StoreU(hn::IfThenElse(pending, c, hn::LoadU(du, rgba + start)), du, rgba + start);
    });
}

int ShadeTaggedRow(const PhongConstants* constants, const TileBuffers& tile, std::size_t at,
                   int count, std::uint32_t* rgba) {
    const hn::ScalableTag<float> d;
    const hn::RebindToUnsigned<decltype(d)> du;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const auto flip_bit = hn::Set(du, kShadeFlip);
    int shaded = 0;
    // Vectors whose tagged pixels are all of material queued_tag wait here to be shaded
    // kGroup at a time.
    int queued[kGroup], queued_count = 0;
    std::uint32_t queued_tag = 0;
    const auto flush = [&] {
        const PhongConstants& k = constants[queued_tag - 1];
        if (queued_count == 1) shade_row_group<1>(d, k, tile, at, count, queued, rgba);
        if (queued_count == 2) shade_row_group<2>(d, k, tile, at, count, queued, rgba);
        if (queued_count >= 3) {
            // Three as four (the third twice): as fast as two and one.
            queued[3] = queued[queued_count - 1];
            shade_row_group<4>(d, k, tile, at, count, queued, rgba);
        }
        queued_count = 0;
    };
    for (int i = 0; i < count; i += lanes) {
        const std::size_t p = at + std::size_t(i);
        const auto tag = hn::LoadU(du, tile.shade_tag + p);
        const auto kernel = hn::AndNot(flip_bit, tag);
        auto pending = hn::And(hn::Ne(kernel, hn::Zero(du)),
                               hn::FirstN(du, static_cast<std::size_t>(count - i)));
        if (hn::AllFalse(du, pending)) continue;
        shaded += static_cast<int>(hn::CountTrue(du, pending));
        const auto first = static_cast<std::size_t>(hn::FindFirstTrue(du, pending));
        // (From memory: a lane extracted at a run-time index goes through the stack.)
        const std::uint32_t which = tile.shade_tag[p + first] & ~kShadeFlip;
        const auto mine = hn::And(pending, hn::Eq(kernel, hn::Set(du, which)));
        if (hn::AllFalse(du, hn::AndNot(mine, pending))) {  // one material: queue the vector
            if (queued_count > 0 && queued_tag != which) flush();
            queued_tag = which;
            queued[queued_count++] = i;
            if (queued_count == kGroup) flush();
            continue;
        }
        // Several materials: one pass per material present.
        const auto nx = hn::LoadU(d, tile.nx + p), ny = hn::LoadU(d, tile.ny + p),
                   nz = hn::LoadU(d, tile.nz + p);
        const auto px = hn::LoadU(d, tile.wx + p), py = hn::LoadU(d, tile.wy + p),
                   pz = hn::LoadU(d, tile.wz + p);
        const auto flip = hn::RebindMask(d, hn::Ne(hn::And(tag, flip_bit), hn::Zero(du)));
        auto out = hn::LoadU(du, rgba + i);
        do {
            const auto lane = static_cast<std::size_t>(hn::FindFirstTrue(du, pending));
            const std::uint32_t material = tile.shade_tag[p + lane] & ~kShadeFlip;
            const auto these = hn::And(pending, hn::Eq(kernel, hn::Set(du, material)));
            const auto color = pack_rgba(
                du, shade_lanes(d, constants[material - 1], nx, ny, nz, px, py, pz, flip));
            out = hn::IfThenElse(these, color, out);
            pending = hn::AndNot(these, pending);
        } while (!hn::AllFalse(du, pending));
        hn::StoreU(out, du, rgba + i);
    }
    if (queued_count > 0) flush();
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

namespace {
std::uint32_t rgba_of(const PhongBatch& batch, int i) {
    return std::uint32_t(batch.r[i]) | std::uint32_t(batch.g[i]) << 8 |
           std::uint32_t(batch.b[i]) << 16 | 0xff000000u;
}
}  // namespace

std::uint32_t shade_interpolated_scalar(const PhongConstants& constants,
                                        const CornerAttributes& corners, const glm::vec3* piece,
                                        float b1, float b2) {
    const glm::vec3 w = interpolation_weights(piece, b1, b2);
    const glm::vec3 n = interpolate_corners(corners.normal, w);
    const glm::vec3 p = interpolate_corners(corners.world, w);
    PhongBatch one;
    one.count = 1;
    one.nx[0] = n.x;
    one.ny[0] = n.y;
    one.nz[0] = n.z;
    one.px[0] = p.x;
    one.py[0] = p.y;
    one.pz[0] = p.z;
    one.flip[0] = (corners.tag & kShadeFlip) ? ~0u : 0u;
    shade_phong_batch_scalar(constants, one);
    return rgba_of(one, 0);
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
        rgba[i] = rgba_of(one, 0);
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
