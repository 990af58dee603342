// Cameras from matrices and from pinhole intrinsics: the projection puts points where the stated
// pixel conventions say, intrinsics() and camera_to_world() invert from_intrinsics(),
// linear_depth() inverts every depth mode, and bad input is refused with a message naming it.
#include <zraster/camera.hpp>
#include <zraster/error.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>

namespace zraster {
namespace {

// A rotation about a skew axis and a translation: a pose with nothing axis-aligned.
glm::dmat4 skew_pose() {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -1.0, 0.4));
    const double angle = 0.7, c = std::cos(angle), s = std::sin(angle);
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 e(0.0);
        e[i] = 1.0;
        // Rodrigues' formula applied to the basis vector: column i of the rotation.
        const glm::dvec3 r = e * c + glm::cross(axis, e) * s + axis * glm::dot(axis, e) * (1 - c);
        m[i] = glm::dvec4(r, 0.0);
    }
    m[3] = glm::dvec4(1.5, -2.0, 3.25, 1.0);
    return m;
}

// Window position (x right, y down, pixel centers at +0.5) and depth of a world point, in double.
glm::dvec3 window_of(const Camera& camera, const glm::dvec3& world, int width, int height) {
    const glm::dvec4 clip = camera.projection_matrix(double(width) / double(height)) *
                            camera.view() * glm::dvec4(world, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    const double depth =
        camera.clip_depth_range() == ClipDepthRange::NegativeOneToOne ? 0.5 * ndc.z + 0.5 : ndc.z;
    return {(ndc.x + 1.0) / 2.0 * width, (1.0 - ndc.y) / 2.0 * height, depth};
}

void expect_message(const std::function<void()>& f, const std::string& message) {
    try {
        f();
        ADD_FAILURE() << "no InputError, expected: " << message;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), message);
    }
}

constexpr Intrinsics kIntrinsics{.fx = 500.0,
                                 .fy = 420.0,
                                 .cx = 301.25,
                                 .cy = 260.5,
                                 .width = 640,
                                 .height = 480,
                                 .near = 0.25,
                                 .far = 40.0};

TEST(CameraIntrinsics, OpenCvPointsLandOnTheStatedPixels) {
    const glm::dmat4 pose = skew_pose();
    const Camera camera = Camera::from_intrinsics(kIntrinsics, pose, CameraConvention::OpenCV);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> xy(-2.0, 2.0), z(0.5, 30.0);
    for (int trial = 0; trial < 100; ++trial) {
        const glm::dvec3 p(xy(rng), xy(rng), z(rng));  // x right, y down, z forward
        const glm::dvec3 w = window_of(camera, glm::dvec3(pose * glm::dvec4(p, 1.0)), 640, 480);
        const double u = kIntrinsics.fx * p.x / p.z + kIntrinsics.cx;
        const double v = kIntrinsics.fy * p.y / p.z + kIntrinsics.cy;
        EXPECT_NEAR(w.x, u + 0.5, 1e-9);
        EXPECT_NEAR(w.y, v + 0.5, 1e-9);
        EXPECT_NEAR(linear_depth(camera, w.z), p.z, 1e-9 * p.z);
    }
}

TEST(CameraIntrinsics, OpenGlPointsLandOnTheStatedPixels) {
    const glm::dmat4 pose = skew_pose();
    const Camera camera = Camera::from_intrinsics(kIntrinsics, pose, CameraConvention::OpenGL);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> xy(-2.0, 2.0), z(0.5, 30.0);
    for (int trial = 0; trial < 100; ++trial) {
        const glm::dvec3 p(xy(rng), xy(rng), -z(rng));  // x right, y up, looking down -z
        const glm::dvec3 w = window_of(camera, glm::dvec3(pose * glm::dvec4(p, 1.0)), 640, 480);
        const double x = kIntrinsics.fx * p.x / -p.z + kIntrinsics.cx;
        const double y_up = kIntrinsics.fy * p.y / -p.z + kIntrinsics.cy;
        EXPECT_NEAR(w.x, x, 1e-9);
        EXPECT_NEAR(480.0 - w.y, y_up, 1e-9);
        EXPECT_NEAR(linear_depth(camera, w.z), -p.z, 1e-9 * -p.z);
    }
}

