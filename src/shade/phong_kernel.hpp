// The Phong lighting of batches of pixels for the common case: Phong shading (normals
// interpolated, lit per pixel) of untextured surfaces by directional lights, with an integer
// shininess. The SIMD batch shader (and the lanes of phong_lanes-inl.h, which the visibility
// kernel's forward shading and the deferred row shader inline) reproduce the scalar path (unit
// normal, two-sided flip, evaluate_lighting, combine, 8-bit rounding) operation for operation; a
// test compares shade_phong_batch with shade_phong_batch_scalar bit for bit.
#pragma once
#include <zraster/lighting.hpp>
#include <zraster/material.hpp>

#include <glm/glm.hpp>

#include <cstdint>

namespace zraster::detail {

inline constexpr int kMaxKernelLights = 4;
inline constexpr int kShadeBatch = 64;

struct PhongConstants {
    glm::vec3 eye{0.0f}, view_axis{0.0f, 0.0f, 1.0f};
    bool local_viewer = true;
    ReflectionModel reflection = ReflectionModel::BlinnPhong;
    int light_count = 0;
    glm::vec3 light_direction[kMaxKernelLights];         // normalized as evaluate_lighting does
    glm::vec3 light_source_direction[kMaxKernelLights];  // as given (for the scalar reference)
    glm::vec3 light_color[kMaxKernelLights];
    glm::vec3 base_color{0.0f};
    float ambient = 0.0f, diffuse = 0.0f;
    glm::vec3 specular{0.0f};
    int shininess = 0;
};

// True when the kernel reproduces evaluate_lighting for this model and material.
bool phong_kernel_applies(const LightingModel& model, const Material& material);
PhongConstants make_phong_constants(const LightingModel& model, const Material& material,
                                    const glm::vec3& eye, const glm::vec3& view_axis);

// Structure of arrays, kShadeBatch pixels (plus padding for the vector tail).
struct PhongBatch {
    int count = 0;
    alignas(64) float nx[kShadeBatch + 16], ny[kShadeBatch + 16], nz[kShadeBatch + 16];
    alignas(64) float px[kShadeBatch + 16], py[kShadeBatch + 16], pz[kShadeBatch + 16];
    alignas(64) std::uint32_t flip[kShadeBatch + 16];  // ~0 where the normal is negated
    alignas(64) std::int32_t r[kShadeBatch + 16], g[kShadeBatch + 16], b[kShadeBatch + 16];
};

// Writes r, g, b (0..255) for the first `count` pixels.
void shade_phong_batch(const PhongConstants& constants, PhongBatch& batch);
void shade_phong_batch_scalar(const PhongConstants& k, PhongBatch& batch);

// The scalar unit normal used by both paths: n / |n|, or (0, 1, 0) for a zero vector.
glm::vec3 unit_normal(const glm::vec3& n);
// 8-bit rounding used by both paths.
inline std::int32_t to_unorm8_int(float v) {
    v = v > 0.0f ? v : 0.0f;
    v = v < 1.0f ? v : 1.0f;
    return static_cast<std::int32_t>(v * 255.0f + 0.5f);
}
inline std::uint8_t to_unorm8(float v) {
    return static_cast<std::uint8_t>(to_unorm8_int(v));
}

// RGBA8 (R in the low byte, alpha 255) of pixel i of a shaded batch.
inline std::uint32_t batch_rgba(const PhongBatch& batch, int i) {
    return std::uint32_t(batch.r[i]) | std::uint32_t(batch.g[i]) << 8 |
           std::uint32_t(batch.b[i]) << 16 | 0xff000000u;
}

}  // namespace zraster::detail
