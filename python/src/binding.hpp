// What the binding's files share: the Python-side objects (Mesh, Scene, Camera, Renderer) and
// the functions that register them in the module.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/material.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/scene.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
// The std::vector/std::string conversions, the same in every file that converts them (a file
// without them would compile and fail at run time: "Unregistered type").
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace zraster::python {

namespace py = pybind11;

// A triangle mesh over numpy arrays: the arrays the caller passed when their dtype and layout fit
// a MeshView (float32 rows of contiguous floats, 16- or 32-bit contiguous indices), copies
// otherwise. The arrays are kept referenced, so the view stays valid while the Mesh lives.
struct PyMesh {
    py::array positions, normals, uvs, colors, indices;  // normals, uvs, colors: None if absent
    MeshView view;                                       // into the arrays above
    // From `color`, `texture`, `alpha_mode`, `alpha_cutoff` or `double_sided` (the texture is the
    // material's own
    // copy of the image); none of them: the scene's default material.
    std::optional<Material> material;
    std::string name;
    bool positions_copied = false, normals_copied = false, uvs_copied = false,
         colors_copied = false, indices_copied = false;
    bool normals_computed = false;
};

// A scene: an owning zraster::Scene (load()), or instances of Meshes and of other Scenes (kept
// referenced), all seen through the same views. Immutable once made, so its views stay valid while
// a frame renders without the GIL.
struct PyScene {
    std::shared_ptr<const Scene> owned;  // load(): the loaded scene; null for Mesh scenes
    std::vector<py::object> keep;        // the Mesh and Scene objects the views point into
    std::vector<MeshView> meshes;
    std::vector<Material> materials{Material{}};
    std::vector<InstanceView> instances;
    std::string spec;  // what load() was given (a builtin scene has its own default camera)
    std::vector<std::string> warnings;

    SceneView view() const { return {meshes, materials, instances}; }
    // World-space vertices of every instance, as Scene::world_positions computes them (so that
    // the default camera is the command's, bit for bit).
    std::vector<glm::vec3> world_positions() const;
    // An owning copy, for the frames only an owning scene can draw (visibility algorithms other
    // than the z-buffer, antialiasing). Made once, with the GIL held.
    const Scene& owning() const;
    std::size_t triangle_count() const;  // over instances
    std::size_t vertex_count() const;    // over instances

  private:
    mutable std::shared_ptr<const Scene> owning_copy_;
};

// The scene a render call draws: a Scene, or a Mesh as a one-instance scene.
std::shared_ptr<const PyScene> scene_argument(py::handle object, const char* argument);

// Material::alpha_mode as Python names it: "opaque", "mask", "blend".
const char* alpha_mode_name(AlphaMode mode);
// One of those names, else TypeError / InputError naming the argument.
AlphaMode alpha_mode_argument(py::handle object, const std::string& argument);

void bind_errors(py::module_& m);
void bind_material(py::module_& m);
void bind_mesh(py::module_& m);
void bind_scene(py::module_& m);
void bind_camera(py::module_& m);
void bind_renderer(py::module_& m);
void bind_batch(py::module_& m);

}  // namespace zraster::python