TEST(CameraIntrinsics, PoseGivesPositionAndViewDirection) {
    const glm::dmat4 pose = skew_pose();
    const Camera cv = Camera::from_intrinsics(kIntrinsics, pose, CameraConvention::OpenCV);
    const Camera gl = Camera::from_intrinsics(kIntrinsics, pose, CameraConvention::OpenGL);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(cv.position()[k], pose[3][k], 1e-12);
        EXPECT_NEAR(gl.position()[k], pose[3][k], 1e-12);
        EXPECT_NEAR(cv.view_direction()[k], pose[2][k], 1e-12);   // OpenCV looks down +z
        EXPECT_NEAR(gl.view_direction()[k], -pose[2][k], 1e-12);  // OpenGL down -z
        EXPECT_NEAR(cv.eye[k], pose[3][k], 1e-12);
        EXPECT_NEAR(cv.target[k], pose[3][k] + pose[2][k], 1e-12);
        EXPECT_NEAR(cv.up[k], -pose[1][k], 1e-12);  // OpenCV's y is down
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_NEAR(cv.camera_to_world(CameraConvention::OpenCV)[c][r], pose[c][r], 1e-12);
            EXPECT_NEAR(gl.camera_to_world(CameraConvention::OpenGL)[c][r], pose[c][r], 1e-12);
        }
    EXPECT_FALSE(cv.is_orthographic());
}

TEST(CameraIntrinsics, IntrinsicsReturnsWhatWasGivenInEitherConvention) {
    const Camera cv = Camera::from_intrinsics(kIntrinsics, skew_pose(), CameraConvention::OpenCV);
    const Intrinsics same = cv.intrinsics(640, 480);
    EXPECT_EQ(same.fx, kIntrinsics.fx);
    EXPECT_EQ(same.fy, kIntrinsics.fy);
    EXPECT_EQ(same.cx, kIntrinsics.cx);
    EXPECT_EQ(same.cy, kIntrinsics.cy);
    EXPECT_EQ(same.near, kIntrinsics.near);
    EXPECT_EQ(same.far, kIntrinsics.far);
    // OpenGL's principal point for the same pixels: half a pixel right, and measured from the
    // bottom edge.
    const Intrinsics gl = cv.intrinsics(640, 480, CameraConvention::OpenGL);
    EXPECT_NEAR(gl.fx, kIntrinsics.fx, 1e-9);
    EXPECT_NEAR(gl.fy, kIntrinsics.fy, 1e-9);
    EXPECT_NEAR(gl.cx, kIntrinsics.cx + 0.5, 1e-9);
    EXPECT_NEAR(gl.cy, 480.0 - (kIntrinsics.cy + 0.5), 1e-9);
    // The same lens at half the resolution: everything in pixels halves (about pixel edges).
    const Intrinsics half = cv.intrinsics(320, 240);
    EXPECT_NEAR(half.fx, kIntrinsics.fx / 2, 1e-9);
    EXPECT_NEAR(half.fy, kIntrinsics.fy / 2, 1e-9);
    EXPECT_NEAR(half.cx + 0.5, (kIntrinsics.cx + 0.5) / 2, 1e-9);
    EXPECT_NEAR(half.cy + 0.5, (kIntrinsics.cy + 0.5) / 2, 1e-9);
}

