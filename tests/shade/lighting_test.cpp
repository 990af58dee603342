#include <zraster/lighting.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace zraster {
namespace {

void expect_vec_near(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tolerance) << "component " << k;
}

// The benchmark's "phong" shading (BENCH-SCENES.md) with the defaults: one white directional
// light towards (-1/3, 2/3, 2/3), local viewer, Blinn-Phong, base (0.8, 0.75, 0.7), ambient 0.15,
// diffuse 0.85, specular 0.25, shininess 32. The expected colors are computed by hand.
glm::vec3 benchmark_color(const glm::vec3& normal, const glm::vec3& view_direction) {
    const LightingModel model;
    const Material material;
    const glm::vec3 position(0.5f, -1.0f, 2.0f);
    const glm::vec3 eye = position + 3.0f * view_direction;
    return combine(evaluate_lighting(model, material, position, normal, eye, {0, 0, 1}),
                   material.base_color);
}

TEST(Lighting, ReproducesTheBenchmarkShading) {
    const glm::vec3 light(-1.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f);
    // N = L = V: N.L = N.H = 1, color = base * (0.15 + 0.85) + 0.25.
    expect_vec_near(benchmark_color(light, light), {1.05f, 1.0f, 0.95f}, 1e-6f);
    // N = +y, V the mirror image of L: N.L = 2/3, H = N so N.H = 1:
    // color = base * (0.15 + 0.85 * 2/3) + 0.25 = base * 0.716667 + 0.25.
    expect_vec_near(benchmark_color({0, 1, 0}, {1.0f / 3.0f, 2.0f / 3.0f, -2.0f / 3.0f}),
                    {0.8233333f, 0.7875f, 0.7516667f}, 1e-6f);
    // N = +y, V = +z: N.L = 2/3, H = (-1, 2, 5) / sqrt(30), N.H^32 = (2 / sqrt(30))^32 = 1e-14.
    expect_vec_near(benchmark_color({0, 1, 0}, {0, 0, 1}), {0.5733333f, 0.5375f, 0.5016667f},
                    1e-6f);
    // N = (0, 1, 1) / sqrt(2), V = +z: N.L = 0.942809, N.H = 7 / sqrt(60) = 0.903696,
    // N.H^32 = 0.0391487.
    expect_vec_near(benchmark_color(glm::normalize(glm::vec3(0, 1, 1)), {0, 0, 1}),
                    {0.7708973f, 0.7233279f, 0.6757586f}, 2e-6f);
    // N facing away from the light: ambient only (and no highlight: N.H < 0 here).
    expect_vec_near(benchmark_color(-light, {0, 0, 1}), {0.12f, 0.1125f, 0.105f}, 1e-6f);
}

TEST(Lighting, SpecularIsNotGatedByNDotL) {
    // L = +y, V = +x (infinite viewer), H = (1, 1, 0) / sqrt(2). N = (1, -0.1, 0) / |..| is just
    // past the terminator (N.L = -0.0995) yet N.H = 0.633238 > 0: the benchmark shader keeps it.
    LightingModel model;
    model.local_viewer = false;
    model.lights[0].direction = {0, 1, 0};
    Material material;
    material.shininess = 1.0f;
    const glm::vec3 n = glm::normalize(glm::vec3(1.0f, -0.1f, 0.0f));
    const LightTerms t = evaluate_lighting(model, material, {0, 0, 0}, n, {0, 0, 0}, {1, 0, 0});
    expect_vec_near(t.diffuse, glm::vec3(0.15f), 1e-7f);  // ambient only
    expect_vec_near(t.specular, glm::vec3(0.25f * 0.6332378f), 1e-6f);
}

LightTerms one_light(ReflectionModel reflection, const glm::vec3& n, const glm::vec3& l,
                     const glm::vec3& v, float shininess) {
    LightingModel model;
    model.reflection = reflection;
    model.local_viewer = false;
    model.lights[0].direction = l;
    Material material;
    material.specular = glm::vec3(1.0f);
    material.shininess = shininess;
    return evaluate_lighting(model, material, {0, 0, 0}, n, {0, 0, 0}, glm::normalize(v));
}

