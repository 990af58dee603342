// Perspective-correct interpolation: a plane at a grazing angle, its UVs at each covered pixel
// against an analytic ray-plane intersection. Screen-linear interpolation must be visibly wrong.
#include <zraster/camera.hpp>
#include <zraster/raster.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace zraster {
namespace {

struct UvError {
    double max_perspective = 0, max_linear = 0;
    double max_perspective_pixels = 0;  // error over the UV footprint of one pixel
    int pixels = 0;
};

UvError measure() {
    constexpr int W = 320, H = 180;
    Camera camera;
    camera.eye = {0, 0.6, 0};
    camera.target = {0, 0.3, -10};
    camera.near = 0.5;
    camera.far = 200;
    const glm::dmat4 vp = camera.projection_matrix(double(W) / H) * camera.view();
    // Ground plane y = 0 from z = -1 to z = -150, x in [-40, 40]; u = (x + 40) / 80, v = -z / 150.
    const glm::dvec3 p[3] = {{-40, 0, -1}, {40, 0, -1}, {0, 0, -150}};
    const glm::dvec2 uv[3] = {{0, 1.0 / 150}, {1, 1.0 / 150}, {0.5, 1}};
    std::array<glm::vec4, 3> clip;
    for (int i = 0; i < 3; ++i) clip[std::size_t(i)] = glm::vec4(vp * glm::dvec4(p[i], 1.0));
    SetupSettings s;
    s.viewport = {W, H};
    s.cull = CullMode::None;
    TriangleSetup t;
    EXPECT_EQ(setup_triangle(clip, s, t), SetupResult::Visible);
    const glm::dmat4 inverse = glm::inverse(vp);
    UvError e;
    for_each_covered_pixel(t, 0, 0, W, H, [&](int x, int y) {
        // Analytic: intersect the pixel's ray with y = 0.
        const double nx = (x + 0.5) / W * 2 - 1, ny = 1 - (y + 0.5) / H * 2;
        glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1, 1), b = inverse * glm::dvec4(nx, ny, 1, 1);
        a /= a.w;
        b /= b.w;
        const double s_hit = a.y / (a.y - b.y);
        const glm::dvec3 hit = glm::dvec3(a) + s_hit * (glm::dvec3(b) - glm::dvec3(a));
        const glm::dvec2 expected((hit.x + 40) / 80, -hit.z / 150);
        auto uv_of = [&](glm::vec3 beta) {
            return uv[0] * double(beta.x) + uv[1] * double(beta.y) + uv[2] * double(beta.z);
        };
        const glm::dvec2 pc = uv_of(barycentrics(t, x, y, Interpolation::PerspectiveCorrect));
        const glm::dvec2 sl = uv_of(barycentrics(t, x, y, Interpolation::ScreenLinear));
        e.max_perspective = std::max(e.max_perspective, glm::length(pc - expected));
        const glm::dvec2 next = uv_of(barycentrics(t, x, y + 1, Interpolation::PerspectiveCorrect));
        e.max_perspective_pixels =
            std::max(e.max_perspective_pixels, glm::length(pc - expected) / glm::length(next - pc));
        e.max_linear = std::max(e.max_linear, glm::length(sl - expected));
        ++e.pixels;
    });
    return e;
}

TEST(PerspectiveCorrect, GrazingPlaneUvsMatchRayPlaneIntersection) {
    const UvError e = measure();
    EXPECT_GT(e.pixels, 10000);
    // Tolerance: 1% of the UV step between vertically adjacent pixels (the float plane
    // equations lose a few bits near the horizon, where one pixel spans a long stretch of
    // ground), and 1e-3 in absolute UV.
    EXPECT_LT(e.max_perspective_pixels, 0.01);
    EXPECT_LT(e.max_perspective, 1e-3);
    // Affine interpolation is wrong by a large fraction of the texture.
    EXPECT_GT(e.max_linear, 0.05);
}

}  // namespace
}  // namespace zraster
