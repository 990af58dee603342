// Shading through the renderer: flat is constant per triangle, Phong matches the lighting model
// evaluated at the ray-cast surface point, Gouraud misses highlights between vertices that Phong
// catches, point lights peak where they should, and user clip planes cut where they say.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <map>

#include "render/render_test_util.hpp"

namespace zraster::test {
namespace {

glm::vec3 pixel_color(const RenderTargets& t, int x, int y) {
    const std::uint8_t* c = &t.color[(std::size_t(y) * std::size_t(t.width) + std::size_t(x)) * 4];
    return glm::vec3(c[0], c[1], c[2]) / 255.0f;
}

Camera front_camera() {
    Camera c;
    c.eye = {0, 0, 4};
    c.target = {0, 0, 0};
    c.near = 1;
    c.far = 10;
    c.fovy_degrees = 45;
    return c;
}

TEST(Shading, FlatIsConstantPerTriangle) {
    Scene scene = scene_from_meshes({make_uv_sphere(1.0f, 8, 16)});
    RenderOptions o;
    o.width = 200;
    o.height = 200;
    o.shading = ShadingMode::Flat;
    o.id_targets = true;
    const auto r = render(scene, o);
    std::map<int, glm::u8vec3> color_of;
    int violations = 0, pixels = 0;
    for (std::size_t i = 0; i < r.targets.primitive_id.size(); ++i) {
        const int id = r.targets.primitive_id[i];
        if (id < 0) continue;
        ++pixels;
        const glm::u8vec3 c(r.targets.color[i * 4], r.targets.color[i * 4 + 1],
                            r.targets.color[i * 4 + 2]);
        auto [it, inserted] = color_of.emplace(id, c);
        violations += !inserted && it->second != c;
    }
    EXPECT_GT(pixels, 10000);
    EXPECT_GT(color_of.size(), 50u);
    EXPECT_EQ(violations, 0);
}

TEST(Shading, PhongOnAPlaneMatchesTheLightingModelAtTheRayCastPoint) {
    // A big quad at z = 0 facing +z, normals +z; a point light close to it so the lighting varies
    // strongly over the surface; local viewer. Each pixel must equal evaluate_lighting at the
    // point its ray hits, within 1.5/255 (8-bit rounding plus float interpolation).
    const std::vector<glm::vec3> quad{{-3, -3, 0}, {3, -3, 0}, {3, 3, 0},
                                      {-3, -3, 0}, {3, 3, 0},  {-3, 3, 0}};
    Scene scene = scene_from_triangles({quad});
    RenderOptions o;
    o.width = 160;
    o.height = 120;
    o.camera = front_camera();
    o.camera->eye = {0.7, 0.4, 3};
    Light point;
    point.type = Light::Type::Point;
    point.position = {0.5f, -0.3f, 0.8f};
    point.quadratic_attenuation = 0.5f;
    o.lighting.lights = {point};
    o.lighting.reflection = ReflectionModel::Phong;
    const auto r = render(scene, o);
    RayCaster caster(*o.camera, o.width, o.height);
    float worst = 0;
    int compared = 0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            const auto ray = caster.ray(x, y);
            const double t = -ray.origin.z / ray.direction.z;
            const glm::vec3 p(ray.origin + t * ray.direction);
            if (std::abs(p.x) > 2.9f || std::abs(p.y) > 2.9f) continue;
            const LightTerms terms = evaluate_lighting(o.lighting, scene.materials[0], p, {0, 0, 1},
                                                       glm::vec3(o.camera->eye), {0, 0, 1});
            const glm::vec3 expected =
                glm::clamp(combine(terms, scene.materials[0].base_color), 0.0f, 1.0f);
            const glm::vec3 got = pixel_color(r.targets, x, y);
            worst = std::max(worst, glm::length(got - expected) / std::sqrt(3.0f));
            ++compared;
        }
    EXPECT_GT(compared, 10000);
    EXPECT_LT(worst, 1.5f / 255.0f);
}

TEST(Shading, GouraudMissesTheHighlightThatPhongCatches) {
    // A coarse sphere with a sharp highlight: per-vertex lighting cannot reach the peak that
    // lies between vertices; per-pixel lighting does.
    Scene scene = scene_from_meshes({make_uv_sphere(1.0f, 6, 12)});
    scene.materials[0].shininess = 200;
    scene.materials[0].specular = glm::vec3(0.5f);
    scene.materials[0].base_color = glm::vec3(0.3f);  // keep the peak below saturation
    RenderOptions o;
    o.width = 200;
    o.height = 200;
    o.camera = front_camera();
    o.lighting.lights[0].direction = glm::normalize(glm::vec3(0.15f, 0.1f, 1.0f));
    auto brightest = [&](ShadingMode mode) {
        o.shading = mode;
        const auto r = render(scene, o);
        float best = 0;
        for (std::size_t i = 0; i < r.targets.color.size(); i += 4)
            best = std::max(
                best, float(r.targets.color[i] + r.targets.color[i + 1] + r.targets.color[i + 2]));
        return best / (3 * 255.0f);
    };
    const float phong = brightest(ShadingMode::Phong);
    const float gouraud = brightest(ShadingMode::Gouraud);
    EXPECT_GT(phong, 0.75f);  // 0.3 * (0.15 + 0.85) + 0.5 at the mirror direction
    EXPECT_LT(gouraud, phong - 0.1f);
}

TEST(Shading, UserClipPlaneRemovesEverythingBehindIt) {
    Scene scene = scene_from_meshes({make_uv_sphere(1.0f, 32, 64)});
    RenderOptions o;
    o.width = 200;
    o.height = 200;
    o.camera = front_camera();
    o.id_targets = true;
    o.cull = CullMode::None;
    o.clip_planes = {glm::vec4(1, 0, 0, -0.25f)};  // keep x >= 0.25
    const auto r = render(scene, o);
    RayCaster caster(*o.camera, o.width, o.height);
    int drawn = 0, wrong = 0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            if (r.targets.instance_id[std::size_t(y * o.width + x)] < 0) continue;
            ++drawn;
            // The visible point lies on the sphere (front or, through the cut, back): its x is
            // at least 0.25 minus the tessellation's slack.
            const auto ray = caster.ray(x, y);
            const double b = glm::dot(ray.origin, ray.direction);
            const double c = glm::dot(ray.origin, ray.origin) - 1.0;
            const double disc = b * b - c;
            if (disc < 0) continue;
            const double t_far = -b + std::sqrt(disc);
            wrong += (ray.origin + t_far * ray.direction).x < 0.2;
        }
    EXPECT_GT(drawn, 3000);
    EXPECT_EQ(wrong, 0);
}

