// zraster.Renderer: frames rendered straight into numpy arrays, without the GIL.
#include <zraster/precision.hpp>

#include <pybind11/stl.h>
#include <tbb/task_arena.h>

#include <array>
#include <cstring>
#include <limits>
#include <mutex>

#include "arrays.hpp"
#include "binding.hpp"
#include "command_line.hpp"
#include "depth_camera_outputs.hpp"
#include "depth_outputs.hpp"
#include "errors.hpp"
#include "flag_effects.hpp"
#include "io/drawable_check.hpp"
#include "options.hpp"
#include "recycled_arrays.hpp"

namespace zraster::python {
namespace {

using namespace pybind11::literals;

enum Output { kColor, kRgba, kDepth, kZ, kRange, kNormal, kInstanceId, kPrimitiveId, kOutputCount };
constexpr const char* kOutputNames[kOutputCount] = {
    "color", "rgba", "depth", "z", "range", "normal", "instance_id", "primitive_id"};

// One Renderer is one zraster::Renderer, which draws one frame at a time: concurrent calls from
// several Python threads wait for each other on `mutex` (with the GIL released).
struct PyRenderer {
    int width = 0, height = 0, threads = 0;
    std::uint64_t max_pixels = RenderLimits{}.max_pixels;
    Renderer renderer;
    std::mutex mutex;
    RenderStats stats;  // of the last frame
    bool rendered = false;
    // The output arrays' memory, recycled from frame to frame; scratch images for z and range
    // when the frame's depth or normals are not outputs themselves (used under `mutex`).
    std::shared_ptr<ArrayPool> arrays = std::make_shared<ArrayPool>();
    std::vector<float> depth_scratch, z_scratch;
    std::vector<glm::vec3> normal_scratch;
    // z and range are computed from the frame in parallel, on this many threads (`threads`; 0:
    // every hardware thread), as the frame itself was.
    std::unique_ptr<tbb::task_arena> post_arena;
};

std::unique_ptr<PyRenderer> make_renderer(const py::object& width, const py::object& height,
                                          const py::object& threads, const py::object& max_pixels) {
    auto r = std::make_unique<PyRenderer>();
    r->width = image_side(width, "width");
    r->height = image_side(height, "height");
    // (0: every hardware thread.)
    const long long t = integer_in_range(threads, "threads", 0, 1 << 20);
    r->threads = cli::checked_thread_count("threads", int(t));
    r->post_arena = std::make_unique<tbb::task_arena>(
        r->threads > 0 ? r->threads : int(tbb::task_arena::automatic));
    if (!max_pixels.is_none()) {
        const long long limit =
            integer_in_range(max_pixels, "max_pixels", 1, std::numeric_limits<long long>::max());
        r->max_pixels = std::uint64_t(limit);
    }
    const std::uint64_t pixels = std::uint64_t(r->width) * std::uint64_t(r->height);
    if (pixels > r->max_pixels)
        input_error("width", std::to_string(r->width) + "x" + std::to_string(r->height) + " is " +
                                 std::to_string(pixels) + " pixels, more than max_pixels " +
                                 std::to_string(r->max_pixels));
    return r;
}

std::array<bool, kOutputCount> wanted_outputs(py::handle outputs, std::vector<Output>& order) {
    std::array<bool, kOutputCount> wanted{};
    const auto add = [&](py::handle item) {
        if (!py::isinstance<py::str>(item)) type_error("outputs", "output names (str)", item);
        const std::string name = item.cast<std::string>();
        for (int k = 0; k < kOutputCount; ++k)
            if (name == kOutputNames[k]) {
                if (wanted[std::size_t(k)])
                    input_error("outputs", "'" + name + "' given twice: give it once");
                order.push_back(Output(k));
                wanted[std::size_t(k)] = true;
                return;
            }
        input_error("outputs", "unknown output '" + name +
                                   "' (expected color, rgba, depth, z, range, normal, "
                                   "instance_id or primitive_id)");
    };
    if (py::isinstance<py::str>(outputs))
        add(outputs);
    else if (py::isinstance<py::sequence>(outputs) || py::isinstance<py::set>(outputs) ||
             py::isinstance<py::frozenset>(outputs))
        for (py::handle item : py::iter(outputs)) add(item);
    else
        type_error("outputs", "an output name or a sequence of them", outputs);
    if (order.empty()) input_error("outputs", "no output asked for");
    return wanted;
}

// The flags that place the camera, which a given camera replaces.
constexpr const char* kPlacementKeywords[] = {"eye", "target", "up", "orbit", "fovy", "ortho"};

template <class T>
py::array_t<T> image(ArrayPool& pool, int height, int width, int channels) {
    if (channels == 1) return pool.array<T>({py::ssize_t(height), py::ssize_t(width)});
    return pool.array<T>({py::ssize_t(height), py::ssize_t(width), py::ssize_t(channels)});
}

// Copies an image of zraster's into an output array of `pixels` elements of T (no Python calls:
// runs without the GIL).
template <class T>
void copy_target(const std::vector<T>& from, void* to, std::size_t pixels, const char* name,
                 const std::string& visibility) {
    if (from.size() != pixels)
        input_error("outputs", std::string("'") + name + "' is not available with visibility='" +
                                   visibility + "' and these options");
    std::memcpy(to, from.data(), pixels * sizeof(T));
}

py::dict stats_dict(const RenderStats& s) {
    py::dict d;
    d["instances"] = s.instances;
    d["instances_frustum_culled"] = s.instances_frustum_culled;
    d["instances_occlusion_culled"] = s.instances_occlusion_culled;
    d["triangles_in"] = s.triangles_in;
    d["triangles_trivially_rejected"] = s.triangles_trivially_rejected;
    d["triangles_non_finite"] = s.triangles_non_finite;
    d["triangles_clipped"] = s.triangles_clipped;
    d["triangles_backface_culled"] = s.triangles_backface_culled;
    d["triangles_degenerate"] = s.triangles_degenerate;
    d["triangles_no_coverage"] = s.triangles_no_coverage;
    d["triangles_rasterized"] = s.triangles_rasterized;
    d["fragments_passed"] = s.fragments_passed;
    d["fragments_shaded"] = s.fragments_shaded;
    d["fragments_alpha_discarded"] = s.fragments_alpha_discarded;
    d["fragments_blended"] = s.fragments_blended;
    d["pixels_blended"] = s.pixels_blended;
    d["deferred"] = s.deferred;
    d["simd_target"] = std::string(s.simd_target);
    d["setup_ms"] = s.setup_ms;
    d["raster_ms"] = s.raster_ms;
    d["total_ms"] = s.total_ms;
    return d;
}

py::dict render(PyRenderer& r, const py::object& scene_object, const py::object& camera_object,
                const py::object& outputs, const py::object& sensor_object,
                const py::kwargs& keywords) {
    const std::shared_ptr<const PyScene> scene = scene_argument(scene_object, "scene");
    // As the command refuses such files: an image of nothing is not a render.
    io::check_some_triangle_has_area(scene->view(), "scene");
    std::vector<Output> order;
    const std::array<bool, kOutputCount> wanted = wanted_outputs(outputs, order);
    DepthCameraImages depth_camera;
    depth_camera.sensor = sensor_argument(sensor_object);
    const bool metric = wanted[kZ] || wanted[kRange];
    if (depth_camera.sensor && !metric)
        input_error("sensor", "measures the 'z' and 'range' outputs: ask for one of them");
    RenderKeywords parsed =
        parse_render_keywords(keywords, r.width, r.height, r.threads, r.max_pixels);
    cli::RenderArguments& a = parsed.arguments;
    a.scene = scene->spec;
    std::optional<Camera> camera;
    if (!camera_object.is_none()) {
        if (!py::isinstance<Camera>(camera_object))
            type_error("camera", "a zraster.Camera or None", camera_object);
        camera = camera_object.cast<Camera>();
        for (const char* keyword : kPlacementKeywords)
            if (parsed.given.count(keyword))
                input_error(keyword,
                            "camera= is given, which places the camera: make the "
                            "Camera with it instead");
    }
    RenderOptions options;
    try {
        // Before the camera fit's copy of every instanced vertex.
        check_frame_memory(
            scene->spec, scene->vertex_count(), scene->triangle_count(), 0,
            {.max_frame_bytes = cli::parse_byte_size("--max-frame-bytes", a.max_frame_bytes_text)});
        const std::vector<glm::vec3> world =
            camera ? std::vector<glm::vec3>() : scene->world_positions();
        options = cli::make_render_options(a, world, camera);
        cli::check_frame_arguments(a);
        std::vector<std::string> warnings = cli::check_flags_take_effect(a);
        if (a.texture_filter != cli::RenderArguments{}.texture_filter || a.alpha_mode == "opaque" ||
            a.interpolation == "linear")
            for (std::string& w : cli::scene_flag_warnings(a, scene->owning(), wanted[kNormal]))
                warnings.push_back(std::move(w));
        for (const std::string& w : warnings)
            if (PyErr_WarnEx(PyExc_UserWarning, with_keyword_names(w).c_str(), 1) != 0)
                throw py::error_already_set();  // warnings turned into errors
    } catch (const LimitExceeded&) {
        throw;  // about the scene, naming its limit
    } catch (const InputError& e) {
        throw InputError(keyword_name(e.file()), with_keyword_names(e.cause()));
    }

    // The outputs, allocated here and written in place by the renderer.
    const int h = r.height, w = r.width;
    std::array<py::array, kOutputCount> arrays;
    TargetViews targets{w, h};
    if (wanted[kColor] || wanted[kRgba]) {
        arrays[kRgba] = image<std::uint8_t>(*r.arrays, h, w, 4);
        targets.color = static_cast<std::uint8_t*>(arrays[kRgba].mutable_data());
        // RGB is a view of the RGBA image: no copy (the alpha channel is opaque).
        arrays[kColor] = arrays[kRgba][py::make_tuple(py::ellipsis(), py::slice(0, 3, 1))];
    }
    if (wanted[kDepth]) {
        arrays[kDepth] = image<float>(*r.arrays, h, w, 1);
        targets.depth = static_cast<float*>(arrays[kDepth].mutable_data());
    }
    if (wanted[kNormal]) {
        arrays[kNormal] = image<float>(*r.arrays, h, w, 3);
        targets.normal = static_cast<glm::vec3*>(arrays[kNormal].mutable_data());
    }
    if (wanted[kInstanceId]) {
        arrays[kInstanceId] = image<std::int32_t>(*r.arrays, h, w, 1);
        targets.instance_id = static_cast<std::int32_t*>(arrays[kInstanceId].mutable_data());
    }
    if (wanted[kPrimitiveId]) {
        arrays[kPrimitiveId] = image<std::int32_t>(*r.arrays, h, w, 1);
        targets.primitive_id = static_cast<std::int32_t*>(arrays[kPrimitiveId].mutable_data());
    }
    // z and range come from the frame's depths (and, through a sensor, its normals): rendered
    // into the Renderer's scratch images (under its lock, below) when they are not outputs.
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    if (metric) {
        if (wanted[kZ]) {
            arrays[kZ] = image<float>(*r.arrays, h, w, 1);
            depth_camera.z = static_cast<float*>(arrays[kZ].mutable_data());
        }
        if (wanted[kRange]) {
            arrays[kRange] = image<float>(*r.arrays, h, w, 1);
            depth_camera.range = static_cast<float*>(arrays[kRange].mutable_data());
        }
    }

    const bool pipeline = cli::renders_with_pipeline(a);
    // Other algorithms draw owning scenes into their own targets, copied into the arrays.
    const Scene* owning = pipeline ? nullptr : &scene->owning();
    StructuredLightStats sensor_stats;
    try {
        py::gil_scoped_release release;
        const std::lock_guard<std::mutex> lock(r.mutex);
        if (metric) {
            if (!targets.depth) {
                r.depth_scratch.resize(pixels);
                targets.depth = r.depth_scratch.data();
            }
            if (depth_camera.sensor && !targets.normal) {
                r.normal_scratch.resize(pixels);
                targets.normal = r.normal_scratch.data();
            }
            if (!depth_camera.z) {
                r.z_scratch.resize(pixels);
                depth_camera.z = r.z_scratch.data();
            }
            depth_camera.depth = targets.depth;
            depth_camera.normal = targets.normal;
        }
        if (pipeline) {
            r.stats = r.renderer.render(scene->view(), options, targets);
        } else {
            options.color_target = targets.color != nullptr;
            options.normal_target = targets.normal != nullptr;
            options.id_targets = targets.instance_id != nullptr || targets.primitive_id != nullptr;
            const RenderResult result = cli::render_frame(a, *owning, options, nullptr, nullptr);
            const RenderTargets& t = result.targets;
            const std::size_t n = std::size_t(w) * std::size_t(h);
            if (targets.color) copy_target(t.color, targets.color, n * 4, "color", a.visibility);
            if (targets.depth) copy_target(t.depth, targets.depth, n, "depth", a.visibility);
            if (targets.normal) copy_target(t.normal, targets.normal, n, "normal", a.visibility);
            if (targets.instance_id)
                copy_target(t.instance_id, targets.instance_id, n, "instance_id", a.visibility);
            if (targets.primitive_id)
                copy_target(t.primitive_id, targets.primitive_id, n, "primitive_id", a.visibility);
            r.stats = result.stats;
        }
        if (metric)
            r.post_arena->execute([&] {
                sensor_stats =
                    depth_camera_images(depth_camera, scene->view(), options, r.stats.camera);
            });
        r.rendered = true;
    } catch (const LimitExceeded& e) {
        // A render budget (max_painter_comparisons, max_bin_bytes, ...): still a LimitExceeded,
        // e.limit the keyword that raises it.
        throw LimitExceeded(keyword_name(e.file()), e.limit(), with_keyword_names(e.cause()));
    } catch (const InputError& e) {
        throw InputError(keyword_name(e.file()), with_keyword_names(e.cause()));
    }
    if (const auto warning = cli::sensor_warning(sensor_stats))
        if (PyErr_WarnEx(PyExc_UserWarning, (scene->spec + ": " + *warning).c_str(), 1) != 0)
            throw py::error_already_set();
    py::dict result;
    for (const Output o : order) result[kOutputNames[o]] = arrays[o];
    return result;
}

const char* const kRenderDoc =
    R"(Renders one frame of `scene` and returns {output name: numpy array}.

scene: a zraster.Scene, or a zraster.Mesh (drawn as a one-instance scene).
camera: a zraster.Camera, or None for the command's default framing (Camera.fit) placed by the
  camera keywords (eye, target, up, orbit, fovy, ortho), which cannot be combined with a camera.
  near, far, reversed_z and infinite_far apply to either.
outputs: the output names wanted, in the order of the returned dict:

