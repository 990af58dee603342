// A depth camera from a rendered frame: metric depth, range, point clouds, and a model of a
// Kinect-style structured-light sensor (docs/depth-camera.md).
//
// Conventions:
//  - Images are width x height, row-major, top row first, as RenderTargets; index py * width + px.
//  - Pixel (px, py) is the pipeline's sample at window (px + 0.5, py + 0.5) (raster.hpp): the
//    point OpenCV calls (u, v) = (px, py) (camera.hpp, CameraConvention).
//  - z: the distance of the surface seen at a pixel along the optical axis (eye-space -z), in
//    scene units; 0 marks a pixel with no measurement (empty, or refused by a sensor model).
//  - range: the distance from the eye to that surface point (perspective); an orthographic
//    camera's rays are parallel, so its range is the distance along the ray from the eye plane,
//    which is z.
//  - Points and normals are in world space.
//
// Bad arguments (sizes that disagree, a camera these functions cannot invert) throw InputError
// naming the argument or field.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/export.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace zraster {

// z from window depths as the Renderer stores them (RenderTargets::depth, any DepthFormat,
// decoded) and the camera that rendered them (RenderStats::camera): each pixel's depth through
// the inverse of the projection's z and w rows (linear_depth), for standard and reversed-Z,
// finite and infinite far, perspective and orthographic cameras. Pixels holding `clear_depth`
// (depth_clear_value(options): nothing drawn there) get 0. z and window_depth have the same
// size. Throws InputError for different sizes and for projections whose depth depends on more
// than eye z. Runs in parallel on the calling thread's oneTBB arena (the same values for any
// number of threads), as range_from_z does.
ZRASTER_API void metric_depth(const Camera& camera, float clear_depth,
                              std::span<const float> window_depth, std::span<float> z);

// The range image of a z image: z times the length of the pixel's ray per unit of z (the ray
// through the pixel's sample point, (x/z, y/z, 1) in eye space), 0 where z is 0. For an
// orthographic camera range equals z (see above). z and range hold width * height values.
ZRASTER_API void range_from_z(const Camera& camera, int width, int height, std::span<const float> z,
                              std::span<float> range);

// The surface points of a z image, one per pixel with z > 0, in row-major pixel order.
struct PointCloud {
    std::vector<glm::vec3> positions;   // world space; a (N, 3) float32 array
    std::vector<std::uint8_t> colors;   // RGB, 3 per point; empty unless colors were given
    std::vector<glm::vec3> normals;     // world space; empty unless normals were given
    std::vector<std::uint32_t> pixels;  // py * width + px of each point
};

// Unprojects every pixel with z > 0 (and finite) through its sample point: the eye-space point
// at depth z on the pixel's ray, taken to world space by the inverse view matrix (in double,
// rounded to float once). rgba (RenderTargets::color, 4 bytes per pixel) and normals
// (RenderTargets::normal) are optional; given, they must cover width * height pixels and their
// values are copied for each point (alpha dropped).
ZRASTER_API PointCloud unproject(const Camera& camera, int width, int height,
                                 std::span<const float> z, std::span<const std::uint8_t> rgba = {},
                                 std::span<const glm::vec3> normals = {});

// z as 16-bit millimetres, as RGB-D data sets store depth (scene units taken as metres): z *
// 1000 rounded to the nearest integer, 0 where z is 0 (no measurement), clamped to 65535 (65.535
// m) above, and to 1 below for measured points nearer than half a millimetre, so that a
// measurement never reads as invalid. out has z.size() values.
ZRASTER_API void depth_millimetres(std::span<const float> z, std::span<std::uint16_t> out);

// A structured-light depth sensor in the manner of the Kinect v1 (the error model of Khoshelham
// and Elberink 2012, "Accuracy and Resolution of Kinect Depth Data for Indoor Mapping
// Applications", Sensors 12(2)): an infrared projector beside the camera, depth by triangulation
// from the disparity of the projected pattern. Lengths are in scene units (metres for the
// Kinect defaults).
struct StructuredLightSensor {
    double baseline = 0.075;              // projector position along the camera's +x axis; > 0
    double disparity_step = 0.125;        // disparity quantum in pixels; > 0
    double min_range = 0.5;               // measured z below this is invalid; >= 0
    double max_range = 4.5;               // measured z above this is invalid; > min_range
    double max_incidence_degrees = 75.0;  // steeper surfaces return no pattern; in (0, 90]
    double noise = 0.0;      // standard deviation of the disparity in pixels (Gaussian); >= 0
    std::uint64_t seed = 0;  // of the noise: the same seed gives the same image
};

