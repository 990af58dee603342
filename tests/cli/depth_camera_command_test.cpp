// `zraster render`'s depth-camera outputs as a user gets them: --z-out is the library's metric
// depth, its PNG the library's millimetres, --points-out a PLY with one point per measured pixel,
// --camera-json enough to reproject a pixel to the PLY's point, and bad flags exit 2 naming the
// option without writing anything.
#include <zraster/depth_camera.hpp>
#include <zraster/image_io.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

constexpr int kWidth = 96, kHeight = 72;
const std::string kView =
    "builtin:sphere --size 96x72 --eye 0.4,0.3,2.6 --target 0,0,0 --near 0.5 --far 10 --fovy 50";

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// A float32 (height, width) .npy as zraster writes it (version 1.0, little-endian).
std::vector<float> read_npy(const std::filesystem::path& path) {
    const std::string bytes = read_bytes(path);
    EXPECT_GT(bytes.size(), 10u);
    const std::size_t header =
        10 + std::size_t(std::uint8_t(bytes[8])) + 256 * std::size_t(std::uint8_t(bytes[9]));
    EXPECT_NE(bytes.find("'<f4'"), std::string::npos);
    std::vector<float> values((bytes.size() - header) / 4);
    std::memcpy(values.data(), bytes.data() + header, values.size() * 4);
    return values;
}

// The camera the command builds for kView, and the frame the library renders with it.
Camera view_camera() {
    Camera c;
    c.eye = {0.4, 0.3, 2.6};
    c.target = glm::dvec3(0.0);
    c.near = 0.5;
    c.far = 10.0;
    c.fovy_degrees = 50.0;
    return c;
}

RenderOptions view_options(const Camera& camera) {
    RenderOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.camera = camera;
    return o;
}

std::vector<float> library_z(const Camera& camera) {
    const Scene scene = make_procedural_scene("builtin:sphere");
    const RenderOptions options = view_options(camera);
    const RenderResult frame = render(scene, options);
    std::vector<float> z(frame.targets.depth.size());
    metric_depth(camera, depth_clear_value(options), frame.targets.depth, z);
    return z;
}

TEST(DepthCameraCommand, ZNpyIsTheLibrarysMetricDepth) {
    const auto dir = temp_dir("cli-z-npy");
    const CommandResult r = run_zraster("render " + kView + " -o c.png --z-out z.npy", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<float> z = read_npy(dir / "z.npy");
    const std::vector<float> expected = library_z(view_camera());
    ASSERT_EQ(z.size(), expected.size());
    EXPECT_EQ(z, expected);
    std::size_t sphere = 0;
    for (const float v : z) sphere += v > 0.0f;
    EXPECT_GT(sphere, 1000u);
}

TEST(DepthCameraCommand, ZPngIsMillimetres) {
    const auto dir = temp_dir("cli-z-png");
    const CommandResult r = run_zraster("render " + kView + " -o c.png --z-out z.png", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<float> z = library_z(view_camera());
    std::vector<std::uint16_t> mm(z.size());
    depth_millimetres(z, mm);
    // The sphere is 1.6 to 2.6 units away: 1600 to 2600 mm.
    for (const std::uint16_t v : mm) ASSERT_TRUE(v == 0 || (v > 1500 && v < 2700)) << v;
    const std::vector<std::uint8_t> png = encode_png16_gray(kWidth, kHeight, mm);
    EXPECT_EQ(read_bytes(dir / "z.png"), std::string(png.begin(), png.end()));
}

TEST(DepthCameraCommand, IntrinsicsCameraMatchesTheLibrary) {
    const auto dir = temp_dir("cli-intrinsics");
    const CommandResult r = run_zraster(
        "render builtin:sphere --size 96x72 --eye 0.4,0.3,2.6 --target 0,0,0 --near 0.5 "
        "--far 10 --intrinsics 90,95,40.5,38 -o c.png --z-out z.npy",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Intrinsics k{90.0, 95.0, 40.5, 38.0, kWidth, kHeight, 0.5, 10.0};
    const Camera camera =
        Camera::from_intrinsics(k, view_camera().camera_to_world(CameraConvention::OpenCV));
    EXPECT_EQ(read_npy(dir / "z.npy"), library_z(camera));
}

struct PlyCloud {
    std::string header;
    std::size_t count = 0;
    std::vector<glm::vec3> positions, normals;
    std::vector<std::uint8_t> colors;
};

PlyCloud read_ply(const std::filesystem::path& path) {
    const std::string bytes = read_bytes(path);
    PlyCloud cloud;
    const std::size_t end = bytes.find("end_header\n");
    EXPECT_NE(end, std::string::npos);
    cloud.header = bytes.substr(0, end + 11);
    std::istringstream lines(cloud.header);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("element vertex ", 0) == 0) cloud.count = std::stoul(line.substr(15));
    const std::size_t stride = 12 + 3 + 12;
    EXPECT_EQ(bytes.size(), cloud.header.size() + cloud.count * stride);
    const char* p = bytes.data() + cloud.header.size();
    for (std::size_t i = 0; i < cloud.count; ++i, p += stride) {
        glm::vec3 position, normal;
        std::memcpy(&position, p, 12);
        std::memcpy(&normal, p + 15, 12);
        cloud.positions.push_back(position);
        cloud.colors.insert(cloud.colors.end(), p + 12, p + 15);
        cloud.normals.push_back(normal);
    }
    return cloud;
}

// The numbers after "key": in a JSON text, in order (enough for K and camera_to_world).
std::vector<double> json_numbers(const std::string& json, const std::string& key,
                                 std::size_t count) {
    std::size_t at = json.find("\"" + key + "\":");
    EXPECT_NE(at, std::string::npos) << key;
    at += key.size() + 3;
    std::vector<double> out;
    while (out.size() < count && at < json.size()) {
        const char c = json[at];
        if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t used = 0;
            out.push_back(std::stod(json.substr(at), &used));
            at += used;
        } else {
            ++at;
        }
    }
    return out;
}

// A camera-space point through a row-major 4x4 camera_to_world of the camera JSON.
glm::dvec3 transform_point(const std::vector<double>& pose, const glm::dvec4& camera_point) {
    glm::dvec3 world(0.0);
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col)
            world[row] += pose[std::size_t(row * 4 + col)] * camera_point[col];
    return world;
}

