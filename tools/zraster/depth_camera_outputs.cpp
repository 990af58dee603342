// `zraster render`'s depth-camera options: z, range and point-cloud outputs, --intrinsics,
// --camera-json and the structured-light sensor (zraster/depth_camera.hpp).
#include "depth_camera_outputs.hpp"

#include <zraster/depth_camera.hpp>
#include <zraster/error.hpp>
#include <zraster/image_io.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/point_cloud_io.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <vector>

#include "camera_ranges.hpp"
#include "command_line.hpp"
#include "output_maps.hpp"

namespace zraster::cli {

namespace {

bool wants_depth(const DepthCameraArguments& a) {
    return !a.z_out.empty() || !a.range_out.empty() || !a.points_out.empty();
}

bool any_sensor_flag(const DepthCameraArguments& a, std::string& which) {
    const std::pair<const char*, bool> flags[] = {
        {"--sensor-baseline", a.baseline.has_value()},
        {"--sensor-disparity-step", a.disparity_step.has_value()},
        {"--sensor-min-range", a.min_range.has_value()},
        {"--sensor-max-range", a.max_range.has_value()},
        {"--sensor-max-incidence", a.max_incidence.has_value()},
        {"--sensor-noise", a.noise.has_value()},
        {"--sensor-seed", !a.seed.empty()}};
    for (const auto& [name, given] : flags)
        if (given) {
            which = name;
            return true;
        }
    return false;
}

// The sensor of the flags, checked; errors name the flag that set the field.
StructuredLightSensor sensor_of(const DepthCameraArguments& a) {
    StructuredLightSensor s;
    if (a.baseline) s.baseline = *a.baseline;
    if (a.disparity_step) s.disparity_step = *a.disparity_step;
    if (a.min_range) s.min_range = *a.min_range;
    if (a.max_range) s.max_range = *a.max_range;
    if (a.max_incidence) s.max_incidence_degrees = *a.max_incidence;
    if (a.noise) s.noise = *a.noise;
    if (!a.seed.empty()) {
        const bool digits =
            a.seed.size() <= 20 && a.seed.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        const unsigned long long seed = digits ? std::strtoull(a.seed.c_str(), nullptr, 10) : 0;
        if (!digits || errno == ERANGE)
            throw InputError("--sensor-seed",
                             "expected a whole number in 0..2^64-1, got '" + a.seed + "'");
        s.seed = seed;
    }
    try {
        check_sensor(s);
    } catch (const InputError& e) {
        static const std::map<std::string, const char*> option{
            {"sensor.baseline", "--sensor-baseline"},
            {"sensor.disparity_step", "--sensor-disparity-step"},
            {"sensor.min_range", "--sensor-min-range"},
            {"sensor.max_range", "--sensor-max-range"},
            {"sensor.max_incidence_degrees", "--sensor-max-incidence"},
            {"sensor.noise", "--sensor-noise"}};
        const auto found = option.find(e.file());
        // A cause may name another field ("must be greater than min_range"): in the flags' terms.
        std::string cause = e.cause();
        for (const auto& [field, flag] : option) {
            const std::string bare = field.substr(field.find('.') + 1);
            for (std::size_t at = cause.find(bare); at != std::string::npos;
                 at = cause.find(bare, at + std::strlen(flag)))
                cause.replace(at, bare.size(), flag);
        }
        throw InputError(found != option.end() ? found->second : "--sensor", cause);
    }
    return s;
}

// "[[a, b, c, d], ...]": the rows of a 4x4 matrix.
std::string matrix_rows(const glm::dmat4& m) {
    std::string out = "[";
    for (int r = 0; r < 4; ++r) {
        out += r ? ", [" : "[";
        for (int c = 0; c < 4; ++c) out += (c ? ", " : "") + exact_number(m[c][r]);
        out += "]";
    }
    return out + "]";
}

// JSON has no infinity or NaN: an infinite far plane, or a clip distance a given projection
// matrix does not have, is null.
std::string distance(double d) {
    return std::isfinite(d) ? exact_number(d) : std::string("null");
}

// An orthographic camera's pixel mapping in OpenCV axes: u = su X + cu, v = sv Y + cv, from the
// projection's x and y rows (window x = (ndc x + 1) W / 2 = u + 0.5; window y from the top =
// (1 - ndc y) H / 2 = v + 0.5, with OpenCV's Y the eye's -y).
struct OrthographicPixels {
    double su, sv, cu, cv;
};
OrthographicPixels orthographic_pixels(const Camera& camera, int width, int height) {
    const glm::dmat4 p = camera.projection_matrix(double(width) / double(height));
    if (p[1][0] != 0.0 || p[0][1] != 0.0)
        throw InputError("--camera-json",
                         "the orthographic projection mixes x and y: no per-axis pixel scale");
    return {p[0][0] * width / 2.0, p[1][1] * height / 2.0, (1.0 + p[3][0]) * width / 2.0 - 0.5,
            (1.0 - p[3][1]) * height / 2.0 - 0.5};
}

// The camera as a data set records it: the pinhole K (or an orthographic camera's pixel scale),
// the OpenCV pose, clip distances, image size.
std::vector<std::uint8_t> camera_json(const Camera& camera, int width, int height) {
    const bool orthographic = camera.is_orthographic();
    const glm::dmat4 pose = camera.camera_to_world(CameraConvention::OpenCV);
    std::string out = "{\n";
    out += "  \"convention\": \"opencv\",\n";
    double near = camera.near,
           far = camera.infinite_far ? std::numeric_limits<double>::infinity() : camera.far;
    if (orthographic) {
        const OrthographicPixels o = orthographic_pixels(camera, width, height);
        out +=
            "  \"projection\": \"orthographic\",\n"
            "  \"convention_note\": \"camera x right, y down, z forward; pixel (u, v) = (column, "
            "row) from the top left, pixel centers at integers; u = su X + cu, v = sv Y + cv "
            "(pixels_per_unit [su, sv], principal_point [cu, cv]); Z moves no pixel\",\n";
        out += fmt::format("  \"width\": {},\n  \"height\": {},\n", width, height);
        out += "  \"pixels_per_unit\": [" + exact_number(o.su) + ", " + exact_number(o.sv) + "],\n";
        out += "  \"principal_point\": [" + exact_number(o.cu) + ", " + exact_number(o.cv) + "],\n";
    } else {
        const Intrinsics k = camera.intrinsics(width, height, CameraConvention::OpenCV);
        near = k.near;
        far = k.far;
        out +=
            "  \"projection\": \"perspective\",\n"
            "  \"convention_note\": \"camera x right, y down, z forward; pixel (u, v) = (column, "
            "row) from the top left, pixel centers at integers; u = fx X / Z + cx, v = fy Y / Z + "
            "cy\",\n";
        out += fmt::format("  \"width\": {},\n  \"height\": {},\n", width, height);
        out += "  \"K\": [[" + exact_number(k.fx) + ", 0, " + exact_number(k.cx) + "], [0, " +
               exact_number(k.fy) + ", " + exact_number(k.cy) + "], [0, 0, 1]],\n";
    }
    out += "  \"camera_to_world\": " + matrix_rows(pose) + ",\n";
    out += "  \"near\": " + distance(near) + ",\n";
    out += "  \"far\": " + distance(far) + ",\n";
    out +=
        "  \"depth\": \"z along the optical axis in scene units; z.png: millimetres, 0 = no "
        "measurement\"\n";
    out += "}\n";
    return {out.begin(), out.end()};
}

}  // namespace

void add_depth_camera_options(CLI::App& cmd, DepthCameraArguments& a) {
    add_depth_camera_output_options(cmd, a);
    add_depth_camera_model_options(cmd, a);
}

void add_depth_camera_output_options(CLI::App& cmd, DepthCameraArguments& a) {
    cmd.add_option("--z-out", a.z_out,
                   "Metric depth (z along the optical axis, scene units, 0 = no measurement): "
                   ".npy (float32, HxW) or .png (16-bit millimetres as RGB-D data sets store "
                   "depth, scene units taken as metres, clamped to 65535)");
    cmd.add_option("--range-out", a.range_out,
                   "Range (distance eye to surface, scene units, 0 = no measurement): .npy "
                   "(float32, HxW)");
    cmd.add_option("--points-out", a.points_out,
                   "Point cloud of the measured pixels: .ply (binary, world-space float "
                   "positions, uchar RGB colors, float normals; row-major pixel order)");
    cmd.add_option("--camera-json", a.camera_json,
                   "Write the camera used as JSON: convention \"opencv\", projection, K (3x3; "
                   "orthographic: pixels_per_unit and principal_point), camera_to_world (4x4), "
                   "near, far, width, height");
}

void add_depth_camera_model_options(CLI::App& cmd, DepthCameraArguments& a) {
    cmd.add_option("--intrinsics", a.intrinsics,
                   "Pinhole camera FX,FY,CX,CY in pixels (OpenCV: pixel centers at integers, v "
                   "down) for the --size image; pose from --eye/--target/--up (or --orbit), "
                   "clip distances from --near/--far");
    cmd.add_option("--sensor", a.sensor,
                   "Depth sensor for --z-out/--range-out/--points-out: ideal (exact) or kinect "
                   "(structured light: projector shadows, disparity quantization, range and "
                   "incidence limits, optional noise)")
        ->check(CLI::IsMember({"ideal", "kinect"}))
        ->capture_default_str();
    const StructuredLightSensor d;
    cmd.add_option("--sensor-baseline", a.baseline,
                   fmt::format("Projector offset along the camera's +x, scene units (default {})",
                               d.baseline));
    cmd.add_option("--sensor-disparity-step", a.disparity_step,
                   fmt::format("Disparity quantum in pixels (default {})", d.disparity_step));
    cmd.add_option("--sensor-min-range", a.min_range,
                   fmt::format("Nearest measured z, scene units (default {})", d.min_range));
    cmd.add_option("--sensor-max-range", a.max_range,
                   fmt::format("Farthest measured z, scene units (default {})", d.max_range));
    cmd.add_option("--sensor-max-incidence", a.max_incidence,
                   fmt::format("Steepest surface seen, degrees from its normal (default {})",
                               d.max_incidence_degrees));
    cmd.add_option("--sensor-noise", a.noise,
                   "Standard deviation of Gaussian disparity noise in pixels (default 0)");
    cmd.add_option("--sensor-seed", a.seed,
                   "Seed of the noise (default 0): the same seed gives the same image");
}

void check_depth_camera_arguments(const DepthCameraArguments& a, const std::string& visibility,
                                  int aa, bool msaa, bool ortho, bool fovy, OutputFiles& outputs) {
    check_output(outputs, a.z_out, {".npy", ".png"}, "--z-out");
    check_output(outputs, a.range_out, {".npy"}, "--range-out");
    check_output(outputs, a.points_out, {".ply"}, "--points-out");
    check_output(outputs, a.camera_json, {".json"}, "--camera-json");
    if (wants_depth(a) && (visibility != "zbuffer" || aa != 1 || msaa)) {
        const char* option = !a.z_out.empty()       ? "--z-out"
                             : !a.range_out.empty() ? "--range-out"
                                                    : "--points-out";
        throw InputError(option, "works with --visibility zbuffer, without --aa and --msaa");
    }
    if (!a.intrinsics.empty() && ortho)
        throw InputError("--intrinsics", "a pinhole camera is a perspective one: not with --ortho");
    if (!a.intrinsics.empty() && fovy)
        throw InputError("--intrinsics", "fy sets the field of view: not with --fovy");
    std::string flag;
    if (a.sensor != "kinect" && any_sensor_flag(a, flag))
        throw InputError(flag, "sets a parameter of --sensor kinect");
    if (a.sensor == "kinect") {
        if (!wants_depth(a))
            throw InputError("--sensor",
                             "kinect changes only --z-out, --range-out and --points-out: give "
                             "one of them");
        if (ortho) throw InputError("--sensor", "kinect needs a perspective camera: not --ortho");
        if (!a.seed.empty() && (!a.noise || *a.noise == 0.0))
            throw InputError("--sensor-seed",
                             "seeds --sensor-noise, which is 0: there is no noise to seed");
        sensor_of(a);
    }
}

bool depth_camera_needs_normals(const DepthCameraArguments& a) {
    return a.sensor == "kinect" || !a.points_out.empty();
}

Camera apply_intrinsics(const DepthCameraArguments& a, const Camera& camera, int width,
                        int height) {
    if (a.intrinsics.empty()) return camera;
    glm::dvec4 v;
    try {
        v = parse_vec4("--intrinsics", a.intrinsics);
    } catch (const InputError&) {
        throw InputError("--intrinsics",
                         "expected FX,FY,CX,CY (finite, in pixels), got '" + a.intrinsics + "'");
    }
    if (const std::string problem = intrinsics_problem(v); !problem.empty())
        throw InputError("--intrinsics", problem);
    Intrinsics k;
    k.fx = v.x;
    k.fy = v.y;
    k.cx = v.z;
    k.cy = v.w;
    k.width = width;
    k.height = height;
    k.near = camera.near;
    k.far = camera.infinite_far ? std::numeric_limits<double>::infinity() : camera.far;
    Camera pinhole;
    try {
        pinhole = Camera::from_intrinsics(k, camera.camera_to_world(CameraConvention::OpenCV));
    } catch (const InputError& e) {
        throw InputError("--intrinsics", e.cause());
    }
    pinhole.reversed_z = camera.reversed_z;
    return pinhole;
}

std::optional<std::string> sensor_warning(const StructuredLightStats& s) {
    const std::uint64_t seen = s.outside_projector + s.grazing + s.shadowed + s.out_of_range;
    if (s.measured > 0 || seen == 0) return std::nullopt;
    return fmt::format(
        "the sensor measured none of the {} pixels that see the scene ({} outside the "
        "projector's image, {} too steep, {} shadowed, {} outside its range): its z and range "
        "are all 0; check the sensor's baseline, ranges and incidence",
        seen, s.outside_projector, s.grazing, s.shadowed, s.out_of_range);
}

void add_depth_camera_outputs(const DepthCameraArguments& a, const Scene& scene,
                              const RenderOptions& options, const RenderTargets& t,
                              OutputFiles& outputs) {
    const Camera& camera = *options.camera;
    if (!a.camera_json.empty()) outputs.add(a.camera_json, camera_json(camera, t.width, t.height));
    if (!wants_depth(a)) return;
    std::vector<float> z(t.depth.size());
    metric_depth(camera, depth_clear_value(options), t.depth, z);
    if (a.sensor == "kinect") {
        std::vector<MeshView> meshes;
        std::vector<InstanceView> instances;
        const StructuredLightStats stats = apply_structured_light(
            sensor_of(a), view_of(scene, meshes, instances), options, z, t.normal);
        if (const auto warning = sensor_warning(stats))
            fmt::print(stderr, "warning: {}: {}\n", scene.name, *warning);
    }
    if (!a.z_out.empty()) {
        if (lower_extension(a.z_out) == ".npy") {
            outputs.add(a.z_out, encode_npy(t.width, t.height, std::span<const float>(z)));
        } else {
            std::vector<std::uint16_t> mm(z.size());
            depth_millimetres(z, mm);
            outputs.add(a.z_out, encode_png16_gray(t.width, t.height, mm));
        }
    }
    if (!a.range_out.empty()) {
        std::vector<float> range(z.size());
        range_from_z(camera, t.width, t.height, z, range);
        outputs.add(a.range_out, encode_npy(t.width, t.height, std::span<const float>(range)));
    }
    if (!a.points_out.empty()) {
        const PointCloud cloud = unproject(camera, t.width, t.height, z, t.color, t.normal);
        outputs.add(a.points_out, encode_ply_points(cloud.positions, cloud.colors, cloud.normals));
    }
}

}  // namespace zraster::cli
