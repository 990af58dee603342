// Cameras from pinhole intrinsics and from matrices, rendered: each pixel's depth, turned into
// metric depth, is what an independent ray cast through that pixel with the intrinsics finds;
// matrices of a look-at camera render its image bit for bit; the intrinsics of a fovy camera
// render its depth again.
#include <zraster/camera.hpp>
#include <zraster/error.hpp>
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "render/render_test_util.hpp"

namespace zraster::test {
namespace {

glm::dmat4 rotated_translated_pose() {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.5, 1.0, -0.3));
    const double angle = 0.9, c = std::cos(angle), s = std::sin(angle);
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) {
        glm::dvec3 e(0.0);
        e[i] = 1.0;
        m[i] =
            glm::dvec4(e * c + glm::cross(axis, e) * s + axis * glm::dot(axis, e) * (1 - c), 0.0);
    }
    m[3] = glm::dvec4(-2.0, 1.25, 4.0, 1.0);
    return m;
}

// A quad on the tilted plane D = 3 + 0.4 X + 0.3 Y, D being the distance along the view axis
// and (X, Y) the camera's x and y axes (x right; y down in OpenCV, up in OpenGL).
constexpr std::array<glm::dvec2, 4> kQuadXY = {glm::dvec2{-0.9, -0.7}, glm::dvec2{1.2, -0.9},
                                               glm::dvec2{1.0, 0.8}, glm::dvec2{-0.8, 0.6}};

double plane_depth(const glm::dvec2& xy) {
    return 3.0 + 0.4 * xy.x + 0.3 * xy.y;
}

// A camera-space point (X, Y) at distance D along the view axis.
glm::dvec3 camera_point(const glm::dvec2& xy, double depth, CameraConvention convention) {
    return {xy.x, xy.y, convention == CameraConvention::OpenCV ? depth : -depth};
}

Scene quad_scene(const glm::dmat4& pose, CameraConvention convention) {
    std::vector<glm::vec3> corners;
    for (const glm::dvec2& xy : kQuadXY)
        corners.push_back(
            glm::vec3(pose * glm::dvec4(camera_point(xy, plane_depth(xy), convention), 1.0)));
    return scene_from_triangles(
        {{corners[0], corners[1], corners[2], corners[0], corners[2], corners[3]}});
}

// Signed distance of xy inside the convex quad (positive inside), in the plane's units.
double inside_distance(const glm::dvec2& xy) {
    double d = 1e300;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec2 a = kQuadXY[std::size_t(i)], b = kQuadXY[std::size_t((i + 1) % 4)];
        const glm::dvec2 edge = glm::normalize(b - a);
        // The corners go counter-clockwise in (X, Y): inside is to the left of each edge.
        d = std::min(d, edge.x * (xy.y - a.y) - edge.y * (xy.x - a.x));
    }
    return d;
}

struct Cast {
    glm::dvec2 xy;  // where the pixel's ray meets the plane
    double depth;   // and at which distance along the view axis
};

// The ray through the center of pixel (px, py) (row 0 at the top), from the intrinsics alone:
// direction (a, b, 1) per unit of depth, met with the plane D = 3 + 0.4 a D + 0.3 b D.
Cast cast(const Intrinsics& k, CameraConvention convention, int px, int py) {
    double a, b;
    if (convention == CameraConvention::OpenCV) {
        a = (px - k.cx) / k.fx;  // pixel centers at integer (u, v)
        b = (py - k.cy) / k.fy;
    } else {
        a = (px + 0.5 - k.cx) / k.fx;  // half-integers, v from the bottom row
        b = (k.height - (py + 0.5) - k.cy) / k.fy;
    }
    const double depth = 3.0 / (1.0 - 0.4 * a - 0.3 * b);
    return {{a * depth, b * depth}, depth};
}

struct DepthCheck {
    int covered = 0, empty = 0;
};

