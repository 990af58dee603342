// zraster.Camera: the cameras of zraster/camera.hpp, and the command's framings (fit, orbit)
// made by the command's own code, so that they are its cameras exactly.
#include <zraster/precision.hpp>

#include <pybind11/stl.h>

#include <charconv>
#include <cmath>

#include "arrays.hpp"
#include "binding.hpp"
#include "errors.hpp"
#include "render_arguments.hpp"

namespace zraster::python {
namespace {

using namespace pybind11::literals;

// A number for a flag's text: the shortest form that reads back as the same double.
std::string exact_text(double v) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, result.ptr);
}

// A number as given (non-finite values included: the camera's own checks name the field).
double real(py::handle object, const std::string& argument) {
    if (py::isinstance<py::bool_>(object) ||
        !(py::isinstance<py::int_>(object) || py::isinstance<py::float_>(object) ||
          py::hasattr(object, "__float__")))
        type_error(argument, "a number", object);
    return py::float_(py::reinterpret_borrow<py::object>(object)).cast<double>();
}

CameraConvention convention_of(const std::string& name) {
    if (name == "opencv") return CameraConvention::OpenCV;
    if (name == "opengl") return CameraConvention::OpenGL;
    input_error("convention", "expected 'opencv' or 'opengl', got '" + name + "'");
}

// The camera `zraster render` uses for `scene` with these arguments (and no others).
Camera command_camera(const PyScene& scene, cli::RenderArguments a, int width, int height) {
    a.size = std::to_string(width) + "x" + std::to_string(height);
    a.scene = scene.spec;
    const std::vector<glm::vec3> world = scene.world_positions();
    return *cli::make_render_options(a, world, std::nullopt).camera;
}

Camera look_at_camera(const py::object& eye, const py::object& target, const py::object& up,
                      const py::object& fovy, const py::object& near, const py::object& far,
                      bool reversed_z, bool infinite_far, const py::object& ortho_height) {
    Camera c;
    c.eye = glm::dvec3(vector_n(eye, 3, "eye"));
    c.target = glm::dvec3(vector_n(target, 3, "target"));
    c.up = glm::dvec3(vector_n(up, 3, "up"));
    c.fovy_degrees = finite_number(fovy, "fovy");
    c.near = finite_number(near, "near");
    c.far = finite_number(far, "far");
    c.reversed_z = reversed_z;
    c.infinite_far = infinite_far;
    if (!ortho_height.is_none()) {
        c.projection = Camera::Projection::Orthographic;
        c.ortho_height = finite_number(ortho_height, "ortho_height");
        if (!(c.ortho_height > 0.0)) input_error("ortho_height", "must be positive");
    }
    if (!(c.fovy_degrees > 0.0 && c.fovy_degrees < 180.0))
        input_error("fovy", "must be in (0, 180) degrees, got " + exact_text(c.fovy_degrees));
    if (!(c.near > 0.0)) input_error("near", "must be positive, got " + exact_text(c.near));
    if (!infinite_far && !(c.far > c.near))
        input_error("far", "must be greater than near, got " + exact_text(c.far));
    check_camera(c, 1, 1);
    return c;
}

// The argument a message of Camera::from_intrinsics is about ("camera intrinsics fx must be
// positive", "camera_to_world is singular"), for InputError.source.
std::string intrinsics_argument(const std::string& cause) {
    if (cause.find("camera_to_world") != std::string::npos) return "pose";
    for (const char* field : {"fx", "fy", "cx", "cy", "width", "near", "far"})
        if (cause.find(std::string(" ") + field + " ") != std::string::npos) return field;
    return "";
}

py::dict intrinsics_dict(const Intrinsics& k) {
    py::dict d;
    d["fx"] = k.fx, d["fy"] = k.fy, d["cx"] = k.cx, d["cy"] = k.cy;
    d["width"] = k.width, d["height"] = k.height, d["near"] = k.near, d["far"] = k.far;
    return d;
}

}  // namespace

