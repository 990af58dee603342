// The structured-light sensor model against what triangulation implies: the projector's shadow
// falls on the far side of an occluder and nowhere on an open wall, depths sit on the disparity
// lattice z = f b / (k step), noise follows the seed and nothing else, bad parameters are named.
#include <zraster/depth_camera.hpp>
#include <zraster/error.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "sensor/sensor_test_util.hpp"

namespace zraster::test {
namespace {

constexpr int kSensorWidth = 160, kSensorHeight = 120;
constexpr double kFocal = 150.0;

StructuredLightSensor open_sensor() {
    StructuredLightSensor s;
    s.baseline = 0.3;
    s.min_range = 0.1;
    s.max_range = 20.0;
    s.max_incidence_degrees = 89.0;
    return s;
}

DepthFrame frame_of(const Scene& scene, const std::optional<StructuredLightSensor>& sensor,
                    int threads = 2) {
    RenderOptions options = options_for(pinhole_camera(kSensorWidth, kSensorHeight, kFocal),
                                        kSensorWidth, kSensorHeight);
    options.threads = threads;
    return render_depth_frame(scene, options, sensor);
}

std::size_t at(int px, int py) {
    return std::size_t(py) * kSensorWidth + std::size_t(px);
}

// A wall at z = 3 and a square occluder at z = 1.5 covering x in [-0.3, 0.3]. The projector
// sits at x = +b, so the occluder's shadow on the wall is the band x in [2 x0 - b, 2 x0] left of
// its left edge x0 = -0.3 (the projector's ray past the edge reaches the wall at
// b + 2 (x0 - b)): b wide on the wall, f b / 3 = 15 pixels in the image, and nothing on the
// right side.
TEST(StructuredLight, ShadowFallsOnTheFarSideOfTheOccluder) {
    const Scene scene = scene_from_triangles(
        {quad(-10, 10, -10, 10, -3.0f), quad(-0.3f, 0.3f, -0.3f, 0.3f, -1.5f)});
    const StructuredLightSensor sensor = open_sensor();
    const DepthFrame ideal = frame_of(scene, std::nullopt);
    const DepthFrame measured = frame_of(scene, sensor);
    EXPECT_GT(measured.sensor_stats.shadowed, 0u);
    const double cx = 0.5 * kSensorWidth - 0.5;
    const double occluder_left = kFocal * -0.3 / 1.5 + cx;  // u of the occluder's left edge
    const double shadow_left = kFocal * (2 * -0.3 - sensor.baseline) / 3.0 + cx;
    // Rows well inside the occluder's vertical extent.
    for (int py = kSensorHeight / 2 - 10; py < kSensorHeight / 2 + 10; ++py) {
        int shadowed = 0;
        for (int px = 0; px < kSensorWidth; ++px) {
            const std::size_t i = at(px, py);
            if (!(ideal.z[i] > 0.0f) || measured.z[i] > 0.0f) continue;
            // The left columns the projector's image does not reach (f b / z of them).
            if (px <= kFocal * sensor.baseline / ideal.z[i] + 1.0) continue;
            // Every other refused pixel of these rows is wall, between the shadow's edges (a pixel
            // of slack for the bias and the sampling).
            ASSERT_NEAR(ideal.z[i], 3.0, 1e-3) << px << "," << py;
            ASSERT_GE(px, shadow_left - 1.0) << px << "," << py;
            ASSERT_LE(px, occluder_left + 1.0) << px << "," << py;
            ++shadowed;
        }
        EXPECT_NEAR(shadowed, kFocal * sensor.baseline / 3.0, 1.5) << "row " << py;
    }
}

// An open wall, facing the camera or turned 60 degrees: no pixel the projector reaches is
// shadowed (the bias holds on slopes), and only the left columns the projector's image does not
// reach (f b / z of them) are refused.
TEST(StructuredLight, NoShadowOnAnUnobstructedWall) {
    for (const double degrees : {0.0, 60.0, -60.0}) {
        SCOPED_TRACE(degrees);
        const Scene scene = scene_from_triangles({tilted_quad(6.0f, -3.0f, degrees)});
        const DepthFrame ideal = frame_of(scene, std::nullopt);
        const DepthFrame measured = frame_of(scene, open_sensor());
        EXPECT_EQ(measured.sensor_stats.shadowed, 0u);
        EXPECT_EQ(measured.sensor_stats.grazing, 0u);
        EXPECT_GT(measured.sensor_stats.measured, std::size_t(kSensorWidth * kSensorHeight) / 2);
        for (int py = 0; py < kSensorHeight; ++py) {
            for (int px = 0; px < kSensorWidth; ++px) {
                const std::size_t i = at(px, py);
                if (!(ideal.z[i] > 0.0f) || measured.z[i] > 0.0f) continue;
                const double unreached = kFocal * open_sensor().baseline / ideal.z[i];
                ASSERT_LE(px, unreached + 1.0) << px << "," << py;
            }
        }
    }
}

// A wall turned 60 degrees about the vertical, z from about 1.6 to 8 across the image. With
// f = 150 and the Kinect's b = 0.075 and step 1/8, every measured z is f b / (k step) for a
// whole k, and consecutive distinct z values are one disparity step apart: the wall's depth
// changes by less than a level per pixel (z = z0 / (1 - s x_image) changes by z^2 s / (f z0) per
// column, the levels are z^2 step / (f b) apart, a ratio s b / (z0 step) = 0.35 for s = tan 60).
TEST(StructuredLight, DepthsSitOnTheDisparityLattice) {
    const Scene scene = scene_from_triangles({tilted_quad(6.0f, -3.0f, 60.0)});
    StructuredLightSensor sensor;  // Kinect baseline and step, no noise
    sensor.min_range = 0.1;
    sensor.max_range = 10.0;
    sensor.max_incidence_degrees = 89.0;
    const DepthFrame measured = frame_of(scene, sensor);
    const double fb = kFocal * sensor.baseline;
    std::set<long> levels;
    for (const float z : measured.z) {
        if (!(z > 0.0f)) continue;
        const double k = fb / (double(z) * sensor.disparity_step);
        ASSERT_NEAR(k, std::round(k), 1e-4) << "z " << z;
        levels.insert(std::lround(k));
    }
    ASSERT_GT(levels.size(), 30u);
    const std::vector<long> k(levels.begin(), levels.end());
    for (std::size_t i = 1; i < k.size(); ++i) {
        EXPECT_EQ(k[i] - k[i - 1], 1) << "disparity level " << k[i - 1];
        const double z_near = fb / (k[i] * sensor.disparity_step);
        const double z_far = fb / (k[i - 1] * sensor.disparity_step);
        // Khoshelham and Elberink's resolution: neighbouring levels z^2 / (f b) * step apart.
        EXPECT_NEAR(z_far - z_near, z_near * z_far / fb * sensor.disparity_step, 1e-9);
    }
}

TEST(StructuredLight, NoiseFollowsTheSeedAndNotTheThreads) {
    const Scene scene = scene_from_triangles({tilted_quad(6.0f, -3.0f, 30.0)});
    StructuredLightSensor sensor = open_sensor();
    sensor.noise = 0.5;
    sensor.seed = 7;
    const DepthFrame a = frame_of(scene, sensor, 1);
    const DepthFrame b = frame_of(scene, sensor, 2);
    const DepthFrame c = frame_of(scene, sensor, 0);
    EXPECT_EQ(a.z, b.z);
    EXPECT_EQ(a.z, c.z);
    sensor.seed = 8;
    const DepthFrame other = frame_of(scene, sensor, 2);
    EXPECT_NE(a.z, other.z);
    sensor.noise = 0.0;
    const DepthFrame quiet = frame_of(scene, sensor, 2);
    EXPECT_NE(a.z, quiet.z);
}

TEST(StructuredLight, OutOfRangeAndGrazingAreRefused) {
    // Turned 80 degrees: the camera's rays (at most 28 degrees off axis) meet it at 52 degrees
    // or more.
    const Scene scene = scene_from_triangles({tilted_quad(6.0f, -3.0f, 80.0)});
    StructuredLightSensor sensor = open_sensor();
    sensor.max_incidence_degrees = 45.0;
    const DepthFrame steep = frame_of(scene, sensor);
    EXPECT_EQ(steep.sensor_stats.measured, 0u);
    EXPECT_GT(steep.sensor_stats.grazing, 0u);
    const Scene wall = scene_from_triangles({quad(-10, 10, -10, 10, -3.0f)});
    sensor.max_range = 2.5;
    const DepthFrame far = frame_of(wall, sensor);
    EXPECT_EQ(far.sensor_stats.measured, 0u);
    EXPECT_GT(far.sensor_stats.out_of_range, 0u);
}

TEST(StructuredLight, BadParametersNameTheField) {
    const auto refused = [](StructuredLightSensor s, const std::string& field) {
        try {
            check_sensor(s);
        } catch (const InputError& e) {
            EXPECT_EQ(e.file(), "sensor." + field) << e.what();
            return;
        }
        ADD_FAILURE() << field << " accepted";
    };
    StructuredLightSensor s;
    s.baseline = 0.0;
    refused(s, "baseline");
    s = {};
    s.baseline = std::nan("");
    refused(s, "baseline");
    s = {};
    s.disparity_step = -1.0;
    refused(s, "disparity_step");
    s = {};
    s.min_range = 5.0;
    refused(s, "max_range");
    s = {};
    s.max_range = std::nan("");
    refused(s, "max_range");
    s = {};
    s.max_incidence_degrees = 91.0;
    refused(s, "max_incidence_degrees");
    s = {};
    s.noise = -0.1;
    refused(s, "noise");
    EXPECT_NO_THROW(check_sensor(StructuredLightSensor{}));
    // A frame is not drawn for a bad sensor, and an orthographic camera has no disparity.
    const Scene scene = scene_from_triangles({quad(-1, 1, -1, 1, -3.0f)});
    s = {};
    s.baseline = -1.0;
    EXPECT_THROW(frame_of(scene, s), InputError);
    Camera ortho;
    ortho.projection = Camera::Projection::Orthographic;
    EXPECT_THROW(render_depth_frame(scene, options_for(ortho, 32, 24), StructuredLightSensor{}),
                 InputError);
}

}  // namespace
}  // namespace zraster::test