TEST(CameraIntrinsics, FovyCameraIntrinsicsAreTheCenteredPinholeAndRoundTrip) {
    Camera camera = orbit_camera({0.5, -1.0, 2.0}, 6.0, 35.0, 20.0, 50.0);
    camera.near = 0.5;
    camera.far = 20.0;
    const int width = 400, height = 300;
    const Intrinsics k = camera.intrinsics(width, height);
    const double f = height / 2.0 / std::tan(25.0 * std::numbers::pi / 180.0);
    EXPECT_NEAR(k.fx, f, 1e-9);
    EXPECT_NEAR(k.fy, f, 1e-9);
    EXPECT_NEAR(k.cx, width / 2.0 - 0.5, 1e-9);
    EXPECT_NEAR(k.cy, height / 2.0 - 0.5, 1e-9);
    EXPECT_EQ(k.near, 0.5);
    EXPECT_EQ(k.far, 20.0);
    const Intrinsics k_gl = camera.intrinsics(width, height, CameraConvention::OpenGL);
    EXPECT_NEAR(k_gl.cx, width / 2.0, 1e-9);
    EXPECT_NEAR(k_gl.cy, height / 2.0, 1e-9);
    for (CameraConvention convention : {CameraConvention::OpenCV, CameraConvention::OpenGL}) {
        const Camera back = Camera::from_intrinsics(camera.intrinsics(width, height, convention),
                                                    camera.camera_to_world(convention), convention);
        const glm::dmat4 a = camera.projection_matrix(double(width) / height) * camera.view();
        const glm::dmat4 b = back.projection_matrix(double(width) / height) * back.view();
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-12);
    }
    // Infinite far: far comes back as infinity, and from_intrinsics takes it so.
    camera.infinite_far = true;
    const Intrinsics infinite = camera.intrinsics(width, height);
    EXPECT_TRUE(std::isinf(infinite.far));
    const Camera back = Camera::from_intrinsics(infinite, camera.camera_to_world());
    EXPECT_TRUE(back.infinite_far);
    const glm::dmat4 p = back.projection_matrix(1.0);
    EXPECT_EQ(p[2][2], -1.0);
    EXPECT_EQ(p[3][2], -2.0 * 0.5);
}

TEST(CameraIntrinsics, LinearDepthInvertsEveryDepthMode) {
    Camera fovy = orbit_camera({0.0, 0.0, 0.0}, 5.0, 10.0, 30.0, 60.0);
    fovy.near = 0.3;
    fovy.far = 50.0;
    Camera ortho = fovy;
    ortho.projection = Camera::Projection::Orthographic;
    const Camera pinhole = Camera::from_intrinsics(Intrinsics{.fx = 300,
                                                              .fy = 310,
                                                              .cx = 100,
                                                              .cy = 80,
                                                              .width = 200,
                                                              .height = 150,
                                                              .near = 0.3,
                                                              .far = 50.0},
                                                   skew_pose());
    for (const Camera& base : {fovy, ortho, pinhole})
        for (int mode = 0; mode < 4; ++mode) {
            Camera camera = base;
            camera.reversed_z = (mode & 1) != 0;
            camera.infinite_far = (mode & 2) != 0;  // ignored by the orthographic camera
            const bool infinite = camera.infinite_far && !camera.is_orthographic();
            for (double distance : {0.3, 0.7, 2.0, 9.5, 31.0, 50.0}) {
                const glm::dvec3 world = camera.position() + distance * camera.view_direction();
                const double depth = window_of(camera, world, 200, 150).z;
                EXPECT_NEAR(linear_depth(camera, depth), distance, 1e-9 * distance)
                    << "mode " << mode << " distance " << distance;
            }
            EXPECT_NEAR(linear_depth(camera, camera.reversed_z ? 1.0 : 0.0), 0.3, 1e-12);
            const double far_depth = linear_depth(camera, camera.reversed_z ? 0.0 : 1.0);
            if (infinite)
                EXPECT_EQ(far_depth, std::numeric_limits<double>::infinity());
            else
                EXPECT_NEAR(far_depth, 50.0, 1e-9);
        }
    // A Direct3D-style projection: clip z in [0, w], near -> 0.
    glm::dmat4 d3d = perspective(1.0, 1.5, 0.3, 50.0);
    d3d[2][2] = 50.0 / (0.3 - 50.0);
    d3d[3][2] = 50.0 * 0.3 / (0.3 - 50.0);
    const Camera camera = Camera::from_matrices(look_at({1, 2, 3}, {0, 0, 0}, {0, 1, 0}), d3d,
                                                ClipDepthRange::ZeroToOne);
    for (double distance : {0.3, 1.0, 7.0, 50.0}) {
        const glm::dvec3 world = camera.position() + distance * camera.view_direction();
        const double depth = window_of(camera, world, 300, 200).z;
        EXPECT_NEAR(linear_depth(camera, depth), distance, 1e-9 * distance);
    }
    EXPECT_NEAR(camera.near, 0.3, 1e-12);
    EXPECT_NEAR(camera.far, 50.0, 1e-9);
}

