// Local illumination: Phong 1975, "Illumination for Computer Generated Pictures" (specular lobe
// around the mirror direction R), and Blinn 1977, "Models of Light Reflection for Computer
// Synthesized Pictures" (the half vector H instead of R).
//
// As in the benchmark shader (docs/bench-scenes.md) the specular term is not gated by N.L: a
// highlight can appear on a point the light does not reach directly when V and L are both grazing.
//
// The arithmetic is written out component by component, in a fixed order and with explicit
// selects instead of std::max, because the SIMD shading kernel (src/render/shade_kernel.cpp)
// reproduces it operation for operation and a test compares the two bit for bit.
#include <zraster/lighting.hpp>

#include <cmath>

namespace zraster {
namespace {

float dot3(const glm::vec3& a, const glm::vec3& b) {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

// x * (1 / sqrt(x.x)): as the kernel computes it.
glm::vec3 normalized(const glm::vec3& v) {
    const float inv = 1.0f / std::sqrt(dot3(v, v));
    return {v.x * inv, v.y * inv, v.z * inv};
}

float positive_part(float x) {
    return x > 0.0f ? x : 0.0f;
}

}  // namespace

float specular_power(float x, float shininess) {
    // Range first: converting a float outside int's range (1e30, inf, NaN) to int is undefined
    // (found by fuzz_pipeline).
    if (!(shininess >= 0.0f && shininess <= static_cast<float>(kMaxIntegerShininess)))
        return std::pow(x, shininess);
    const int n = static_cast<int>(shininess);
    if (static_cast<float>(n) != shininess) return std::pow(x, shininess);
    // Exponentiation by squaring: the same multiplications in the scalar and SIMD paths.
    float result = 1.0f, base = x;
    for (int e = n; e > 0; e >>= 1) {
        if (e & 1) result = result * base;
        base = base * base;
    }
    return result;
}

LightTerms evaluate_lighting(const LightingModel& model, const Material& material,
                             const glm::vec3& position, const glm::vec3& normal,
                             const glm::vec3& eye, const glm::vec3& view_axis) {
    const glm::vec3 v = model.local_viewer ? normalized(eye - position) : view_axis;
    glm::vec3 diffuse_sum(0.0f), specular_sum(0.0f);
    for (const Light& light : model.lights) {
        glm::vec3 l;
        float attenuation = 1.0f;
        if (light.type == Light::Type::Directional) {
            l = normalized(light.direction);
        } else {
            const glm::vec3 to_light = light.position - position;
            const float d2 = dot3(to_light, to_light);
            if (!(d2 > 0.0f)) continue;  // a light at the point itself has no direction
            const float inv = 1.0f / std::sqrt(d2);
            l = {to_light.x * inv, to_light.y * inv, to_light.z * inv};
            attenuation = 1.0f / (1.0f + light.quadratic_attenuation * d2);
        }
        const glm::vec3 intensity = light.color * attenuation;
        diffuse_sum += intensity * positive_part(dot3(normal, l));

        float cos_lobe = 0.0f;
        if (model.reflection == ReflectionModel::BlinnPhong) {
            const glm::vec3 sum = l + v;
            const float len2 = dot3(sum, sum);
            // L = -V (light exactly behind the viewer's line): H is undefined, no highlight.
            if (len2 > 0.0f) {
                const float inv = 1.0f / std::sqrt(len2);
                cos_lobe = dot3(normal, {sum.x * inv, sum.y * inv, sum.z * inv});
            }
        } else {
            // R = reflect(-L, N) = -L + N * (2 N.L)
            const float twice = dot3(normal, l) * 2.0f;
            const glm::vec3 r(normal.x * twice - l.x, normal.y * twice - l.y,
                              normal.z * twice - l.z);
            cos_lobe = dot3(r, v);
        }
        specular_sum += intensity * specular_power(positive_part(cos_lobe), material.shininess);
    }
    LightTerms terms;
    terms.diffuse = glm::vec3(material.ambient) + material.diffuse * diffuse_sum;
    terms.specular = material.specular * specular_sum;
    return terms;
}

}  // namespace zraster