DepthCheck check_quad_depth(const Camera& camera, const Intrinsics& k, CameraConvention convention,
                            const Scene& scene) {
    RenderOptions o;
    o.width = k.width;
    o.height = k.height;
    o.camera = camera;
    o.cull = CullMode::None;
    o.color_target = false;
    o.threads = 2;
    const RenderResult r = render(scene, o);
    const float clear = camera.reversed_z ? 0.0f : 1.0f;
    DepthCheck out;
    // Half a pixel at the quad's distance is ~0.02 in the plane: 0.005 keeps clear of the edge's
    // snapping and rounding, and a principal point off by half a pixel still moves pixels across.
    constexpr double kMargin = 0.005;
    for (int py = 0; py < k.height; ++py)
        for (int px = 0; px < k.width; ++px) {
            const Cast c = cast(k, convention, px, py);
            const float stored =
                r.targets.depth[std::size_t(py) * std::size_t(k.width) + std::size_t(px)];
            const double inside = inside_distance(c.xy);
            if (inside > kMargin) {
                ++out.covered;
                // dD/d(window depth) = D^2 (f - n) / (f n) ~ 23 here: 2e-5 is about 15 float
                // ulps of window depth (2 seen), where half a pixel of principal point moves
                // the plane's depth by ~7e-3.
                EXPECT_NEAR(linear_depth(camera, stored), c.depth, 2e-5)
                    << "pixel " << px << "," << py;
            } else if (inside < -kMargin) {
                ++out.empty;
                EXPECT_EQ(stored, clear) << "pixel " << px << "," << py;
            }
        }
    return out;
}

TEST(CameraIntrinsicsRender, DepthMatchesARayCastWithTheIntrinsics) {
    const glm::dmat4 pose = rotated_translated_pose();
    // Principal points well off center, fx != fy, a non-square image.
    const Intrinsics opencv{.fx = 80.0,
                            .fy = 66.0,
                            .cx = 40.3,
                            .cy = 35.7,
                            .width = 96,
                            .height = 64,
                            .near = 0.5,
                            .far = 10.0};
    const Intrinsics opengl{.fx = 72.0,
                            .fy = 90.0,
                            .cx = 52.9,
                            .cy = 27.2,
                            .width = 96,
                            .height = 72,
                            .near = 0.5,
                            .far = 10.0};
    for (CameraConvention convention : {CameraConvention::OpenCV, CameraConvention::OpenGL}) {
        const Intrinsics& k = convention == CameraConvention::OpenCV ? opencv : opengl;
        const Scene scene = quad_scene(pose, convention);
        for (int mode = 0; mode < 3; ++mode) {
            SCOPED_TRACE(std::string(convention == CameraConvention::OpenCV ? "OpenCV" : "OpenGL") +
                         " depth mode " + std::to_string(mode));
            Camera camera = Camera::from_intrinsics(k, pose, convention);
            camera.reversed_z = mode >= 1;
            camera.infinite_far = mode == 2;
            const DepthCheck c = check_quad_depth(camera, k, convention, scene);
            // The quad covers part of the image, and the margin leaves most pixels decided.
            EXPECT_GT(c.covered, k.width * k.height / 4);
            EXPECT_GT(c.empty, k.width * k.height / 8);
        }
    }
}

// The same check with the pixel grid shifted by half a pixel: the coverage and depth tests
// above must notice it (else they would not test the principal point).
TEST(CameraIntrinsicsRender, AHalfPixelShiftIsDetected) {
    const glm::dmat4 pose = rotated_translated_pose();
    Intrinsics k{.fx = 80.0,
                 .fy = 66.0,
                 .cx = 40.3,
                 .cy = 35.7,
                 .width = 96,
                 .height = 64,
                 .near = 0.5,
                 .far = 10.0};
    Intrinsics shifted = k;
    shifted.cx += 0.5;
    const Camera camera = Camera::from_intrinsics(shifted, pose);
    RenderOptions o;
    o.width = k.width;
    o.height = k.height;
    o.camera = camera;
    o.cull = CullMode::None;
    o.color_target = false;
    const RenderResult r = render(quad_scene(pose, CameraConvention::OpenCV), o);
    int wrong = 0;
    for (int py = 0; py < k.height; ++py)
        for (int px = 0; px < k.width; ++px) {
            const Cast c = cast(k, CameraConvention::OpenCV, px, py);
            if (inside_distance(c.xy) < 0.005) continue;
            const float stored = r.targets.depth[std::size_t(py * k.width + px)];
            if (stored == 1.0f || std::abs(linear_depth(camera, stored) - c.depth) > 2e-4) ++wrong;
        }
    EXPECT_GT(wrong, 100);
}

RenderResult render_with(const Scene& scene, const Camera& camera, int width, int height) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.camera = camera;
    o.normal_target = true;
    o.threads = 2;
    return render(scene, o);
}