TEST(CameraMatrices, ReturnsTheGivenMatricesAndTheViewerFromTheInverseView) {
    Camera look = orbit_camera({1.0, 0.5, -2.0}, 7.0, -40.0, 25.0, 45.0);
    look.near = 1.0;
    look.far = 30.0;
    const glm::dmat4 v = look.view(), p = look.projection_matrix(1.25);
    const Camera m = Camera::from_matrices(v, p, look.clip_depth_range());
    EXPECT_EQ(m.view(), v);
    EXPECT_EQ(m.projection_matrix(0.3), p);  // aspect ignored
    EXPECT_EQ(m.view_projection(7.0), look.view_projection(1.25));
    EXPECT_EQ(m.clip_depth_range(), ClipDepthRange::NegativeOneToOne);
    EXPECT_FALSE(m.reversed_z);
    EXPECT_FALSE(m.is_orthographic());
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(m.position()[k], look.eye[k], 1e-12);
        EXPECT_NEAR(m.view_direction()[k], look.view_direction()[k], 1e-12);
    }
    // up for reading: the camera's orthonormal up, in the plane of look.up and the view direction.
    EXPECT_NEAR(glm::dot(m.up, m.view_direction()), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(m.up, glm::normalize(look.up - glm::dot(look.up, m.view_direction()) *
                                                            m.view_direction())),
                1.0, 1e-12);
    EXPECT_NEAR(m.fovy_degrees, 45.0, 1e-12);
    EXPECT_NEAR(m.near, 1.0, 1e-12);
    EXPECT_NEAR(m.far, 30.0, 1e-9);

    Camera ortho = look;
    ortho.projection = Camera::Projection::Orthographic;
    ortho.ortho_height = 3.0;
    ortho.reversed_z = true;
    const Camera mo = Camera::from_matrices(ortho.view(), ortho.projection_matrix(1.0),
                                            ortho.clip_depth_range(), true);
    EXPECT_TRUE(mo.is_orthographic());
    EXPECT_EQ(mo.projection, Camera::Projection::Orthographic);
    EXPECT_EQ(mo.clip_depth_range(), ClipDepthRange::ZeroToOne);
    EXPECT_NEAR(mo.ortho_height, 3.0, 1e-12);
    EXPECT_NEAR(mo.near, 1.0, 1e-12);
    EXPECT_NEAR(mo.far, 30.0, 1e-9);
    EXPECT_THROW(mo.intrinsics(100, 100), InputError);
}

