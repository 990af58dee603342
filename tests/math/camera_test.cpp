#include <zraster/camera.hpp>
#include <zraster/error.hpp>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace zraster {
namespace {

TEST(LookAt, EqualsGlmLookAtForRandomInputs) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> d(-10.0, 10.0);
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec3 eye(d(rng), d(rng), d(rng)), target(d(rng), d(rng), d(rng));
        const glm::dvec3 up = glm::normalize(glm::dvec3(d(rng), d(rng), d(rng)));
        if (glm::length(glm::cross(target - eye, up)) < 1e-3 * glm::length(target - eye)) continue;
        const glm::dmat4 ours = look_at(eye, target, up), theirs = glm::lookAt(eye, target, up);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(ours[c][r], theirs[c][r], 1e-12);
    }
}

TEST(LookAt, MapsEyeToOriginAndTargetDownMinusZ) {
    const glm::dvec3 eye(1.0, 2.0, 3.0), target(-4.0, 0.5, 1.0), up(0.0, 1.0, 0.0);
    const glm::dmat4 v = look_at(eye, target, up);
    const glm::dvec4 e = v * glm::dvec4(eye, 1.0), t = v * glm::dvec4(target, 1.0);
    EXPECT_NEAR(glm::length(glm::dvec3(e)), 0.0, 1e-12);
    EXPECT_NEAR(t.x, 0.0, 1e-12);
    EXPECT_NEAR(t.y, 0.0, 1e-12);
    EXPECT_NEAR(t.z, -glm::length(target - eye), 1e-12);
    // A point above the eye (along up) is above the view axis: positive y in eye space.
    EXPECT_GT((v * glm::dvec4(eye + up, 1.0)).y, 0.0);
}

TEST(FitCamera, BoxCornersGiveTheFormulasCenterRadiusAndEye) {
    const glm::vec3 lo(-1.0f, 2.0f, -3.0f), hi(3.0f, 4.0f, 5.0f);
    std::vector<glm::vec3> corners;
    for (int k = 0; k < 8; ++k)
        corners.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
    const Camera cam = fit_camera(corners);
    const glm::dvec3 center(1.0, 3.0, 1.0);
    const double radius = std::sqrt(2.0 * 2.0 + 1.0 * 1.0 + 4.0 * 4.0);      // half the diagonal
    const double dist = radius / std::sin(30.0 * std::numbers::pi / 180.0);  // = 2 r
    EXPECT_NEAR(dist, 2.0 * radius, 1e-12);
    const glm::dvec3 eye = center + dist * glm::dvec3(1.0, 1.0, 2.0) / std::sqrt(6.0);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(cam.target[k], center[k], 1e-12);
        EXPECT_NEAR(cam.eye[k], eye[k], 1e-12);
    }
    EXPECT_EQ(cam.up, glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(cam.fovy_degrees, 60.0);
    EXPECT_NEAR(cam.near, dist - 1.01 * radius, 1e-12);
    EXPECT_NEAR(cam.far, dist + 1.01 * radius, 1e-12);
    // Every corner is inside the view volume, strictly between near and far.
    const glm::mat4 vp = cam.view_projection(1.0);
    for (const glm::vec3& p : corners) {
        const glm::vec4 c = vp * glm::vec4(p, 1.0f);
        for (int k = 0; k < 3; ++k) {
            EXPECT_LT(std::abs(c[k]), c.w) << k;
        }
    }
}

TEST(FitCamera, EmptyOrSinglePointGetsRadiusOne) {
    const Camera empty = fit_camera({});
    EXPECT_NEAR(glm::length(empty.eye - empty.target), 2.0, 1e-12);
    EXPECT_NEAR(empty.near, 2.0 - 1.01, 1e-12);
    const std::vector<glm::vec3> one = {{5.0f, -1.0f, 2.0f}};
    const Camera single = fit_camera(one);
    EXPECT_EQ(single.target, glm::dvec3(5.0, -1.0, 2.0));
    EXPECT_NEAR(single.far, 2.0 + 1.01, 1e-12);
}

// Coordinates past kMaxCoordinate cannot be framed in single precision: refused, not an empty
// image; up to it the fitted camera's matrices stay finite. Non-finite points are not its
// business (the renderer drops their triangles).
TEST(FitCamera, CoordinatesBeyondTheSupportedRangeAreRefused) {
    const std::vector<glm::vec3> far = {{3e38f, 0, 0}, {0, 3e38f, 0}, {0, 0, 3e38f}};
    try {
        fit_camera(far);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("coordinates reach 3e+38"), std::string::npos)
            << e.what();
    }
    const std::vector<glm::vec3> edge = {{-9e29f, 0, 0}, {9e29f, 0, 0}, {0, 9e29f, 0}};
    const Camera camera = fit_camera(edge);
    const glm::mat4 vp(camera.view_projection(1.0));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(vp[c][r]));
    Camera beyond = camera;
    beyond.eye.x = 2e32;
    EXPECT_THROW(check_camera(beyond, 64, 64), InputError);
    EXPECT_NO_THROW(check_camera(camera, 64, 64));
}

