// The depth-camera options of `zraster render` (docs/depth-camera.md): metric depth, range and
// point-cloud outputs, a pinhole camera from intrinsics, the camera written as JSON, and the
// structured-light sensor model.
#pragma once
#include <zraster/depth_camera.hpp>
#include <zraster/output_files.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace zraster::cli {

struct DepthCameraArguments {
    std::string z_out, range_out, points_out, camera_json;
    std::string intrinsics;
    std::string sensor = "ideal";
    std::optional<double> baseline, disparity_step, min_range, max_range, max_incidence, noise;
    std::string seed;
};

// Both of the two below.
void add_depth_camera_options(CLI::App& cmd, DepthCameraArguments& arguments);
// The output paths: --z-out, --range-out, --points-out, --camera-json.
void add_depth_camera_output_options(CLI::App& cmd, DepthCameraArguments& arguments);
// The camera and sensor model: --intrinsics, --sensor and its parameters.
void add_depth_camera_model_options(CLI::App& cmd, DepthCameraArguments& arguments);

// Before any work: the output paths (extension, then OutputFiles::check) and the flags'
// consistency; throws InputError naming the option.
void check_depth_camera_arguments(const DepthCameraArguments& arguments,
                                  const std::string& visibility, int aa, bool msaa, bool ortho,
                                  bool fovy, OutputFiles& outputs);

// Whether the frame needs its normal target (sensor model, point cloud).
bool depth_camera_needs_normals(const DepthCameraArguments& arguments);

// `camera` as the pinhole of --intrinsics (its pose, near, far and depth mode kept), for an
// image of `width` x `height`; unchanged without --intrinsics.
Camera apply_intrinsics(const DepthCameraArguments& arguments, const Camera& camera, int width,
                        int height);

// A warning when the sensor measured none of the pixels that see the scene (its settings, such
// as a baseline of 1e-300, can leave every one unmeasured): the counts by cause. nullopt when it
// measured some, or nothing was in view.
std::optional<std::string> sensor_warning(const StructuredLightStats& stats);

// The requested outputs' bytes, added to `outputs` (options: those the frame was rendered
// with, their camera the one used).
void add_depth_camera_outputs(const DepthCameraArguments& arguments, const Scene& scene,
                              const RenderOptions& options, const RenderTargets& targets,
                              OutputFiles& outputs);

}  // namespace zraster::cli