TEST(CameraMatrices, BadMatricesAreRefusedWithTheirName) {
    const glm::dmat4 view = look_at({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
    const glm::dmat4 proj = perspective(1.0, 1.0, 0.1, 10.0);
    const auto with = [](glm::dmat4 m, int c, int r, double value) {
        m[c][r] = value;
        return m;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto matrices = [](const glm::dmat4& v, const glm::dmat4& p) {
        return [v, p] { Camera::from_matrices(v, p, ClipDepthRange::NegativeOneToOne); };
    };
    expect_message(matrices(with(view, 1, 2, nan), proj),
                   "camera view matrix has a non-finite element");
    expect_message(matrices(with(view, 2, 3, 0.5), proj),
                   "camera view matrix is not affine (its last row must be 0, 0, 0, 1)");
    expect_message(matrices(with(with(view, 0, 0, 0.0), 0, 2, 0.0), proj),
                   "camera view matrix is singular");
    expect_message(matrices(view, with(proj, 3, 2, inf)),
                   "camera projection matrix has a non-finite element");
    expect_message(matrices(view, with(proj, 0, 0, 0.0)), "camera projection matrix is singular");
    expect_message(matrices(view, with(proj, 0, 3, 0.1)),
                   "camera projection matrix: the last row must be (0, 0, -c, 0) (perspective) "
                   "or (0, 0, 0, c) (orthographic) with c > 0");
    expect_message(matrices(view, with(proj, 3, 0, 0.1)),
                   "camera projection matrix: a perspective projection's x and y rows need a "
                   "zero constant term (the center of projection is the eye)");
    expect_message(matrices(view, with(orthographic(-1, 1, -1, 1, 0.1, 10), 2, 1, 0.2)),
                   "camera projection matrix: an orthographic projection's x and y rows need a "
                   "zero z term (the direction of projection is -z)");
    // An off-center frustum and an off-center box are fine.
    EXPECT_NO_THROW(matrices(view, with(proj, 2, 0, 0.3))());
    EXPECT_NO_THROW(matrices(view, orthographic(-1, 3, -2, 1, 0.1, 10))());
    // A camera changed after construction is checked when it renders.
    Camera camera = Camera::from_matrices(view, proj, ClipDepthRange::NegativeOneToOne);
    camera.given_projection->matrix[1][1] = 0.0;
    expect_message([&] { check_camera(camera, 64, 64); }, "camera projection matrix is singular");
    // linear_depth needs depth to depend on eye z alone (an oblique near plane does not).
    const Camera oblique =
        Camera::from_matrices(view, with(proj, 0, 2, 0.2), ClipDepthRange::NegativeOneToOne);
    expect_message([&] { linear_depth(oblique, 0.5); },
                   "linear_depth needs a projection whose depth depends on eye z only");
}

TEST(CameraIntrinsics, BadIntrinsicsAndPosesAreRefusedWithTheField) {
    const glm::dmat4 pose(1.0);
    const auto intrinsics = [&pose](Intrinsics k) {
        return [k, &pose] { Camera::from_intrinsics(k, pose); };
    };
    Intrinsics k = kIntrinsics;
    k.fx = 0.0;
    expect_message(intrinsics(k), "camera intrinsics fx must be finite and > 0, not 0");
    k = kIntrinsics;
    k.fy = -3.0;
    expect_message(intrinsics(k), "camera intrinsics fy must be finite and > 0, not -3");
    k.fy = std::numeric_limits<double>::quiet_NaN();
    expect_message(intrinsics(k), "camera intrinsics fy must be finite and > 0, not nan");
    k = kIntrinsics;
    k.cx = std::numeric_limits<double>::infinity();
    expect_message(intrinsics(k), "camera intrinsics cx must be finite");
    k = kIntrinsics;
    k.cy = -std::numeric_limits<double>::infinity();
    expect_message(intrinsics(k), "camera intrinsics cy must be finite");
    k = kIntrinsics;
    k.width = 0;
    expect_message(intrinsics(k), "camera intrinsics width and height must be >= 1, not 0x480");
    k = kIntrinsics;
    k.height = -2;
    expect_message(intrinsics(k), "camera intrinsics width and height must be >= 1, not 640x-2");
    k = kIntrinsics;
    k.near = 0.0;
    expect_message(intrinsics(k), "camera intrinsics need 0 < near < far, not near 0, far 40");
    k = kIntrinsics;
    k.far = 0.25;
    expect_message(intrinsics(k), "camera intrinsics need 0 < near < far, not near 0.25, far 0.25");
    k.far = std::numeric_limits<double>::quiet_NaN();
    expect_message(intrinsics(k), "camera intrinsics need 0 < near < far, not near 0.25, far nan");

    const auto posed = [](glm::dmat4 m) {
        return [m] { Camera::from_intrinsics(kIntrinsics, m); };
    };
    glm::dmat4 bad(1.0);
    bad[3][0] = std::numeric_limits<double>::quiet_NaN();
    expect_message(posed(bad), "camera_to_world has a non-finite element");
    bad = glm::dmat4(1.0);
    bad[0][3] = 1.0;
    expect_message(posed(bad), "camera_to_world is not affine (its last row must be 0, 0, 0, 1)");
    bad = glm::dmat4(1.0);
    bad[2] = bad[0];
    expect_message(posed(bad), "camera_to_world is singular");

    const Camera camera = Camera::from_intrinsics(kIntrinsics, pose);
    expect_message([&] { check_camera(camera, 320, 240); },
                   "camera intrinsics are for 640x480 but the image is 320x240");
    EXPECT_NO_THROW(check_camera(camera, 640, 480));
    expect_message([&] { camera.intrinsics(0, 10); },
                   "intrinsics need an image size of at least 1x1, not 0x10");
}

}  // namespace
}  // namespace zraster
