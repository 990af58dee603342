// Local illumination: Phong 1975, "Illumination for Computer Generated Pictures" (specular lobe
// around the mirror direction R), and Blinn 1977, "Models of Light Reflection for Computer
// Synthesized Pictures" (the half vector H instead of R).
//
// As in the benchmark shader (BENCH-SCENES.md) the specular term is not gated by N.L: a highlight
// can appear on a point the light does not reach directly when V and L are both grazing.
#include <zraster/lighting.hpp>

#include <algorithm>
#include <cmath>

namespace zraster {

LightTerms evaluate_lighting(const LightingModel& model, const Material& material,
                             const glm::vec3& position, const glm::vec3& normal,
                             const glm::vec3& eye, const glm::vec3& view_axis) {
    const glm::vec3 v = model.local_viewer ? glm::normalize(eye - position) : view_axis;
    glm::vec3 diffuse_sum(0.0f), specular_sum(0.0f);
    for (const Light& light : model.lights) {
        glm::vec3 l;
        float attenuation = 1.0f;
        if (light.type == Light::Type::Directional) {
            l = glm::normalize(light.direction);
        } else {
            const glm::vec3 to_light = light.position - position;
            const float d2 = glm::dot(to_light, to_light);
            if (!(d2 > 0.0f)) continue;  // a light at the point itself has no direction
            l = to_light / std::sqrt(d2);
            attenuation = 1.0f / (1.0f + light.quadratic_attenuation * d2);
        }
        const glm::vec3 intensity = light.color * attenuation;
        diffuse_sum += intensity * std::max(glm::dot(normal, l), 0.0f);

        float cos_lobe = 0.0f;
        if (model.reflection == ReflectionModel::BlinnPhong) {
            const glm::vec3 sum = l + v;
            const float len2 = glm::dot(sum, sum);
            // L = -V (light exactly behind the viewer's line): H is undefined, no highlight.
            if (len2 > 0.0f) cos_lobe = glm::dot(normal, sum / std::sqrt(len2));
        } else {
            cos_lobe = glm::dot(glm::reflect(-l, normal), v);
        }
        specular_sum += intensity * std::pow(std::max(cos_lobe, 0.0f), material.shininess);
    }
    LightTerms terms;
    terms.diffuse = glm::vec3(material.ambient) + material.diffuse * diffuse_sum;
    terms.specular = material.specular * specular_sum;
    return terms;
}

}  // namespace zraster
