// SIMD deferred shading for the common case: Phong shading (normals interpolated, lit per pixel)
// of untextured surfaces by directional lights, with an integer shininess. It reproduces the
// scalar path (unit normal, two-sided flip, evaluate_lighting, combine, 8-bit rounding)
// operation for operation; a test compares it with shade_phong_batch_scalar bit for bit.
#pragma once
#include <zraster/lighting.hpp>

#include "raster/visibility_kernel.hpp"

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

// Shades the pixels [at, at + count) of a tile row whose shade_tag is set (constants[tag - 1])
// from the interpolated normals and positions there, and writes them as RGBA8 (R in the low
// byte) to rgba[0, count); other pixels of rgba are left alone (rgba holds TileBuffers::kStride
// values: vectors may run past count). Returns the number of pixels shaded.
int shade_tagged_row(const PhongConstants* constants, const TileBuffers& tile, std::size_t at,
                     int count, std::uint32_t* rgba);
int shade_tagged_row_scalar(const PhongConstants* constants, const TileBuffers& tile,
                            std::size_t at, int count, std::uint32_t* rgba);

// The scalar twin of the visibility kernel's forward shading: the corner attributes
// interpolated at (b1, b2) as store_interpolated does, lit, as RGBA8.
std::uint32_t shade_interpolated_scalar(const PhongConstants& constants,
                                        const CornerAttributes& corners, const glm::vec3* piece,
                                        float b1, float b2);

// The scalar unit normal used by both paths: n / |n|, or (0, 1, 0) for a zero vector.
glm::vec3 unit_normal(const glm::vec3& n);
// 8-bit rounding used by both paths.
inline std::int32_t to_unorm8_int(float v) {
    v = v > 0.0f ? v : 0.0f;
    v = v < 1.0f ? v : 1.0f;
    return static_cast<std::int32_t>(v * 255.0f + 0.5f);
}

}  // namespace zraster::detail
