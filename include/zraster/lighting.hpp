// Lights and the Phong / Blinn-Phong reflection models (Phong 1975, Blinn 1977).
#pragma once
#include <zraster/export.hpp>
#include <zraster/material.hpp>

#include <vector>

namespace zraster {

enum class ShadingMode {
    Flat,     // one face normal per triangle, lit once per triangle
    Gouraud,  // lit per vertex, colors interpolated (Gouraud 1971)
    Phong,    // normals interpolated, lit per pixel (Phong 1975)
    Unlit,    // the base color (times the texture), no lighting
};

enum class ReflectionModel {
    Phong,       // specular = max(R.V, 0)^n, R = reflect(-L, N)
    BlinnPhong,  // specular = max(N.H, 0)^n, H = normalize(L + V)
};

struct Light {
    enum class Type { Directional, Point };
    Type type = Type::Directional;
    glm::vec3 direction{-1.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f};  // towards the light, world space
    glm::vec3 position{0.0f};                                     // point lights, world space
    glm::vec3 color{1.0f};
    // Point lights: intensity / (1 + quadratic * d^2); zero means no falloff.
    float quadratic_attenuation = 0.0f;
};

struct LightingModel {
    ReflectionModel reflection = ReflectionModel::BlinnPhong;
    // Local viewer: V = normalize(eye - P) per point. Infinite viewer: V is the constant direction
    // towards the eye along the view axis (cheaper, highlights slide less with position).
    bool local_viewer = true;
    std::vector<Light> lights =
        std::vector<Light>(1);  // one default light (not an init list: GCC 12 warns falsely on it)
};

// The two parts of the lit color, kept apart so Gouraud shading can interpolate them per vertex
// and still apply a per-pixel texture: color = base * diffuse + specular.
struct LightTerms {
    glm::vec3 diffuse{0.0f};   // ambient + diffuse factors (multiplied by the base color later)
    glm::vec3 specular{0.0f};  // added after the base color
};

// position: world-space point; normal: unit world-space normal facing the viewer side;
// eye: world-space eye; view_axis: unit direction from the scene towards the eye (infinite viewer).
ZRASTER_API LightTerms evaluate_lighting(const LightingModel& model, const Material& material,
                                         const glm::vec3& position, const glm::vec3& normal,
                                         const glm::vec3& eye, const glm::vec3& view_axis);

// x^shininess for x >= 0. Integer exponents up to kMaxIntegerShininess use exponentiation by
// squaring (exactly reproducible by SIMD code), others std::pow.
inline constexpr int kMaxIntegerShininess = 4096;
ZRASTER_API float specular_power(float x, float shininess);

inline glm::vec3 combine(const LightTerms& terms, const glm::vec3& base) {
    return base * terms.diffuse + terms.specular;
}

}  // namespace zraster