TEST(CameraMatricesRender, LookAtMatricesRenderTheLookAtImageBitForBit) {
    const Scene scene = make_procedural_scene("builtin:default");
    const Camera builtin = *builtin_camera("builtin:default");
    const int width = 160, height = 90;
    const double aspect = double(width) / double(height);
    Camera reversed = builtin;
    reversed.reversed_z = true;
    reversed.infinite_far = true;
    Camera ortho = builtin;
    ortho.projection = Camera::Projection::Orthographic;
    ortho.ortho_height = 6.0;
    for (const Camera& camera : {builtin, reversed, ortho}) {
        const Camera matrices =
            Camera::from_matrices(camera.view(), camera.projection_matrix(aspect),
                                  camera.clip_depth_range(), camera.reversed_z);
        const RenderResult a = render_with(scene, camera, width, height);
        const RenderResult b = render_with(scene, matrices, width, height);
        EXPECT_EQ(a.targets.color, b.targets.color);
        EXPECT_EQ(a.targets.depth, b.targets.depth);
        EXPECT_EQ(a.targets.normal, b.targets.normal);
        EXPECT_EQ(a.stats.triangles_rasterized, b.stats.triangles_rasterized);
    }
}

TEST(CameraIntrinsicsRender, FovyCameraIntrinsicsRenderTheSameDepth) {
    const Scene scene = make_procedural_scene("builtin:default");
    Camera camera = *builtin_camera("builtin:default");
    const int width = 160, height = 120;
    const RenderResult a = render_with(scene, camera, width, height);
    for (CameraConvention convention : {CameraConvention::OpenCV, CameraConvention::OpenGL}) {
        const Camera pinhole =
            Camera::from_intrinsics(camera.intrinsics(width, height, convention),
                                    camera.camera_to_world(convention), convention);
        const RenderResult b = render_with(scene, pinhole, width, height);
        int both = 0, one = 0;
        double max_error = 0.0;
        for (std::size_t i = 0; i < a.targets.depth.size(); ++i) {
            const bool in_a = a.targets.depth[i] < 1.0f, in_b = b.targets.depth[i] < 1.0f;
            if (in_a != in_b) ++one;
            if (!in_a || !in_b) continue;
            ++both;
            max_error =
                std::max(max_error, std::abs(double(a.targets.depth[i]) - b.targets.depth[i]));
        }
        EXPECT_GT(both, width * height / 2);
        // The matrices agree to ~1e-15 and are rounded to float for the vertex transform: at
        // most an edge pixel or two may change hands, and depth differs by a few float ulps.
        EXPECT_LE(one, 4);
        EXPECT_LE(max_error, 4e-7);
        // The metric depth of the center pixel agrees as well.
        const std::size_t center = std::size_t(height / 2 * width + width / 2);
        EXPECT_NEAR(linear_depth(pinhole, b.targets.depth[center]),
                    linear_depth(camera, a.targets.depth[center]), 1e-4);
    }
}

TEST(CameraIntrinsicsRender, RendererRefusesAnotherImageSizeAndBadCameras) {
    const Scene scene = scene_from_triangles({{{-1, -1, -5}, {1, -1, -5}, {0, 1, -5}}});
    RenderOptions o;
    o.width = 320;
    o.height = 240;
    o.camera = Camera::from_intrinsics(Intrinsics{.fx = 500,
                                                  .fy = 500,
                                                  .cx = 319.5,
                                                  .cy = 239.5,
                                                  .width = 640,
                                                  .height = 480,
                                                  .near = 0.1,
                                                  .far = 10},
                                       glm::dmat4(1.0));
    try {
        render(scene, o);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "camera intrinsics are for 640x480 but the image is 320x240");
    }
    o.width = 640;
    o.height = 480;
    EXPECT_NO_THROW(render(scene, o));
    o.camera->pinhole->intrinsics.fx = -1.0;
    try {
        render(scene, o);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "camera intrinsics fx must be finite and > 0, not -1");
    }
    o.camera =
        Camera::from_matrices(look_at({0, 0, 1}, {0, 0, 0}, {0, 1, 0}),
                              perspective(1.0, 1.0, 0.1, 10.0), ClipDepthRange::NegativeOneToOne);
    EXPECT_NO_THROW(render(scene, o));
    (*o.camera->given_view)[3][3] = 2.0;
    try {
        render(scene, o);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "camera view matrix is not affine (its last row must be 0, 0, 0, 1)");
    }
}

}  // namespace
}  // namespace zraster::test