TEST(DepthCameraCommand, PointsAndCameraJsonReprojectEachOther) {
    const auto dir = temp_dir("cli-points");
    const CommandResult r = run_zraster(
        "render " + kView + " -o c.png --z-out z.npy --points-out cloud.ply --camera-json cam.json",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<float> z = read_npy(dir / "z.npy");
    const PlyCloud cloud = read_ply(dir / "cloud.ply");
    EXPECT_NE(cloud.header.find("format binary_little_endian 1.0"), std::string::npos);
    for (const char* property : {"float x", "float y", "float z", "uchar red", "uchar green",
                                 "uchar blue", "float nx", "float ny", "float nz"})
        EXPECT_NE(cloud.header.find(std::string("property ") + property), std::string::npos)
            << property;
    std::vector<std::size_t> measured;
    for (std::size_t i = 0; i < z.size(); ++i)
        if (z[i] > 0.0f) measured.push_back(i);
    ASSERT_EQ(cloud.count, measured.size());

    const std::string json = read_bytes(dir / "cam.json");
    EXPECT_NE(json.find("\"convention\": \"opencv\""), std::string::npos) << json;
    EXPECT_EQ(json_numbers(json, "width", 1), std::vector<double>{double(kWidth)});
    EXPECT_EQ(json_numbers(json, "height", 1), std::vector<double>{double(kHeight)});
    EXPECT_EQ(json_numbers(json, "near", 1), std::vector<double>{0.5});
    EXPECT_EQ(json_numbers(json, "far", 1), std::vector<double>{10.0});
    const std::vector<double> k = json_numbers(json, "K", 9);
    const std::vector<double> pose = json_numbers(json, "camera_to_world", 16);
    ASSERT_EQ(k.size(), 9u);
    ASSERT_EQ(pose.size(), 16u);
    EXPECT_EQ(k[1], 0.0);
    EXPECT_EQ(k[8], 1.0);
    // Every PLY point is its pixel's (u, v, z) through K^-1 and the pose, and lies on the unit
    // sphere at the origin (within its tessellation's 1.6e-3).
    for (std::size_t n = 0; n < measured.size(); ++n) {
        const double u = double(measured[n] % kWidth), v = double(measured[n] / kWidth);
        const double depth = z[measured[n]];
        const glm::dvec4 camera_point((u - k[2]) / k[0] * depth, (v - k[5]) / k[4] * depth, depth,
                                      1.0);
        const glm::dvec3 world = transform_point(pose, camera_point);
        ASSERT_NEAR(world.x, cloud.positions[n].x, 1e-5) << "point " << n;
        ASSERT_NEAR(world.y, cloud.positions[n].y, 1e-5) << "point " << n;
        ASSERT_NEAR(world.z, cloud.positions[n].z, 1e-5) << "point " << n;
        ASSERT_NEAR(glm::length(world), 1.0, 1.6e-3) << "point " << n;
        EXPECT_GT(glm::dot(glm::normalize(world), glm::dvec3(cloud.normals[n])), 0.99);
    }
}

TEST(DepthCameraCommand, OrthographicCameraJsonReprojectsThePoints) {
    const auto dir = temp_dir("cli-points-ortho");
    const CommandResult r = run_zraster(
        "render builtin:sphere --size 96x72 --ortho --eye 0.4,0.3,2.6 --target 0,0,0 --near 0.5 "
        "--far 10 -o c.png --z-out z.npy --points-out cloud.ply --camera-json cam.json",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::vector<float> z = read_npy(dir / "z.npy");
    const PlyCloud cloud = read_ply(dir / "cloud.ply");
    const std::string json = read_bytes(dir / "cam.json");
    EXPECT_NE(json.find("\"projection\": \"orthographic\""), std::string::npos) << json;
    EXPECT_EQ(json.find("\"K\""), std::string::npos) << json;
    EXPECT_EQ(json_numbers(json, "near", 1), std::vector<double>{0.5});
    EXPECT_EQ(json_numbers(json, "far", 1), std::vector<double>{10.0});
    const std::vector<double> scale = json_numbers(json, "pixels_per_unit", 2);
    const std::vector<double> centre = json_numbers(json, "principal_point", 2);
    const std::vector<double> pose = json_numbers(json, "camera_to_world", 16);
    ASSERT_EQ(scale.size(), 2u);
    ASSERT_EQ(centre.size(), 2u);
    ASSERT_EQ(pose.size(), 16u);
    // Square pixels, and the optical axis through the image's centre.
    EXPECT_DOUBLE_EQ(scale[0], scale[1]);
    EXPECT_DOUBLE_EQ(centre[0], (kWidth - 1) / 2.0);
    EXPECT_DOUBLE_EQ(centre[1], (kHeight - 1) / 2.0);
    std::size_t n = 0;
    for (std::size_t i = 0; i < z.size(); ++i) {
        if (!(z[i] > 0.0f)) continue;
        ASSERT_LT(n, cloud.count);
        const double u = double(i % kWidth), v = double(i / kWidth);
        const glm::dvec4 camera_point((u - centre[0]) / scale[0], (v - centre[1]) / scale[1], z[i],
                                      1.0);
        const glm::dvec3 world = transform_point(pose, camera_point);
        ASSERT_NEAR(world.x, cloud.positions[n].x, 1e-5) << "pixel " << i;
        ASSERT_NEAR(world.y, cloud.positions[n].y, 1e-5) << "pixel " << i;
        ASSERT_NEAR(world.z, cloud.positions[n].z, 1e-5) << "pixel " << i;
        ASSERT_NEAR(glm::length(world), 1.0, 1.6e-3) << "pixel " << i;
        ++n;
    }
    EXPECT_EQ(n, cloud.count);
    EXPECT_GT(n, 1000u);
}

TEST(DepthCameraCommand, KinectSensorIsTheLibrarysAndFollowsTheSeed) {
    const auto dir = temp_dir("cli-kinect");
    const std::string kinect =
        "render " + kView + " -o c.png --sensor kinect --sensor-noise 0.5 --sensor-baseline 0.1 ";
    ASSERT_EQ(run_zraster(kinect + "--sensor-seed 3 --z-out a.npy", dir).exit_code, 0);
    ASSERT_EQ(run_zraster(kinect + "--sensor-seed 3 --z-out b.npy --threads 1", dir).exit_code, 0);
    ASSERT_EQ(run_zraster(kinect + "--sensor-seed 4 --z-out c.npy", dir).exit_code, 0);
    const std::vector<float> a = read_npy(dir / "a.npy");
    EXPECT_EQ(a, read_npy(dir / "b.npy"));
    EXPECT_NE(a, read_npy(dir / "c.npy"));

    StructuredLightSensor sensor;
    sensor.noise = 0.5;
    sensor.baseline = 0.1;
    sensor.seed = 3;
    const DepthFrame frame = render_depth_frame(make_procedural_scene("builtin:sphere"),
                                                view_options(view_camera()), sensor);
    EXPECT_EQ(a, frame.z);
    EXPECT_GT(frame.sensor_stats.measured, 1000u);
}

// A sensor that measures none of the pixels in view (a baseline of 1e-300: every disparity
// rounds to nothing) writes its all-zero images with a warning giving the counts by cause; one
// that measures some says nothing.
TEST(DepthCameraCommand, ASensorThatMeasuresNothingSaysSo) {
    const auto dir = temp_dir("cli-kinect-nothing");
    const std::string kinect = "render " + kView + " -o c.png --sensor kinect --z-out z.npy ";
    StructuredLightSensor sensor;
    sensor.baseline = 1e-300;
    const DepthFrame frame = render_depth_frame(make_procedural_scene("builtin:sphere"),
                                                view_options(view_camera()), sensor);
    ASSERT_EQ(frame.sensor_stats.measured, 0u);
    const StructuredLightStats& s = frame.sensor_stats;
    const CommandResult r = run_zraster(kinect + "--sensor-baseline 1e-300", dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output,
              "warning: builtin:sphere: the sensor measured none of the " +
                  std::to_string(s.outside_projector + s.grazing + s.shadowed + s.out_of_range) +
                  " pixels that see the scene (" + std::to_string(s.outside_projector) +
                  " outside the projector's image, " + std::to_string(s.grazing) + " too steep, " +
                  std::to_string(s.shadowed) + " shadowed, " + std::to_string(s.out_of_range) +
                  " outside its range): its z and range are all 0; check the sensor's "
                  "baseline, ranges and incidence\n");
    EXPECT_EQ(read_npy(dir / "z.npy"), frame.z);
    const CommandResult measured = run_zraster(kinect, dir);
    EXPECT_EQ(measured.exit_code, 0);
    EXPECT_EQ(measured.output, "");
}

TEST(DepthCameraCommand, BadFlagsExitTwoNamingTheOptionWithoutWritingAnything) {
    const struct {
        std::string flags, option;
    } cases[] = {
        {"--z-out z.npy --sensor kinect --sensor-baseline -1", "--sensor-baseline"},
        {"--z-out z.npy --sensor kinect --sensor-baseline nan", "--sensor-baseline"},
        {"--z-out z.npy --sensor kinect --sensor-max-range 0.2", "--sensor-max-range"},
        {"--z-out z.npy --sensor kinect --sensor-max-incidence 120", "--sensor-max-incidence"},
        {"--z-out z.npy --sensor kinect --sensor-noise -0.5", "--sensor-noise"},
        {"--z-out z.npy --sensor kinect --sensor-seed -5", "--sensor-seed"},
        {"--z-out z.npy --sensor-baseline 0.1", "--sensor-baseline"},
        {"--sensor kinect --camera-json cam.json", "--sensor"},
        {"--z-out z.npy --sensor sonar", "--sensor"},
        {"--z-out z.txt", "--z-out"},
        {"--range-out r.png", "--range-out"},
        {"--points-out cloud.obj", "--points-out"},
        {"--camera-json cam.txt", "--camera-json"},
        {"--z-out z.npy --visibility painter", "--z-out"},
        {"--points-out cloud.ply --aa 2", "--points-out"},
        {"--z-out z.npy --intrinsics 90,95,40", "--intrinsics"},
        {"--z-out z.npy --intrinsics -90,95,40,30", "--intrinsics"},
        {"--z-out z.npy --intrinsics 90,95,40,30 --ortho", "--intrinsics"},
        {"--z-out z.npy --intrinsics 90,95,40,30 --fovy 40", "--intrinsics"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.flags);
        const auto dir = temp_dir("cli-depth-bad");
        const CommandResult r =
            run_zraster("render builtin:sphere --size 32x24 -o c.png " + c.flags, dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find(c.option), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;
        EXPECT_TRUE(std::filesystem::is_empty(dir)) << r.output;
        // Only the command's own names: no library field name ("min_range") in a message.
        EXPECT_EQ(r.output.find('_'), std::string::npos) << r.output;
    }
}

TEST(DepthCameraCommand, HelpDescribesEveryOption) {
    const CommandResult r = run_zraster("render --help");
    ASSERT_EQ(r.exit_code, 0);
    for (const char* option :
         {"--z-out", "--range-out", "--points-out", "--intrinsics", "--camera-json", "--sensor",
          "--sensor-baseline", "--sensor-disparity-step", "--sensor-min-range",
          "--sensor-max-range", "--sensor-max-incidence", "--sensor-noise", "--sensor-seed"})
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
}

}  // namespace
}  // namespace zraster::test