  name          shape       dtype    contents (row 0 is the image's top row)
  color         (H, W, 3)   uint8    RGB, as `zraster render -o F.png` writes it
  rgba          (H, W, 4)   uint8    RGBA (alpha 255)
  depth         (H, W)      float32  window depth as `--depth-out F.npy` writes it: 0..1, the
                                     clear value (1.0, or 0.0 with reversed_z) where empty
  z             (H, W)      float32  metric depth along the optical axis in scene units, 0 where
                                     empty (the depth-camera convention; `--z-out F.npy`)
  range         (H, W)      float32  distance from the eye to the surface, 0 where empty
                                     (`--range-out`)
  normal        (H, W, 3)   float32  world-space unit shading normal, zeros where empty
  instance_id   (H, W)      int32    index of the instance drawn there, -1 where empty
  primitive_id  (H, W)      int32    triangle index within that instance's mesh, -1 where empty

sensor: None or "ideal" (exact depth), "kinect" or a zraster.StructuredLightSensor: z and range
  as a structured-light sensor measures them (0 where it measures nothing); the other outputs
  are the ideal frame's. zraster.unproject(out["z"], camera) gives the point cloud.

The renderer writes into the returned arrays: nothing is copied afterwards (`color` is a view of
the RGBA image, `color` and `rgba` share memory). Each call returns new arrays, which the caller
owns; the memory of arrays the caller has freed is reused for later frames of this Renderer. Frames the
pipeline does not draw itself (visibility other than "zbuffer", aa > 1, msaa) are drawn into
zraster's own images and copied, and a Scene of Meshes is copied once into an owning scene for
them. The GIL is released while the frame renders; calls on one Renderer from several threads
wait for each other (a Renderer draws one frame at a time), separate Renderers run concurrently.

Options: the flags of `zraster render` that set the camera and the pipeline, as keywords (dashes
become underscores) with the flags' values: strings for named values ("phong"), numbers, and
sequences of numbers for the X,Y,Z-style values (or the flag's own text, "1,2,3"); a flag without
a value is a bool. An unknown keyword raises TypeError; a bad value raises InputError naming the
option and the cause. The keywords (the command's help text):

)";

}  // namespace

void bind_renderer(py::module_& m) {
    static const std::string render_doc = std::string(kRenderDoc) + render_keywords_doc();
    py::class_<PyRenderer>(m, "Renderer", R"(A zraster::Renderer for images of width x height.

Renderer(width, height, threads=0, max_pixels=None)

It keeps its working memory and its thread pool (`threads` worker threads; 0: every hardware
thread) from frame to frame: keep one for many frames. max_pixels raises the limit on
width * height (the command's --max-pixels). One frame at a time: concurrent render() calls on
one Renderer are serialized.)")
        .def(py::init(&make_renderer), "width"_a, "height"_a, "threads"_a = 0,
             "max_pixels"_a = py::none())
        .def("render", &render, "scene"_a, "camera"_a = py::none(),
             "outputs"_a = py::make_tuple("color", "depth"), "sensor"_a = py::none(),
             render_doc.c_str())
        .def_property_readonly("width", [](const PyRenderer& r) { return r.width; })
        .def_property_readonly("height", [](const PyRenderer& r) { return r.height; })
        .def_property_readonly("threads", [](const PyRenderer& r) { return r.threads; })
        .def_property_readonly(
            "stats",
            [](PyRenderer& r) -> py::object {
                RenderStats stats;
                bool rendered = false;
                {
                    // Waits for a frame another thread is rendering, without holding the GIL.
                    py::gil_scoped_release release;
                    const std::lock_guard<std::mutex> lock(r.mutex);
                    stats = r.stats;
                    rendered = r.rendered;
                }
                if (!rendered) return py::none();
                return stats_dict(stats);
            },
            "Counts and times of the last frame (a dict), None before the first.")
        .def("__repr__", [](const PyRenderer& r) {
            return "<zraster.Renderer " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                   ", threads " + std::to_string(r.threads) + ">";
        });
    m.attr("RENDER_OPTIONS") = py::tuple(render_keyword_names());
    m.attr("_render_options_doc") = render_keywords_doc();
}

}  // namespace zraster::python
