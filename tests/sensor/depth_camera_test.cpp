// Metric depth, range and point clouds of rendered frames against the geometry that was drawn:
// a plane at a known distance gives back that distance in every depth mode, range is z times
// each pixel's ray length, unprojected points lie on the surface they came from.
#include <zraster/depth_buffer.hpp>
#include <zraster/depth_camera.hpp>
#include <zraster/error.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "sensor/sensor_test_util.hpp"

namespace zraster::test {
namespace {

constexpr int kWidth = 64, kHeight = 48;

struct DepthMode {
    const char* name;
    Camera::Projection projection;
    DepthFormat format;
    bool reversed_z, infinite_far;
};

// The size of one step of the depth format at window depth w (for D32F a float ulp there).
double depth_step(DepthFormat format, float w) {
    switch (format) {
        case DepthFormat::D32F:
            return double(std::nextafter(w, 2.0f)) - double(w);
        case DepthFormat::D24:
            return 1.0 / double((1 << 24) - 1);
        case DepthFormat::D16:
            return 1.0 / 65535.0;
    }
    return 0.0;
}

// A plane perpendicular to the view axis at distance 3 fills the image; metric z is 3 at every
// pixel, to within the rounding of the stored depth: four steps of the depth format (the float
// transform and the format's quantization), turned into z by the slope of linear_depth there.
// The D24 and D16 images are the frame's depths stored through the format's codec
// (DepthBuffer::encode, decode), as the pipeline stores a single plane's fragments; the
// Renderer's own D24 and D16 frames follow (RendererUnormFramesOfAPlane).
TEST(MetricDepth, PlaneAtKnownDistanceInEveryDepthMode) {
    const double distance = 3.0;
    const Scene scene = scene_from_triangles({quad(-20, 20, -20, 20, -float(distance))});
    const DepthMode modes[] = {
        {"perspective d32f", Camera::Projection::Perspective, DepthFormat::D32F, false, false},
        {"perspective d24", Camera::Projection::Perspective, DepthFormat::D24, false, false},
        {"perspective d16", Camera::Projection::Perspective, DepthFormat::D16, false, false},
        {"perspective reversed-z d32f", Camera::Projection::Perspective, DepthFormat::D32F, true,
         false},
        {"perspective reversed-z infinite far", Camera::Projection::Perspective, DepthFormat::D32F,
         true, true},
        {"perspective infinite far d24", Camera::Projection::Perspective, DepthFormat::D24, false,
         true},
        {"orthographic d32f", Camera::Projection::Orthographic, DepthFormat::D32F, false, false},
        {"orthographic d16", Camera::Projection::Orthographic, DepthFormat::D16, false, false},
        {"orthographic reversed-z d32f", Camera::Projection::Orthographic, DepthFormat::D32F, true,
         false},
    };
    for (const DepthMode& mode : modes) {
        SCOPED_TRACE(mode.name);
        Camera camera;
        camera.eye = glm::dvec3(0.0);
        camera.target = glm::dvec3(0.0, 0.0, -1.0);
        camera.projection = mode.projection;
        camera.near = 0.5;
        camera.far = 20.0;
        camera.reversed_z = mode.reversed_z;
        camera.infinite_far = mode.infinite_far;
        const RenderOptions options = options_for(camera, kWidth, kHeight);
        const RenderResult frame = render(scene, options);
        std::vector<float> depth = frame.targets.depth;
        const DepthBuffer codec(1, 1, mode.format);
        for (float& w : depth) w = codec.decode(codec.encode(w));
        std::vector<float> z(depth.size());
        metric_depth(frame.stats.camera, depth_clear_value(options), depth, z);
        for (std::size_t i = 0; i < z.size(); ++i) {
            const float w = depth[i];
            const double slope =
                std::abs(linear_depth(camera, w + 1e-7) - linear_depth(camera, w - 1e-7)) / 2e-7;
            const double tolerance = 4.0 * depth_step(mode.format, w) * slope + 1e-6;
            ASSERT_NEAR(z[i], distance, tolerance) << "pixel " << i << " window depth " << w;
        }
    }
}

// The same plane through the Renderer's D24 and D16 paths.
TEST(MetricDepth, RendererUnormFramesOfAPlane) {
    const Scene scene = scene_from_triangles({quad(-20, 20, -20, 20, -3.0f)});
    for (const DepthFormat format : {DepthFormat::D24, DepthFormat::D16}) {
        Camera camera;
        camera.eye = glm::dvec3(0.0);
        camera.target = glm::dvec3(0.0, 0.0, -1.0);
        camera.near = 0.5;
        camera.far = 20.0;
        RenderOptions options = options_for(camera, kWidth, kHeight);
        options.depth_format = format;
        const RenderResult frame = render(scene, options);
        std::vector<float> z(frame.targets.depth.size());
        metric_depth(frame.stats.camera, depth_clear_value(options), frame.targets.depth, z);
        EXPECT_NEAR(z[std::size_t(kHeight / 2) * kWidth + kWidth / 2], 3.0, 1e-3);
    }
}

// An orthographic camera's points: its rays are parallel to the axis, so the points of a plane
// facing it keep the plane's z and spread over the view volume's width and height (less half a
// pixel at each edge, where the extreme samples are).
TEST(Unproject, OrthographicPointsFillTheViewVolume) {
    const Scene scene = scene_from_triangles({quad(-20, 20, -20, 20, -2.0f)});
    Camera camera;
    camera.eye = glm::dvec3(0.0, 0.0, 1.0);
    camera.target = glm::dvec3(0.0, 0.0, -1.0);
    camera.projection = Camera::Projection::Orthographic;
    camera.ortho_height = 3.0;
    const DepthFrame frame = render_depth_frame(scene, options_for(camera, kWidth, kHeight));
    const PointCloud cloud = unproject(frame.camera, kWidth, kHeight, frame.z);
    ASSERT_EQ(cloud.positions.size(), std::size_t(kWidth) * kHeight);
    const double pixel = camera.ortho_height / kHeight;
    const double half_width = 0.5 * camera.ortho_height * kWidth / kHeight;
    EXPECT_NEAR(cloud.positions.front().x, -half_width + 0.5 * pixel, 1e-5);
    EXPECT_NEAR(cloud.positions.front().y, 1.5 - 0.5 * pixel, 1e-5);
    EXPECT_NEAR(cloud.positions.back().x, half_width - 0.5 * pixel, 1e-5);
    EXPECT_NEAR(cloud.positions.back().y, -1.5 + 0.5 * pixel, 1e-5);
    for (const glm::vec3& p : cloud.positions) ASSERT_NEAR(p.z, -2.0, 1e-5);
}

// Where nothing was drawn z is 0, with the standard and the reversed clear value.
TEST(MetricDepth, EmptyPixelsAreZero) {
    const Scene scene = scene_from_triangles({quad(-0.5f, 0.5f, -0.5f, 0.5f, -3.0f)});
    for (const bool reversed : {false, true}) {
        Camera camera;
        camera.eye = glm::dvec3(0.0);
        camera.target = glm::dvec3(0.0, 0.0, -1.0);
        camera.reversed_z = reversed;
        const RenderOptions options = options_for(camera, kWidth, kHeight);
        const RenderResult frame = render(scene, options);
        std::vector<float> z(frame.targets.depth.size());
        metric_depth(frame.stats.camera, depth_clear_value(options), frame.targets.depth, z);
        EXPECT_EQ(z[0], 0.0f);  // a corner, outside the small quad
        EXPECT_NEAR(z[std::size_t(kHeight / 2) * kWidth + kWidth / 2], 3.0, 1e-4);
    }
}

TEST(MetricDepth, RefusesMismatchedSizes) {
    std::vector<float> depth(10), z(9);
    EXPECT_THROW(metric_depth(Camera{}, 1.0f, depth, z), InputError);
}

// At the four corner pixels range = z * |(x/z, y/z, 1)|, the ray computed here from the fovy
// camera's own parameters: x/z = ndc_x * tan(fovy / 2) * aspect, y/z = ndc_y * tan(fovy / 2).
TEST(Range, IsZTimesTheRayLengthAtTheCorners) {
    const double distance = 2.5;
    const Scene scene = scene_from_triangles({quad(-20, 20, -20, 20, -float(distance))});
    Camera camera;
    camera.eye = glm::dvec3(0.0);
    camera.target = glm::dvec3(0.0, 0.0, -1.0);
    camera.fovy_degrees = 70.0;
    const RenderOptions options = options_for(camera, kWidth, kHeight);
    const DepthFrame frame = render_depth_frame(scene, options);
    const double t = std::tan(camera.fovy_degrees * std::numbers::pi / 360.0);
    const double aspect = double(kWidth) / kHeight;
    for (const auto& [px, py] : {std::pair{0, 0}, std::pair{kWidth - 1, 0},
                                 std::pair{0, kHeight - 1}, std::pair{kWidth - 1, kHeight - 1}}) {
        const double ndc_x = (px + 0.5) / kWidth * 2.0 - 1.0;
        const double ndc_y = 1.0 - (py + 0.5) / kHeight * 2.0;
        const double x = ndc_x * t * aspect, y = ndc_y * t;
        const std::size_t i = std::size_t(py) * kWidth + std::size_t(px);
        const double z = frame.z[i];
        EXPECT_NEAR(frame.range[i], z * std::sqrt(1.0 + x * x + y * y), 1e-6 * z);
        // And the range is the true distance to the plane along that ray.
        EXPECT_NEAR(frame.range[i], distance * std::sqrt(1.0 + x * x + y * y), 1e-5);
    }
}

TEST(Range, OrthographicRangeIsZ) {
    const Scene scene = scene_from_triangles({quad(-20, 20, -20, 20, -2.0f)});
    Camera camera;
    camera.eye = glm::dvec3(0.0, 0.0, 1.0);
    camera.target = glm::dvec3(0.0, 0.0, -1.0);
    camera.projection = Camera::Projection::Orthographic;
    const DepthFrame frame = render_depth_frame(scene, options_for(camera, kWidth, kHeight));
    EXPECT_EQ(frame.range, frame.z);
    EXPECT_NEAR(frame.z[0], 3.0, 1e-5);
}

// A UV sphere of radius 1 at (0.2, -0.1, -4): every unprojected point is on the tessellated
// sphere. Its vertices are on the sphere and its faces inside, by at most
// 1 - cos(pi / stacks) cos(pi / slices) (the center of a face of the widest band), so
// 1 - 1.6e-3 <= |p - c| <= 1 + 1e-5 (float rounding of the points at distance 4).
TEST(Unproject, SpherePointsLieOnTheSphere) {
    const glm::vec3 center(0.2f, -0.1f, -4.0f);
    Scene scene = scene_from_meshes({make_uv_sphere(1.0f, 64, 128)});
    scene.instances[0].transform = glm::translate(glm::mat4(1.0f), center);
    const Camera camera = pinhole_camera(160, 120, 140.0);
    const DepthFrame frame = render_depth_frame(scene, options_for(camera, 160, 120));
    const PointCloud cloud = unproject(frame.camera, 160, 120, frame.z, frame.color, frame.normal);
    std::size_t measured = 0;
    for (const float z : frame.z) measured += z > 0.0f;
    ASSERT_GT(measured, 1000u);
    ASSERT_EQ(cloud.positions.size(), measured);
    ASSERT_EQ(cloud.normals.size(), measured);
    ASSERT_EQ(cloud.colors.size(), 3 * measured);
    ASSERT_EQ(cloud.pixels.size(), measured);
    const double sag = 1.0 - std::cos(std::numbers::pi / 64) * std::cos(std::numbers::pi / 128);
    ASSERT_LT(sag, 1.6e-3);
    for (std::size_t i = 0; i < measured; ++i) {
        const glm::dvec3 offset = glm::dvec3(cloud.positions[i]) - glm::dvec3(center);
        const double r = glm::length(offset);
        ASSERT_GE(r, 1.0 - 1.6e-3) << "point " << i;
        ASSERT_LE(r, 1.0 + 1e-5) << "point " << i;
        // The shading normal is the sphere's outward normal there.
        EXPECT_GT(glm::dot(glm::normalize(offset), glm::dvec3(cloud.normals[i])), 0.99);
        // Row-major pixel order.
        if (i > 0) {
            ASSERT_LT(cloud.pixels[i - 1], cloud.pixels[i]);
        }
        ASSERT_GT(frame.z[cloud.pixels[i]], 0.0f);
    }
}

// OpenCV's convention: the point of pixel (u, v) projects back to (u, v) through K and the pose.
TEST(Unproject, PointsReprojectThroughTheIntrinsics) {
    Intrinsics k{150.0, 140.0, 70.25, 45.5, 120, 90, 0.1, 30.0};
    const Camera look = [] {
        Camera c;
        c.eye = glm::dvec3(1.0, 2.0, 3.0);
        c.target = glm::dvec3(0.5, 0.0, -4.0);
        return c;
    }();
    const glm::dmat4 pose = look.camera_to_world(CameraConvention::OpenCV);
    const Camera camera = Camera::from_intrinsics(k, pose);
    std::vector<float> z(std::size_t(k.width) * std::size_t(k.height), 0.0f);
    z[7 * 120 + 3] = 2.0f;
    z[60 * 120 + 100] = 5.5f;
    const PointCloud cloud = unproject(camera, k.width, k.height, z);
    ASSERT_EQ(cloud.positions.size(), 2u);
    const glm::dmat4 world_to_camera = glm::inverse(pose);
    for (std::size_t i = 0; i < 2; ++i) {
        const glm::dvec3 p = glm::dvec3(world_to_camera * glm::dvec4(cloud.positions[i], 1.0));
        const double u = k.fx * p.x / p.z + k.cx, v = k.fy * p.y / p.z + k.cy;
        EXPECT_NEAR(u, cloud.pixels[i] % 120, 1e-4);
        EXPECT_NEAR(v, cloud.pixels[i] / 120, 1e-4);
        EXPECT_NEAR(p.z, z[cloud.pixels[i]], 1e-5);
    }
}

TEST(DepthMillimetres, RoundsClampsAndKeepsZeroForInvalid) {
    const std::vector<float> z{0.0f, 1.2344f, 1.2346f, 70.0f, 0.0001f, -1.0f};
    std::vector<std::uint16_t> mm(z.size());
    depth_millimetres(z, mm);
    EXPECT_EQ(mm, (std::vector<std::uint16_t>{0, 1234, 1235, 65535, 1, 0}));
}

}  // namespace
}  // namespace zraster::test
