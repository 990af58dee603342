#include <zraster/camera.hpp>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <utility>

namespace zraster {
namespace {

constexpr double kFovy = 60.0 * std::numbers::pi / 180.0;

// Clip-space image of the eye-space point (x, y, z).
glm::dvec4 clip(const glm::dmat4& p, double x, double y, double z) {
    return p * glm::dvec4(x, y, z, 1.0);
}

double ndc_z(const glm::dmat4& p, double z_eye) {
    const glm::dvec4 c = clip(p, 0.0, 0.0, z_eye);
    return c.z / c.w;
}

void expect_matrix_near(const glm::dmat4& a, const glm::dmat4& b, double tolerance) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(a[c][r], b[c][r], tolerance) << "[" << c << "][" << r << "]";
}

TEST(Perspective, NearMapsToMinusOneAndFarToPlusOne) {
    const std::pair<double, double> planes[] = {{0.1, 100.0}, {1.0, 2.0}, {0.01, 1e5}, {3.5, 7.25}};
    for (const auto& [n, f] : planes) {
        const glm::dmat4 p = perspective(kFovy, 1.5, n, f);
        EXPECT_NEAR(ndc_z(p, -n), -1.0, 1e-12);
        EXPECT_NEAR(ndc_z(p, -f), 1.0, 1e-12);
        // Depth increases monotonically with distance between the planes.
        EXPECT_LT(ndc_z(p, -n), ndc_z(p, -(n + f) / 2.0));
        EXPECT_LT(ndc_z(p, -(n + f) / 2.0), ndc_z(p, -f));
        // w_clip is the distance in front of the eye.
        EXPECT_DOUBLE_EQ(clip(p, 0.0, 0.0, -f).w, f);
    }
}

TEST(Perspective, FieldOfViewEdgesMapToPlusMinusOne) {
    const double aspect = 16.0 / 9.0, z = -7.0;
    const glm::dmat4 p = perspective(kFovy, aspect, 0.5, 50.0);
    const double half_height = -z * std::tan(kFovy / 2.0), half_width = half_height * aspect;
    const glm::dvec4 top_right = clip(p, half_width, half_height, z);
    EXPECT_NEAR(top_right.x / top_right.w, 1.0, 1e-12);
    EXPECT_NEAR(top_right.y / top_right.w, 1.0, 1e-12);
    const glm::dvec4 bottom_left = clip(p, -half_width, -half_height, z);
    EXPECT_NEAR(bottom_left.x / bottom_left.w, -1.0, 1e-12);
    EXPECT_NEAR(bottom_left.y / bottom_left.w, -1.0, 1e-12);
}

TEST(Perspective, AgreesWithGlm) {
    expect_matrix_near(perspective(kFovy, 1.25, 0.3, 40.0),
                       glm::perspective(kFovy, 1.25, 0.3, 40.0), 1e-12);
    expect_matrix_near(perspective_infinite(kFovy, 1.25, 0.3),
                       glm::infinitePerspective(kFovy, 1.25, 0.3), 1e-12);
}

TEST(Perspective, ReversedZMapsNearToOneAndFarToZero) {
    const std::pair<double, double> planes[] = {{0.1, 100.0}, {1.0, 2.0}, {0.01, 1e5}};
    for (const auto& [n, f] : planes) {
        const glm::dmat4 p = perspective_reversed_z(kFovy, 1.0, n, f);
        EXPECT_NEAR(ndc_z(p, -n), 1.0, 1e-12);
        EXPECT_NEAR(ndc_z(p, -f), 0.0, 1e-12);
        // Every point between the planes has 0 <= z_clip <= w_clip, decreasing with distance.
        double previous = 2.0;
        for (int i = 0; i <= 64; ++i) {
            const double z = -(n + (f - n) * i / 64.0);
            const glm::dvec4 c = clip(p, 0.0, 0.0, z);
            EXPECT_GE(c.z, -1e-12 * c.w);
            EXPECT_LE(c.z, c.w * (1.0 + 1e-12));
            EXPECT_LT(c.z / c.w, previous);
            previous = c.z / c.w;
        }
    }
}

TEST(Perspective, InfiniteFarIsTheLimitOfAHugeFar) {
    const double n = 0.25, huge = 1e12;
    expect_matrix_near(perspective_infinite(kFovy, 1.5, n), perspective(kFovy, 1.5, n, huge), 1e-9);
    expect_matrix_near(perspective_reversed_z_infinite(kFovy, 1.5, n),
                       perspective_reversed_z(kFovy, 1.5, n, huge), 1e-9);
    // Near still maps to the near end of the depth range; infinity to the far end.
    EXPECT_NEAR(ndc_z(perspective_infinite(kFovy, 1.5, n), -n), -1.0, 1e-12);
    EXPECT_NEAR(ndc_z(perspective_infinite(kFovy, 1.5, n), -1e300), 1.0, 1e-12);
    EXPECT_NEAR(ndc_z(perspective_reversed_z_infinite(kFovy, 1.5, n), -n), 1.0, 1e-12);
    EXPECT_NEAR(ndc_z(perspective_reversed_z_infinite(kFovy, 1.5, n), -1e300), 0.0, 1e-12);
}

TEST(Perspective, ReversedZInfiniteDepthIsNearOverDistance) {
    const double n = 0.5;
    const glm::dmat4 p = perspective_reversed_z_infinite(kFovy, 1.0, n);
    for (double d : {0.5, 1.0, 3.0, 1000.0, 1e9}) EXPECT_DOUBLE_EQ(ndc_z(p, -d), n / d);
}

TEST(Orthographic, BoxCornersMapToPlusMinusOne) {
    const double l = -3.0, r = 5.0, b = -1.0, t = 2.0, n = 0.5, f = 20.0;
    const glm::dmat4 p = orthographic(l, r, b, t, n, f);
    const glm::dmat4 p_reversed = orthographic_reversed_z(l, r, b, t, n, f);
    for (int corner = 0; corner < 8; ++corner) {
        const double x = (corner & 1) ? r : l, y = (corner & 2) ? t : b, z = (corner & 4) ? -f : -n;
        const glm::dvec4 c = clip(p, x, y, z);
        EXPECT_DOUBLE_EQ(c.w, 1.0);
        EXPECT_NEAR(c.x, (corner & 1) ? 1.0 : -1.0, 1e-12);
        EXPECT_NEAR(c.y, (corner & 2) ? 1.0 : -1.0, 1e-12);
        EXPECT_NEAR(c.z, (corner & 4) ? 1.0 : -1.0, 1e-12);  // near -> -1, far -> 1
        const glm::dvec4 cr = clip(p_reversed, x, y, z);
        EXPECT_NEAR(cr.x, c.x, 1e-12);
        EXPECT_NEAR(cr.y, c.y, 1e-12);
        EXPECT_NEAR(cr.z, (corner & 4) ? 0.0 : 1.0, 1e-12);  // near -> 1, far -> 0
    }
    expect_matrix_near(p, glm::ortho(l, r, b, t, n, f), 1e-12);
}

TEST(Camera, ProjectionMatrixFollowsTheFlags) {
    Camera cam;
    cam.near = 0.5;
    cam.far = 30.0;
    const double aspect = 4.0 / 3.0, fovy = cam.fovy_degrees * std::numbers::pi / 180.0;
    expect_matrix_near(cam.projection_matrix(aspect), perspective(fovy, aspect, 0.5, 30.0), 0.0);
    EXPECT_EQ(cam.clip_depth_range(), ClipDepthRange::NegativeOneToOne);
    cam.infinite_far = true;
    expect_matrix_near(cam.projection_matrix(aspect), perspective_infinite(fovy, aspect, 0.5), 0.0);
    cam.reversed_z = true;
    EXPECT_EQ(cam.clip_depth_range(), ClipDepthRange::ZeroToOne);
    expect_matrix_near(cam.projection_matrix(aspect),
                       perspective_reversed_z_infinite(fovy, aspect, 0.5), 0.0);
    cam.infinite_far = false;
    expect_matrix_near(cam.projection_matrix(aspect),
                       perspective_reversed_z(fovy, aspect, 0.5, 30.0), 0.0);
    cam.projection = Camera::Projection::Orthographic;
    cam.ortho_height = 4.0;
    expect_matrix_near(cam.projection_matrix(aspect),
                       orthographic_reversed_z(-2.0 * aspect, 2.0 * aspect, -2.0, 2.0, 0.5, 30.0),
                       0.0);
    cam.reversed_z = false;
    expect_matrix_near(cam.projection_matrix(aspect),
                       orthographic(-2.0 * aspect, 2.0 * aspect, -2.0, 2.0, 0.5, 30.0), 0.0);
}

}  // namespace
}  // namespace zraster