TEST(Shading, OrthographicCameraProjectsToExactSizes) {
    // A unit square seen orthographically with a view 4 units high over 400 pixels: 100 pixels.
    const std::vector<glm::vec3> quad{{-0.5f, -0.5f, 0}, {0.5f, -0.5f, 0}, {0.5f, 0.5f, 0},
                                      {-0.5f, -0.5f, 0}, {0.5f, 0.5f, 0},  {-0.5f, 0.5f, 0}};
    RenderOptions o;
    o.width = 400;
    o.height = 400;
    o.camera = front_camera();
    o.camera->projection = Camera::Projection::Orthographic;
    o.camera->ortho_height = 4;
    o.id_targets = true;
    const auto r = render(scene_from_triangles({quad}), o);
    int covered = 0;
    for (const auto id : r.targets.instance_id) covered += id >= 0;
    EXPECT_EQ(covered, 100 * 100);
}

TEST(Shading, MipmappingAveragesTheDistantCheckerboard) {
    // Far rows of the default scene's ground: trilinear filtering averages the checkerboard
    // towards its mean, nearest sampling aliases (high variance between neighbouring pixels).
    RenderOptions o;
    o.width = 480;
    o.height = 270;
    o.camera = builtin_camera("builtin:default");
    const Scene scene = make_procedural_scene("builtin:default");
    auto roughness = [&](TextureFilter filter) {
        o.texture_filter = filter;
        const auto r = render(scene, o);
        // Mean absolute difference between horizontal neighbours over a band of rows just below
        // the horizon, where the ground is far away.
        double sum = 0;
        int n = 0;
        for (int y = 0; y < o.height; ++y) {
            const float d = r.targets.depth[std::size_t(y * o.width + o.width / 2)];
            if (!(d > 0.995f && d < 1.0f)) continue;
            for (int x = 0; x + 1 < o.width; ++x) {
                sum += std::abs(int(r.targets.color[std::size_t(y * o.width + x) * 4]) -
                                int(r.targets.color[std::size_t(y * o.width + x + 1) * 4]));
                ++n;
            }
        }
        return n ? sum / n : -1.0;
    };
    const double trilinear = roughness(TextureFilter::Trilinear);
    const double nearest = roughness(TextureFilter::Nearest);
    ASSERT_GE(trilinear, 0.0) << "no distant ground rows found";
    EXPECT_LT(trilinear * 3, nearest);
}

}  // namespace
}  // namespace zraster::test