TEST(Lighting, PhongAndBlinnPhongAgreeOnlyAtTheMirrorDirection) {
    const glm::vec3 n(0, 1, 0), l = glm::normalize(glm::vec3(1, 1, 0));
    // V = R = reflect(-L, N): both lobes peak at 1.
    const glm::vec3 mirror = glm::normalize(glm::vec3(-1, 1, 0));
    for (ReflectionModel r : {ReflectionModel::Phong, ReflectionModel::BlinnPhong})
        expect_vec_near(one_light(r, n, l, mirror, 32.0f).specular, glm::vec3(1.0f), 1e-5f);
    // Exactly representable mirror configuration (normal incidence): exactly 1 for both.
    for (ReflectionModel r : {ReflectionModel::Phong, ReflectionModel::BlinnPhong})
        EXPECT_EQ(one_light(r, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 32.0f).specular, glm::vec3(1.0f));
    // V = N, 45 degrees from R: Phong sees R.V = cos 45, Blinn N.H = cos 22.5 (the angle between
    // N and H is half the angle between R and V in the plane of incidence).
    const float phong = one_light(ReflectionModel::Phong, n, l, n, 1.0f).specular.x;
    const float blinn = one_light(ReflectionModel::BlinnPhong, n, l, n, 1.0f).specular.x;
    EXPECT_NEAR(phong, std::cos(0.25f * 3.14159265f), 1e-6f);
    EXPECT_NEAR(blinn, std::cos(0.125f * 3.14159265f), 1e-6f);
    EXPECT_GT(blinn - phong, 0.2f);
    // The diffuse part does not depend on the reflection model.
    EXPECT_EQ(one_light(ReflectionModel::Phong, n, l, n, 1.0f).diffuse,
              one_light(ReflectionModel::BlinnPhong, n, l, n, 1.0f).diffuse);
}

TEST(Lighting, PointLightDirectionAndQuadraticAttenuation) {
    LightingModel model;
    model.lights[0].type = Light::Type::Point;
    model.lights[0].position = {1.0f, 3.0f, -2.0f};
    model.lights[0].quadratic_attenuation = 0.5f;
    Material material;
    material.specular = glm::vec3(0.0f);
    const glm::vec3 p(1.0f, 0.0f, -2.0f), n(0, 1, 0);  // the light is 3 units straight above
    LightTerms t = evaluate_lighting(model, material, p, n, {0, 5, 5}, {0, 0, 1});
    // 1 / (1 + 0.5 * 3^2) = 1 / 5.5, N.L = 1.
    expect_vec_near(t.diffuse, glm::vec3(0.15f + 0.85f / 5.5f), 1e-6f);
    // No falloff when the coefficient is 0.
    model.lights[0].quadratic_attenuation = 0.0f;
    t = evaluate_lighting(model, material, p, n, {0, 5, 5}, {0, 0, 1});
    expect_vec_near(t.diffuse, glm::vec3(1.0f), 1e-6f);
    // The direction is towards the light's position: 60 degrees off the normal gives N.L = 1/2.
    model.lights[0].position = p + glm::vec3(std::sqrt(3.0f), 1.0f, 0.0f);
    t = evaluate_lighting(model, material, p, n, {0, 5, 5}, {0, 0, 1});
    expect_vec_near(t.diffuse, glm::vec3(0.15f + 0.85f * 0.5f), 1e-6f);
    // Light color scales both terms; lights add.
    model.lights[0].color = {1.0f, 0.5f, 0.0f};
    model.lights.push_back(Light{});
    model.lights[1].direction = n;
    t = evaluate_lighting(model, material, p, n, {0, 5, 5}, {0, 0, 1});
    expect_vec_near(t.diffuse, glm::vec3(0.15f) + 0.85f * (glm::vec3(0.5f, 0.25f, 0.0f) + 1.0f),
                    1e-6f);
}

TEST(Lighting, InfiniteViewerUsesTheViewAxis) {
    Material material;
    material.shininess = 4.0f;
    LightingModel local;
    const glm::vec3 p(2.0f, 1.0f, -1.0f), n = glm::normalize(glm::vec3(0.2f, 1.0f, 0.3f));
    const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f));
    LightingModel infinite = local;
    infinite.local_viewer = false;
    // The eye passed is ignored: the result is that of a local viewer straight along the axis.
    const LightTerms far_eye = evaluate_lighting(infinite, material, p, n, {-40, 7, 3}, axis);
    const LightTerms on_axis = evaluate_lighting(local, material, p, n, p + 5.0f * axis, axis);
    expect_vec_near(far_eye.specular, on_axis.specular, 1e-6f);
    expect_vec_near(far_eye.diffuse, on_axis.diffuse, 1e-6f);
    // While a local viewer at that other eye sees a different highlight.
    const LightTerms local_far = evaluate_lighting(local, material, p, n, {-40, 7, 3}, axis);
    EXPECT_GT(std::abs(local_far.specular.x - far_eye.specular.x), 1e-3f);
}

}  // namespace
}  // namespace zraster
