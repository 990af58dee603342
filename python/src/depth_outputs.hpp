// The depth camera's part of a render call (depth_camera_binding.cpp): the sensor argument and
// the z and range outputs.
#pragma once
#include <zraster/depth_camera.hpp>
#include <zraster/render.hpp>

#include <pybind11/pybind11.h>

#include <optional>

namespace zraster::python {

namespace py = pybind11;

// sensor=: None or "ideal" (exact), "kinect" (StructuredLightSensor()), or a
// zraster.StructuredLightSensor; else TypeError / InputError naming `sensor`.
std::optional<StructuredLightSensor> sensor_argument(py::handle object);

// Where a frame's depth-camera images come from and go (width * height values each).
struct DepthCameraImages {
    const float* depth = nullptr;       // the frame's window depths (decoded)
    const glm::vec3* normal = nullptr;  // its world normals: needed with a sensor
    float* z = nullptr;
    float* range = nullptr;  // null: not wanted
    std::optional<StructuredLightSensor> sensor;
};

// z (metric depth), measured through the sensor if there is one, then range, for a frame
// rendered with `options` by `camera` (RenderStats::camera). Makes no Python call: runs without
// the GIL. Returns the sensor's counts (all zero without one).
StructuredLightStats depth_camera_images(const DepthCameraImages& images, const SceneView& scene,
                                         const RenderOptions& options, const Camera& camera);

void bind_depth_camera(py::module_& m);

}  // namespace zraster::python