// Throws InputError("sensor.FIELD", cause) for a non-finite or out-of-range field (the ranges
// above).
ZRASTER_API void check_sensor(const StructuredLightSensor& sensor);

// Pixels the sensor refused, by cause (each pixel counts once, under the first cause found in
// this order); measured counts the pixels left with a depth.
struct StructuredLightStats {
    std::uint64_t outside_projector = 0;  // the projector's image does not reach the point
    std::uint64_t grazing = 0;            // incidence beyond max_incidence_degrees
    std::uint64_t shadowed = 0;           // the projector's light is blocked before the point
    std::uint64_t out_of_range = 0;       // measured z outside [min_range, max_range]
    std::uint64_t measured = 0;
};

// Turns an ideal z image (metric_depth of a frame) into what the sensor measures, in place.
// camera_options are the options the frame was rendered with, camera set to the camera actually
// used (RenderStats::camera); it must be a pinhole-like perspective camera (Camera::intrinsics
// succeeds; f below is its fx). normals are the frame's world normals (RenderTargets::normal).
// For each pixel with z > 0, with p its surface point:
//  1. The projector is a camera with the same projection placed `baseline` along the camera's
//     +x axis; p outside its image is unlit and invalid.
//  2. Incidence: the larger of the angles between the normal at p and the directions from p to
//     the camera and to the projector; beyond max_incidence_degrees the pattern is not seen.
//  3. Shadow: the scene is rendered from the projector with the pipeline (same options, D32F
//     depth); p is lit when its depth along the projector's axis (equal to z: the baseline is
//     perpendicular to the axis) is at most the projector's stored depth at the pixel p falls in
//     plus a bias, as shadow mapping tests. The bias covers what separates p from that pixel's
//     sample on the same surface: up to half a pixel diagonal sideways, so one pixel footprint
//     (z / f) times the tangent of the projector incidence (clamped at 85 degrees), plus four
//     depth-buffer steps of both images at z (their rounding; RenderOptions::depth_format for
//     the camera) and 1e-6 z. Shadows shrink by at most about a pixel at their edges for it.
//  4. Disparity d = f * baseline / z, plus Gaussian noise of deviation `noise` (a per-pixel
//     counter-based generator seeded by `seed`: the image does not depend on thread count or
//     call order), rounded to a multiple k * disparity_step; k < 1 is invalid; measured
//     z' = f * baseline / (k * disparity_step), so depth steps grow with z^2 (Khoshelham and
//     Elberink's eq. 9: dz = z^2 / (f b) dd).
//  5. z' outside [min_range, max_range] is invalid.
// Invalid pixels get 0. Throws InputError for a bad sensor (check_sensor), camera_options
// without a camera or with an orthographic one, and spans not of width * height values; and
// what render() throws for the projector's frame.
ZRASTER_API StructuredLightStats apply_structured_light(const StructuredLightSensor& sensor,
                                                        const SceneView& scene,
                                                        const RenderOptions& camera_options,
                                                        std::span<float> z,
                                                        std::span<const glm::vec3> normals);

// One depth-camera frame: the rendered images with z and range, rendered from `options`
// (normals are always rendered; color when options.color_target) and, with a sensor, measured
// through apply_structured_light.
struct DepthFrame {
    int width = 0, height = 0;
    Camera camera;                      // the camera actually used
    std::vector<float> z, range;        // as above; 0 = no measurement
    std::vector<std::uint8_t> color;    // RGBA8, empty without options.color_target
    std::vector<glm::vec3> normal;      // world normals, (0, 0, 0) where empty
    StructuredLightStats sensor_stats;  // zeros without a sensor
};
ZRASTER_API DepthFrame render_depth_frame(const Scene& scene, const RenderOptions& options,
                                          const std::optional<StructuredLightSensor>& sensor = {});

}  // namespace zraster