void bind_camera(py::module_& m) {
    py::class_<Camera>(m, "Camera", R"(A camera: where it is, where it looks, and its projection.

Made by the factories: Camera.fit (the command's default framing), Camera.orbit,
Camera.look_at, Camera.from_intrinsics, Camera.from_matrices. OpenGL conventions (right-handed,
looking down -z; window depth 0 at near, 1 at far, or the reverse with reversed_z). Immutable:
make a new one to change it.)")
        .def_static(
            "fit",
            [](const py::object& scene, const py::object& width, const py::object& height) {
                const int w = image_side(width, "width"), h = image_side(height, "height");
                return command_camera(*scene_argument(scene, "scene"), {}, w, h);
            },
            "scene"_a, "width"_a, "height"_a,
            R"(The camera `zraster render` uses when given no camera flags, exactly: a builtin
scene's own camera, else the benchmark framing of the scene's bounding sphere (60 degree field of
view, eye along (1, 1, 2) from its center, near and far from its radius). The framing depends
on the scene only; width and height (checked) are the image's, whose aspect the render applies.)")
        .def_static(
            "orbit",
            [](const py::object& scene, const py::object& azimuth, const py::object& elevation,
               const py::object& width, const py::object& height, const py::object& distance) {
                const int w = image_side(width, "width"), h = image_side(height, "height");
                const double d = finite_number(distance, "distance");
                if (!(d > 0.0)) input_error("distance", "must be positive");
                cli::RenderArguments a;
                a.orbit = exact_text(finite_number(azimuth, "azimuth")) + "," +
                          exact_text(finite_number(elevation, "elevation")) + "," + exact_text(d);
                return command_camera(*scene_argument(scene, "scene"), a, w, h);
            },
            "scene"_a, "azimuth"_a, "elevation"_a, "width"_a, "height"_a, "distance"_a = 2.0,
            R"(The camera of `zraster render --orbit AZIMUTH,ELEVATION,DISTANCE`: circling the
scene's bounding-sphere center at `distance` scene radii (2.0 is the default framing's
distance), azimuth in degrees around +y from +z towards +x, elevation in degrees above the xz
plane; near and far hug the sphere.)")
        .def_static("look_at", &look_at_camera, "eye"_a, "target"_a,
                    "up"_a = py::make_tuple(0.0, 1.0, 0.0), "fovy"_a = 60.0, "near"_a = 0.1,
                    "far"_a = 100.0, "reversed_z"_a = false, "infinite_far"_a = false,
                    "ortho_height"_a = py::none(),
                    R"(A camera at `eye` looking at `target` (gluLookAt), `up` the up direction.

fovy: vertical field of view in degrees (perspective). ortho_height: given, an orthographic
camera whose view volume is this tall (world units) instead. near, far: clip distances along the
view axis (far is ignored with infinite_far). reversed_z: window depth 1 at near, 0 at far, with
the GREATER depth test by default. Raises InputError naming a non-finite or out-of-range value.)")
        .def_static(
            "from_intrinsics",
            [](const py::object& fx, const py::object& fy, const py::object& cx,
               const py::object& cy, const py::object& width, const py::object& height,
               const py::object& near, const py::object& far, const py::object& pose,
               const std::string& convention) {
                Intrinsics k;
                k.fx = real(fx, "fx"), k.fy = real(fy, "fy");
                k.cx = real(cx, "cx"), k.cy = real(cy, "cy");
                k.width = image_side(width, "width"), k.height = image_side(height, "height");
                k.near = real(near, "near"), k.far = real(far, "far");
                const glm::dmat4 camera_to_world =
                    pose.is_none() ? glm::dmat4(1.0) : matrix4(pose, "pose");
                const CameraConvention axes = convention_of(convention);
                try {
                    return Camera::from_intrinsics(k, camera_to_world, axes);
                } catch (const InputError& e) {
                    throw InputError(intrinsics_argument(e.cause()), e.cause());
                }
            },
            "fx"_a, "fy"_a, "cx"_a, "cy"_a, "width"_a, "height"_a, "near"_a = 0.1, "far"_a = 100.0,
            "pose"_a = py::none(), "convention"_a = "opencv",
            R"(A pinhole camera from intrinsics (C++ Camera::from_intrinsics).

fx, fy: focal lengths in pixels; cx, cy: principal point in pixels; width, height: the image
size it is for (the Renderer must have this size). near, far: clip distances along the optical
axis (far may be inf). pose: the 4x4 camera-to-world matrix (the camera's axes and position in
world space; default identity). convention "opencv": camera x right, y down, z forward, pixel
centers at integer (u, v), v = 0 the top row, so a point on the optical axis lands at (cx, cy).
"opengl": x right, y up, looking down -z, pixel centers at half-integers from the bottom-left.
Raises InputError naming the field for non-finite values, fx or fy <= 0, not 0 < near < far, a
singular or non-affine pose.)")
        .def_static(
            "from_matrices",
            [](const py::object& view, const py::object& projection, const std::string& depth_range,
               bool reversed_z) {
                ClipDepthRange range{};
                if (depth_range == "-1..1")
                    range = ClipDepthRange::NegativeOneToOne;
                else if (depth_range == "0..1")
                    range = ClipDepthRange::ZeroToOne;
                else
                    input_error("depth_range",
                                "expected '-1..1' (OpenGL) or '0..1' (Direct3D), got '" +
                                    depth_range + "'");
                return Camera::from_matrices(matrix4(view, "view"),
                                             matrix4(projection, "projection"), range, reversed_z);
            },
            "view"_a, "projection"_a, "depth_range"_a = "-1..1", "reversed_z"_a = false,
            R"(A camera from a 4x4 view matrix (world to OpenGL eye space) and a projection
matrix whose clip z spans depth_range ("-1..1": OpenGL, "0..1": Direct3D); reversed_z: the
projection maps near to depth 1. See C++ Camera::from_matrices for the projections accepted.)")
        .def_property_readonly(
            "eye", [](const Camera& c) { return to_numpy(c.position()); },
            "The eye's world position.")
        .def_property_readonly(
            "target", [](const Camera& c) { return to_numpy(c.target); },
            "The point looked at (for cameras from matrices or intrinsics: eye + view direction).")
        .def_property_readonly(
            "up", [](const Camera& c) { return to_numpy(c.up); }, "The up direction given.")
        .def_property_readonly(
            "view_direction", [](const Camera& c) { return to_numpy(c.view_direction()); },
            "The unit view direction in world space.")
        .def_property_readonly(
            "fovy", [](const Camera& c) { return c.fovy_degrees; },
            "Vertical field of view in degrees (perspective look-at cameras).")
        .def_property_readonly(
            "near", [](const Camera& c) { return c.near; },
            "Near clip distance along the view axis (NaN for some cameras from matrices).")
        .def_property_readonly(
            "far", [](const Camera& c) { return c.far; },
            "Far clip distance (inf with an infinite far plane from intrinsics).")
        .def_property_readonly(
            "reversed_z", [](const Camera& c) { return c.reversed_z; },
            "Window depth 1 at near and 0 at far (the GREATER test by default).")
        .def_property_readonly(
            "infinite_far", [](const Camera& c) { return c.infinite_far; },
            "The far plane at infinity.")
        .def_property_readonly("orthographic", &Camera::is_orthographic,
                               "An orthographic projection (else perspective).")
        .def_property_readonly(
            "ortho_height", [](const Camera& c) { return c.ortho_height; },
            "Height of an orthographic view volume in world units.")
        .def(
            "view_matrix", [](const Camera& c) { return to_numpy(c.view()); },
            "The 4x4 world-to-eye matrix (OpenGL eye space, looking down -z).")
        .def(
            "projection_matrix",
            [](const Camera& c, const py::object& width, const py::object& height) {
                const int w = image_side(width, "width"), h = image_side(height, "height");
                return to_numpy(c.projection_matrix(double(w) / double(h)));
            },
            "width"_a, "height"_a, "The 4x4 projection matrix for an image of width x height.")
        .def(
            "intrinsics",
            [](const Camera& c, const py::object& width, const py::object& height,
               const std::string& convention) {
                return intrinsics_dict(c.intrinsics(image_side(width, "width"),
                                                    image_side(height, "height"),
                                                    convention_of(convention)));
            },
            "width"_a, "height"_a, "convention"_a = "opencv",
            "fx, fy, cx, cy, width, height, near, far of this camera for an image of width x "
            "height (a dict), exactly what from_intrinsics would take to make it.")
        .def(
            "camera_to_world",
            [](const Camera& c, const std::string& convention) {
                return to_numpy(c.camera_to_world(convention_of(convention)));
            },
            "convention"_a = "opencv", "The pose: the inverse view matrix, in `convention`'s axes.")
        .def("__repr__", [](const Camera& c) {
            const glm::dvec3 e = c.position(), d = c.view_direction();
            std::string kind = c.pinhole            ? "pinhole"
                               : c.given_projection ? "from matrices"
                               : c.is_orthographic()
                                   ? "orthographic"
                                   : "perspective fovy " + exact_text(c.fovy_degrees);
            return "<zraster.Camera " + kind + ", eye (" + exact_text(e.x) + ", " +
                   exact_text(e.y) + ", " + exact_text(e.z) + "), direction (" + exact_text(d.x) +
                   ", " + exact_text(d.y) + ", " + exact_text(d.z) + "), near " +
                   exact_text(c.near) + ", far " + exact_text(c.far) + ">";
        });
}

}  // namespace zraster::python
