// A structured-light depth sensor (Kinect v1 style) applied to an ideal z image. The error model
// is Khoshelham and Elberink 2012, "Accuracy and Resolution of Kinect Depth Data for Indoor
// Mapping Applications", Sensors 12(2), 1437-1454: depth is triangulated from the disparity d of
// the projected pattern, z = f b / d (their eq. 4 with the reference plane at infinity), d is
// measured in steps of 1/8 pixel, so the depth resolution is dz = z^2 / (f b) dd (eq. 9) and
// random disparity error sigma_d gives sigma_z = z^2 / (f b) sigma_d (eq. 10). Where the
// projector's light cannot reach (occlusion by nearer surfaces, outside its field of view,
// grazing surfaces) the pattern is missing and the sensor returns no depth.
#include <zraster/depth_camera.hpp>
#include <zraster/error.hpp>

#include "sensor/pixel_rays.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace zraster {

namespace {

std::string number(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

[[noreturn]] void refuse(const char* field, const std::string& cause, double value) {
    throw InputError(std::string("sensor.") + field, cause + ", not " + number(value));
}

// splitmix64's output function (Steele, Lea and Flood 2014): a bijective 64-bit mix.
std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// A standard normal variate for (seed, pixel) alone (Box-Muller on two counter-based uniforms),
// so that the noise image depends on neither thread count nor the order pixels are visited in.
double gaussian(std::uint64_t seed, std::uint64_t pixel) {
    const std::uint64_t key = mix(seed + 0x9E3779B97F4A7C15ull);
    const std::uint64_t a = mix(key ^ mix(2 * pixel + 1));
    const std::uint64_t b = mix(key ^ mix(2 * pixel + 2));
    const double u1 = double((a >> 11) + 1) * 0x1.0p-53;  // (0, 1]: the logarithm is finite
    const double u2 = double(b >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// The scene's depth as the projector sees it: the camera's frame moved by the baseline, drawn by
// the same pipeline into a D32F buffer (the shadow map).
std::vector<float> projector_depth(const SceneView& scene, const RenderOptions& camera_options,
                                   const Camera& projector, float& clear) {
    RenderOptions o = camera_options;
    o.camera = projector;
    o.depth_format = DepthFormat::D32F;
    o.depth_compare.reset();
    o.depth_test = true;
    o.depth_write = true;
    o.edges = RenderOptions::Edges::None;
    std::vector<float> depth(std::size_t(o.width) * std::size_t(o.height));
    TargetViews views;
    views.width = o.width;
    views.height = o.height;
    views.depth = depth.data();
    render(scene, o, views);
    clear = depth_clear_value(o);
    return depth;
}

}  // namespace

void check_sensor(const StructuredLightSensor& s) {
    if (!(std::isfinite(s.baseline) && s.baseline > 0.0))
        refuse("baseline", "must be finite and > 0", s.baseline);
    if (!(std::isfinite(s.disparity_step) && s.disparity_step > 0.0))
        refuse("disparity_step", "must be finite and > 0", s.disparity_step);
    if (!(std::isfinite(s.min_range) && s.min_range >= 0.0))
        refuse("min_range", "must be finite and >= 0", s.min_range);
    if (!(s.max_range > s.min_range))
        refuse("max_range", "must be greater than min_range (" + number(s.min_range) + ")",
               s.max_range);
    if (!(s.max_incidence_degrees > 0.0 && s.max_incidence_degrees <= 90.0))
        refuse("max_incidence_degrees", "must be in (0, 90]", s.max_incidence_degrees);
    if (!(std::isfinite(s.noise) && s.noise >= 0.0))
        refuse("noise", "must be finite and >= 0", s.noise);
}

StructuredLightStats apply_structured_light(const StructuredLightSensor& sensor,
                                            const SceneView& scene,
                                            const RenderOptions& camera_options, std::span<float> z,
                                            std::span<const glm::vec3> normals) {
    check_sensor(sensor);
    if (!camera_options.camera)
        throw InputError("camera_options.camera",
                         "must be the camera the depth was rendered with (RenderStats::camera)");
    const Camera& camera = *camera_options.camera;
    if (camera.is_orthographic())
        throw InputError("camera_options.camera",
                         "a structured-light sensor needs a perspective camera");
    const int width = camera_options.width, height = camera_options.height;
    sensor::check_image_span("z", z.size(), width, height);
    sensor::check_image_span("normals", normals.size(), width, height);
    check_camera(camera, width, height);
    const double f = camera.intrinsics(width, height).fx;
    const double fb = f * sensor.baseline;
    const sensor::PixelRays rays(camera, width, height);
    const sensor::DepthAxis axis(camera);

    // The projector: the camera's eye space moved by the baseline along its x axis.
    Camera projector = camera;
    glm::dmat4 shift(1.0);
    shift[3][0] = -sensor.baseline;
    projector.given_view = shift * camera.view();
    float projector_clear = 0.0f;
    const std::vector<float> shadow_map =
        projector_depth(scene, camera_options, projector, projector_clear);

    // Normals to eye space (inverse transpose: a view from matrices may scale).
    const glm::dmat3 normal_to_eye = glm::transpose(glm::inverse(glm::dmat3(camera.view())));
    const glm::dvec3 projector_eye(sensor.baseline, 0.0, 0.0);
    const double min_cos = std::cos(sensor.max_incidence_degrees * std::numbers::pi / 180.0);
    // The shadow bias's slope factor is capped: beyond 85 degrees it would excuse everything.
    const double max_tan = std::tan(85.0 * std::numbers::pi / 180.0);

    StructuredLightStats stats;
    for (int py = 0; py < height; ++py) {
        for (int px = 0; px < width; ++px) {
            const std::size_t i = std::size_t(py) * std::size_t(width) + std::size_t(px);
            const double depth = z[i];
            z[i] = 0.0f;
            if (!(depth > 0.0) || !std::isfinite(depth)) continue;
            const glm::dvec3 p = rays.eye_point(px, py, depth);

            // 1. Inside the projector's image?
            glm::dvec2 window;
            if (!rays.window_of(p - projector_eye, window) || !(window.x >= 0.0) ||
                !(window.x < width) || !(window.y >= 0.0) || !(window.y < height)) {
                ++stats.outside_projector;
                continue;
            }

            // 2. Incidence at the camera and at the projector.
            double tan_projector = max_tan;
            const glm::dvec3 n = normal_to_eye * glm::dvec3(normals[i]);
            if (glm::length(n) > 0.0) {
                const glm::dvec3 unit = glm::normalize(n);
                const double cos_camera = std::abs(glm::dot(unit, glm::normalize(-p)));
                const double cos_projector =
                    std::abs(glm::dot(unit, glm::normalize(projector_eye - p)));
                if (std::min(cos_camera, cos_projector) < min_cos) {
                    ++stats.grazing;
                    continue;
                }
                tan_projector = std::min(
                    std::sqrt(std::max(0.0, 1.0 - cos_projector * cos_projector)) / cos_projector,
                    max_tan);
            }

            // 3. Shadow: is a nearer surface in the projector's pixel? The bias (header) covers
            // the offset from that pixel's sample to p on the same surface and both depths'
            // rounding.
            const int qx = std::min(static_cast<int>(window.x), width - 1);
            const int qy = std::min(static_cast<int>(window.y), height - 1);
            const float stored = shadow_map[std::size_t(qy) * std::size_t(width) + std::size_t(qx)];
            if (stored != projector_clear) {
                const double bias = depth / f * tan_projector +
                                    axis.z_resolution(depth, camera_options.depth_format, 4.0) +
                                    axis.z_resolution(depth, DepthFormat::D32F, 4.0) + 1e-6 * depth;
                if (depth > axis.z_of(stored) + bias) {
                    ++stats.shadowed;
                    continue;
                }
            }

            // 4. Disparity, noise, quantization.
            double disparity = fb / depth;
            if (sensor.noise > 0.0) disparity += sensor.noise * gaussian(sensor.seed, i);
            const double steps = std::floor(disparity / sensor.disparity_step + 0.5);
            const double measured = fb / (steps * sensor.disparity_step);

            // 5. Working range (no disparity step at all: beyond any range).
            if (!(steps >= 1.0) ||
                !(measured >= sensor.min_range && measured <= sensor.max_range)) {
                ++stats.out_of_range;
                continue;
            }
            z[i] = static_cast<float>(measured);
            ++stats.measured;
        }
    }
    return stats;
}

}  // namespace zraster
