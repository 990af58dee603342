// See phong_kernel.hpp. Highway's foreach_target re-includes this file once per instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "shade/phong_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cmath>

#include "shade/phong_kernel.hpp"

// Per target, like this file.
#include "shade/phong_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
    for (; i + (kShadeGroup - 1) * lanes < count; i += kShadeGroup * lanes)
        shade_batch_group<kShadeGroup>(d, k, batch, i);
    for (; i < count; i += lanes) shade_batch_group<1>(d, k, batch, i);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(ShadePhongBatch);

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