TEST(FitCamera, OctahedronOfTheUnitSphere) {
    // The poles and +-x, +-z are exact in float, so the radius is exactly 1. The eye matches the
    // sphere:1000000 row of BENCH-SCENES.md; its near/far do not quite (0.990000069 / 3.01000023):
    // those come from that mesh's float vertices, whose farthest is 1 + 4.4e-8 from the center
    // (see BenchFraming.SphereMillion), so here they are one float ulp lower.
    const std::vector<glm::vec3> points = {{0, 1, 0},  {0, -1, 0}, {1, 0, 0},
                                           {-1, 0, 0}, {0, 0, 1},  {0, 0, -1}};
    const Camera cam = fit_camera(points);
    EXPECT_EQ(cam.target, glm::dvec3(0.0));
    EXPECT_EQ(float(cam.eye.x), 0.816496611f);
    EXPECT_EQ(float(cam.eye.y), 0.816496611f);
    EXPECT_EQ(float(cam.eye.z), 1.63299322f);
    EXPECT_EQ(float(cam.near), 0.99000001f);
    EXPECT_EQ(float(cam.far), 3.00999999f);
    EXPECT_EQ(std::nextafter(float(cam.near), 1.0f), 0.990000069f);
    EXPECT_EQ(std::nextafter(float(cam.far), 4.0f), 3.01000023f);
}

TEST(Camera, ViewProjectionRoundsVAndPToFloatThenMultipliesInDouble) {
    Camera cam;
    cam.eye = {1.3, 2.7, 4.1};
    cam.target = {0.2, -0.4, 0.1};
    cam.near = 0.37;
    cam.far = 11.3;
    const double aspect = 1920.0 / 1080.0;
    const glm::dmat4 v(glm::mat4(cam.view())), p(glm::mat4(cam.projection_matrix(aspect)));
    const glm::dmat4 expected = p * v;
    const glm::mat4 vp = cam.view_projection(aspect);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_EQ(vp[c][r], float(expected[c][r]));
    // And it is still P * V: the target lands in the middle of the screen.
    const glm::vec4 t = vp * glm::vec4(glm::vec3(cam.target), 1.0f);
    EXPECT_NEAR(t.x / t.w, 0.0f, 1e-6f);
    EXPECT_NEAR(t.y / t.w, 0.0f, 1e-6f);
}

TEST(OrbitCamera, PlacesTheEyeByAzimuthAndElevation) {
    const glm::dvec3 target(1.0, 2.0, 3.0);
    const Camera front = orbit_camera(target, 4.0, 0.0, 0.0);
    EXPECT_NEAR(glm::length(front.eye - (target + glm::dvec3(0.0, 0.0, 4.0))), 0.0, 1e-12);
    const Camera right = orbit_camera(target, 4.0, 90.0, 0.0);
    EXPECT_NEAR(glm::length(right.eye - (target + glm::dvec3(4.0, 0.0, 0.0))), 0.0, 1e-12);
    const Camera above = orbit_camera(target, 4.0, 30.0, 45.0, 50.0);
    EXPECT_NEAR(glm::length(above.eye - above.target), 4.0, 1e-12);
    EXPECT_NEAR(above.eye.y - target.y, 4.0 * std::sqrt(0.5), 1e-12);
    EXPECT_EQ(above.fovy_degrees, 50.0);
    // Straight down: still a valid (orthonormal, finite) view matrix.
    const Camera top = orbit_camera(target, 4.0, 30.0, 90.0);
    const glm::dmat4 v = top.view();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(v[c][r]));
    EXPECT_NEAR(glm::determinant(glm::dmat3(v)), 1.0, 1e-9);
}

TEST(NormalMatrix, KeepsNormalsPerpendicularUnderNonUniformScale) {
    glm::mat4 model_view = glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    model_view = glm::scale(model_view, glm::vec3(4.0f, 0.5f, 1.0f));
    // A tilted plane: normal n, two tangents perpendicular to it.
    const glm::vec3 n = glm::normalize(glm::vec3(1.0f, 1.0f, 0.5f));
    const glm::vec3 t1 = glm::normalize(glm::cross(n, glm::vec3(0.0f, 0.0f, 1.0f)));
    const glm::vec3 t2 = glm::cross(n, t1);
    const glm::mat3 linear(model_view);
    const glm::vec3 mt1 = glm::normalize(linear * t1), mt2 = glm::normalize(linear * t2);
    const glm::vec3 good = glm::normalize(normal_matrix(model_view) * n);
    EXPECT_NEAR(glm::dot(good, mt1), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(good, mt2), 0.0f, 1e-6f);
    // The plain matrix tilts the normal off the surface.
    const glm::vec3 bad = glm::normalize(linear * n);
    EXPECT_GT(std::max(std::abs(glm::dot(bad, mt1)), std::abs(glm::dot(bad, mt2))), 0.1f);
    // For a pure rotation both agree.
    const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), 1.1f, glm::vec3(0, 1, 0));
    const glm::mat3 nm = normal_matrix(rotation);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(nm[c][r], rotation[c][r], 1e-6f);
}

}  // namespace
}  // namespace zraster
