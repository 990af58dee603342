// The depth camera for Python (docs/depth-camera.md): zraster.StructuredLightSensor, the `sensor`
// argument of Renderer.render, the z and range outputs, and zraster.unproject.
#include "depth_outputs.hpp"

#include <pybind11/stl.h>

#include <cstring>
#include <string>

#include "arrays.hpp"
#include "errors.hpp"

namespace zraster::python {
namespace {

using namespace pybind11::literals;

// check_sensor's message names "sensor.FIELD"; the Python keyword of max_incidence_degrees is
// max_incidence.
[[noreturn]] void refuse_sensor(const InputError& e) {
    std::string field = e.file();
    if (field == "sensor.max_incidence_degrees") field = "max_incidence";
    if (field.rfind("sensor.", 0) == 0) field = field.substr(7);
    input_error(field, e.cause());
}

StructuredLightSensor make_sensor(const py::object& baseline, const py::object& disparity_step,
                                  const py::object& min_range, const py::object& max_range,
                                  const py::object& max_incidence, const py::object& noise,
                                  const py::object& seed) {
    StructuredLightSensor s;
    s.baseline = finite_number(baseline, "baseline");
    s.disparity_step = finite_number(disparity_step, "disparity_step");
    s.min_range = finite_number(min_range, "min_range");
    s.max_range = finite_number(max_range, "max_range");
    s.max_incidence_degrees = finite_number(max_incidence, "max_incidence");
    s.noise = finite_number(noise, "noise");
    if (py::isinstance<py::bool_>(seed) || !py::hasattr(seed, "__index__"))
        type_error("seed", "an integer", seed);
    const py::int_ value(py::reinterpret_borrow<py::object>(seed));
    if (value < py::int_(0) || value > py::int_(std::uint64_t(-1)))
        input_error("seed", "must be in 0..2^64 - 1");
    s.seed = value.cast<std::uint64_t>();
    try {
        check_sensor(s);
    } catch (const InputError& e) {
        refuse_sensor(e);
    }
    return s;
}

}  // namespace

std::optional<StructuredLightSensor> sensor_argument(py::handle object) {
    if (object.is_none()) return std::nullopt;
    if (py::isinstance<StructuredLightSensor>(object)) return object.cast<StructuredLightSensor>();
    if (py::isinstance<py::str>(object)) {
        const std::string name = object.cast<std::string>();
        if (name == "ideal") return std::nullopt;
        if (name == "kinect") return StructuredLightSensor{};
        input_error("sensor", "unknown sensor '" + name +
                                  "' (expected None, 'ideal', 'kinect' or a "
                                  "zraster.StructuredLightSensor)");
    }
    type_error("sensor", "None, 'ideal', 'kinect' or a zraster.StructuredLightSensor", object);
}

StructuredLightStats depth_camera_images(const DepthCameraImages& images, const SceneView& scene,
                                         const RenderOptions& options, const Camera& camera) {
    const std::size_t n = std::size_t(options.width) * std::size_t(options.height);
    const std::span<float> z(images.z, n);
    metric_depth(camera, depth_clear_value(options), {images.depth, n}, z);
    StructuredLightStats stats;
    if (images.sensor) {
        RenderOptions used = options;
        used.camera = camera;
        stats = apply_structured_light(*images.sensor, scene, used, z, {images.normal, n});
    }
    if (images.range != nullptr)
        range_from_z(camera, options.width, options.height, z, {images.range, n});
    return stats;
}

void bind_depth_camera(py::module_& m) {
    py::class_<StructuredLightSensor>(m, "StructuredLightSensor",
                                      R"(A Kinect-style structured-light depth sensor.

StructuredLightSensor(baseline=0.075, disparity_step=0.125, min_range=0.5, max_range=4.5,
                      max_incidence=75, noise=0.0, seed=0)

Given to Renderer.render(..., sensor=...), it turns the z (and range) outputs into what such a
sensor measures (the error model of Khoshelham and Elberink 2012, "Accuracy and Resolution of
Kinect Depth Data for Indoor Mapping Applications", Sensors 12(2)): an infrared projector
`baseline` scene units along the camera's +x axis; pixels the projector cannot light (in its
shadow, outside its image) are 0; depth comes from the disparity d = f * baseline / z, rounded to
multiples of `disparity_step` pixels, so depth steps grow with z^2; measured depths outside
[min_range, max_range] and surfaces steeper than `max_incidence` degrees are 0; `noise` adds
Gaussian disparity noise (pixels) from `seed`: the same seed gives the same image, whatever the
thread count. sensor="kinect" is StructuredLightSensor() (metres); None or "ideal" is exact.)")
        .def(py::init(&make_sensor), "baseline"_a = 0.075, "disparity_step"_a = 0.125,
             "min_range"_a = 0.5, "max_range"_a = 4.5, "max_incidence"_a = 75.0, "noise"_a = 0.0,
             "seed"_a = 0)
        .def_readonly("baseline", &StructuredLightSensor::baseline)
        .def_readonly("disparity_step", &StructuredLightSensor::disparity_step)
        .def_readonly("min_range", &StructuredLightSensor::min_range)
        .def_readonly("max_range", &StructuredLightSensor::max_range)
        .def_readonly("max_incidence", &StructuredLightSensor::max_incidence_degrees)
        .def_readonly("noise", &StructuredLightSensor::noise)
        .def_readonly("seed", &StructuredLightSensor::seed)
        .def("__repr__", [](const StructuredLightSensor& s) {
            return "zraster.StructuredLightSensor(baseline=" + std::to_string(s.baseline) +
                   ", disparity_step=" + std::to_string(s.disparity_step) +
                   ", min_range=" + std::to_string(s.min_range) +
                   ", max_range=" + std::to_string(s.max_range) +
                   ", max_incidence=" + std::to_string(s.max_incidence_degrees) +
                   ", noise=" + std::to_string(s.noise) + ", seed=" + std::to_string(s.seed) + ")";
        });

    m.def(
        "unproject",
        [](const py::object& z_object, const py::object& camera_object) {
            if (!py::isinstance<Camera>(camera_object))
                type_error("camera", "a zraster.Camera", camera_object);
            const Camera camera = camera_object.cast<Camera>();
            if (!py::isinstance<py::array>(z_object))
                type_error("z", "a (H, W) numpy array", z_object);
            const auto z =
                py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(z_object);
            if (!z || z.ndim() != 2)
                input_error("z", "must be a (H, W) array of metric depths (the 'z' output)");
            const int height = image_side(py::int_(z.shape(0)), "z's height");
            const int width = image_side(py::int_(z.shape(1)), "z's width");
            PointCloud cloud;
            {
                py::gil_scoped_release release;
                cloud = unproject(camera, width, height,
                                  {z.data(), std::size_t(width) * std::size_t(height)});
            }
            py::array_t<float> points({py::ssize_t(cloud.positions.size()), py::ssize_t(3)});
            if (!cloud.positions.empty())
                std::memcpy(points.mutable_data(), cloud.positions.data(),
                            cloud.positions.size() * sizeof(glm::vec3));
            return points;
        },
        "z"_a, "camera"_a,
        R"(The world-space points of a z image (the 'z' output): one per pixel with z > 0, in
row-major pixel order, as an (N, 3) float32 array. Each is the point at depth z on the ray
through the pixel's sample (its centre; OpenCV's (u, v) = (column, row)) of `camera`, the camera
the frame was rendered with (for Camera.fit, the same width and height).)");
}

}  // namespace zraster::python
