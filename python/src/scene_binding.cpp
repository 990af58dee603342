// zraster.Scene and zraster.load(): scenes from files, procedural specs or Meshes.
#include <zraster/load.hpp>
#include <zraster/scenes.hpp>

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "arrays.hpp"
#include "binding.hpp"
#include "command_line.hpp"
#include "errors.hpp"

namespace zraster::python {
namespace {

using namespace pybind11::literals;

const char* float_bytes(const AttributeView& view, std::size_t i, std::size_t size) {
    return reinterpret_cast<const char*>(view.data) + i * (view.stride ? view.stride : size);
}

constexpr const char* kItemExpected = "a Mesh, a Scene, or a (Mesh or Scene, 4x4 transform) pair";

// A transform that places an item: finite (matrix4) and invertible, since normals are
// transformed by its inverse transpose.
glm::dmat4 item_transform(py::handle object, const std::string& argument) {
    const glm::dmat4 transform = matrix4(object, argument);
    const double determinant = glm::determinant(transform);
    if (!(determinant != 0.0 && std::isfinite(determinant)))
        input_error(argument, "the matrix is singular (determinant " + std::to_string(determinant) +
                                  "): it has no inverse");
    return transform;
}

// A Scene's instances placed by `transform` on top of their own transforms (transform applied
// last), in the Scene's order; its meshes and materials are added once however often it is
// given (`first_mesh`: where its meshes start, or npos the first time).
void add_scene(PyScene& scene, const PyScene& item, const glm::dmat4* transform,
               std::size_t& first_mesh) {
    if (first_mesh == std::size_t(-1)) {
        first_mesh = scene.meshes.size();
        const auto first_material = std::uint32_t(scene.materials.size());
        scene.materials.insert(scene.materials.end(), item.materials.begin(), item.materials.end());
        for (MeshView view : item.meshes) {
            view.material += first_material;
            scene.meshes.push_back(view);
        }
    }
    for (InstanceView instance : item.instances) {
        instance.mesh += std::uint32_t(first_mesh);
        if (transform != nullptr)
            instance.transform = glm::mat4(*transform * glm::dmat4(instance.transform));
        scene.instances.push_back(instance);
    }
}

std::shared_ptr<PyScene> scene_from_items(const py::iterable& items) {
    auto scene = std::make_shared<PyScene>();
    // Each distinct Mesh's mesh index, and where each distinct Scene's meshes start.
    std::vector<std::pair<const PyMesh*, std::size_t>> meshes_seen;
    std::vector<std::pair<const PyScene*, std::size_t>> scenes_seen;
    std::size_t position = 0;
    for (py::handle item : items) {
        const std::string argument = "items[" + std::to_string(position++) + "]";
        py::handle object = item;
        std::optional<glm::dmat4> transform;
        if (py::isinstance<py::tuple>(item) || py::isinstance<py::list>(item)) {
            const auto pair = py::reinterpret_borrow<py::sequence>(item);
            if (py::len(pair) != 2) type_error(argument, kItemExpected, item);
            object = pair[0];
            if (!py::isinstance<PyMesh>(object) && !py::isinstance<PyScene>(object))
                type_error(argument, kItemExpected, object);
            transform = item_transform(pair[1], argument + " transform");
        }
        if (py::isinstance<PyScene>(object)) {
            const auto& item_scene = object.cast<const PyScene&>();
            auto found = std::find_if(scenes_seen.begin(), scenes_seen.end(),
                                      [&](const auto& s) { return s.first == &item_scene; });
            if (found == scenes_seen.end()) {
                scene->keep.push_back(py::reinterpret_borrow<py::object>(object));
                scenes_seen.emplace_back(&item_scene, std::size_t(-1));
                found = scenes_seen.end() - 1;
            }
            add_scene(*scene, item_scene, transform ? &*transform : nullptr, found->second);
            continue;
        }
        if (!py::isinstance<PyMesh>(object)) type_error(argument, kItemExpected, object);
        const auto& mesh = object.cast<const PyMesh&>();
        auto found = std::find_if(meshes_seen.begin(), meshes_seen.end(),
                                  [&](const auto& s) { return s.first == &mesh; });
        if (found == meshes_seen.end()) {
            meshes_seen.emplace_back(&mesh, scene->meshes.size());
            found = meshes_seen.end() - 1;
            scene->keep.push_back(py::reinterpret_borrow<py::object>(object));
            MeshView view = mesh.view;
            view.name = mesh.name;
            if (mesh.material) {
                view.material = std::uint32_t(scene->materials.size());
                scene->materials.push_back(*mesh.material);
            }
            scene->meshes.push_back(view);
        }
        InstanceView instance;
        instance.mesh = std::uint32_t(found->second);
        instance.transform = glm::mat4(transform.value_or(glm::dmat4(1.0)));
        scene->instances.push_back(instance);
    }
    return scene;
}

std::shared_ptr<PyScene> scene_from_owned(std::shared_ptr<const Scene> owned, std::string spec,
                                          std::vector<std::string> warnings) {
    auto scene = std::make_shared<PyScene>();
    view_of(*owned, scene->meshes, scene->instances);
    scene->materials = owned->materials;
    scene->warnings = std::move(warnings);
    scene->spec = std::move(spec);
    scene->owned = std::move(owned);
    return scene;
}

std::shared_ptr<PyScene> load(const py::object& path_object, const std::string& isolation,
                              bool allow_outside_references, const py::object& max_instances,
                              const py::object& max_triangles, const py::object& max_texture_side,
                              const py::object& max_texture_bytes,
                              const py::object& max_geometry_bytes,
                              const py::object& max_triangulation_work,
                              const py::object& max_materials) {
    if (!py::isinstance<py::str>(path_object) && !py::hasattr(path_object, "__fspath__"))
        type_error("path", "a str or os.PathLike", path_object);
    const auto os = py::module_::import("os");
    const auto path = os.attr("fspath")(path_object);
    if (!py::isinstance<py::str>(path)) type_error("path", "a str path", path);
    // The file system's bytes for the name, as Python's open() uses them: a name that is not
    // UTF-8 (a surrogate-escaped byte, '\udcff') is a valid path, not a conversion error.
    const std::string spec = os.attr("fsencode")(path).cast<std::string>();
    // The system would read the path only up to it (Python's own open() refuses it too).
    if (spec.find('\0') != std::string::npos)
        input_error("path", "contains a NUL character: no file has such a name");
    LoadOptions options;
    if (isolation == "worker")
        options.isolation = LoadIsolation::WorkerProcess;
    else if (isolation == "in-process")
        options.isolation = LoadIsolation::InProcess;
    else
        input_error("isolation", "expected 'worker' or 'in-process', got '" + isolation + "'");
    // The command's ranges (docs/limits.md).
    constexpr long long kMost = std::numeric_limits<long long>::max();
    options.allow_outside_references = allow_outside_references;
    options.max_instances =
        std::size_t(integer_in_range(max_instances, "max_instances", 1, 1'000'000'000));
    options.max_triangles =
        std::size_t(integer_in_range(max_triangles, "max_triangles", 1, 1LL << 40));
    options.max_texture_side =
        int(integer_in_range(max_texture_side, "max_texture_side", 1, 1 << 16));
    // Bytes, or a size as the command writes it ("512M", "2G"), as Renderer's max_frame_bytes.
    const auto byte_count = [&](const py::object& value, const char* name) {
        if (py::isinstance<py::str>(value))
            return std::size_t(cli::parse_byte_size(name, value.cast<std::string>()));
        return std::size_t(integer_in_range(value, name, 1, kMost));
    };
    options.max_texture_bytes = byte_count(max_texture_bytes, "max_texture_bytes");
    options.max_geometry_bytes = byte_count(max_geometry_bytes, "max_geometry_bytes");
    options.max_triangulation_work = std::uint64_t(
        integer_in_range(max_triangulation_work, "max_triangulation_work", 1, 1LL << 40));
    options.max_materials =
        std::size_t(integer_in_range(max_materials, "max_materials", 1, 1'000'000'000));
    std::shared_ptr<const Scene> owned;
    std::vector<std::string> warnings;
    {
        py::gil_scoped_release release;
        owned = std::make_shared<const Scene>(is_procedural_spec(spec)
                                                  ? make_procedural_scene(spec)
                                                  : load_scene(spec, options, &warnings));
    }
    for (const std::string& warning : warnings)  // each names the file
        warn_load(warning.starts_with(spec) ? warning : spec + ": " + warning);
    return scene_from_owned(std::move(owned), spec, std::move(warnings));
}

}  // namespace

std::vector<glm::vec3> PyScene::world_positions() const {
    if (owned) return owned->world_positions();
    std::vector<glm::vec3> out;
    for (const InstanceView& instance : instances) {
        const AttributeView& p = meshes[instance.mesh].positions;
        for (std::size_t i = 0; i < p.count; ++i) {
            glm::vec3 v;
            std::memcpy(&v, float_bytes(p, i, 12), 12);
            // As Scene::world_positions: the same float operations, so the same bits.
            const glm::vec4 q = instance.transform * glm::vec4(v, 1.0f);
            out.push_back(glm::vec3(q) / q.w);
        }
    }
    return out;
}

std::size_t PyScene::triangle_count() const {
    std::size_t n = 0;
    for (const InstanceView& instance : instances) n += meshes[instance.mesh].indices.count / 3;
    return n;
}

std::size_t PyScene::vertex_count() const {
    std::size_t n = 0;
    for (const InstanceView& instance : instances) n += meshes[instance.mesh].positions.count;
    return n;
}

const Scene& PyScene::owning() const {
    if (owned) return *owned;
    if (owning_copy_) return *owning_copy_;
    auto scene = std::make_shared<Scene>();
    scene->materials = materials;
    scene->name = spec;
    for (const MeshView& view : meshes) {
        Mesh mesh;
        mesh.name = std::string(view.name);
        mesh.material = view.material;
        mesh.positions.resize(view.positions.count);
        for (std::size_t i = 0; i < view.positions.count; ++i)
            std::memcpy(&mesh.positions[i], float_bytes(view.positions, i, 12), 12);
        mesh.normals.resize(view.normals.count);
        for (std::size_t i = 0; i < view.normals.count; ++i)
            std::memcpy(&mesh.normals[i], float_bytes(view.normals, i, 12), 12);
        mesh.uvs.resize(view.uvs.count);
        for (std::size_t i = 0; i < view.uvs.count; ++i)
            std::memcpy(&mesh.uvs[i], float_bytes(view.uvs, i, 8), 8);
        mesh.colors.resize(view.colors.count);
        for (std::size_t i = 0; i < view.colors.count; ++i)
            std::memcpy(&mesh.colors[i], float_bytes(view.colors, i, 16), 16);
        mesh.indices.resize(view.indices.count);
        for (std::size_t i = 0; i < view.indices.count; ++i)
            mesh.indices[i] = view.indices.type == IndexType::UInt16
                                  ? static_cast<const std::uint16_t*>(view.indices.data)[i]
                                  : static_cast<const std::uint32_t*>(view.indices.data)[i];
        update_bounds(mesh);
        scene->meshes.push_back(std::move(mesh));
    }
    for (const InstanceView& view : instances) {
        Instance instance;
        instance.mesh = view.mesh;
        instance.transform = view.transform;
        instance.shading = view.shading;
        scene->instances.push_back(instance);
    }
    owning_copy_ = scene;
    return *scene;
}

std::shared_ptr<const PyScene> scene_argument(py::handle object, const char* argument) {
    if (py::isinstance<PyScene>(object)) return object.cast<std::shared_ptr<PyScene>>();
    if (py::isinstance<PyMesh>(object)) return scene_from_items(py::make_tuple(object));
    type_error(argument, "a zraster.Scene or zraster.Mesh", object);
}

void bind_scene(py::module_& m) {
    py::class_<PyScene, std::shared_ptr<PyScene>>(m, "Scene", R"(Meshes placed in the world.

Scene(items): each item is a Mesh or a Scene (a loaded one, or another Scene of items), alone
or as an (item, transform) pair, transform a 4x4 object-to-world matrix acting on column vectors
(p_world = transform @ [x, y, z, 1]). A Scene item brings its instances, in its order, each
placed by `transform @ its own transform`, and its meshes and materials (textures included) as
they are. Instance ids (the instance_id output) follow the items' order: a Scene item's
instances take the next len(scene) ids. A Mesh or Scene given more than once is one mesh (or set
of meshes) drawn several times (instances). The Scene keeps its items referenced (their arrays
are not copied) and cannot be changed once made.

Raises TypeError naming the item (items[i]) for anything else, and InputError naming
"items[i] transform" for a transform that is not 4x4, not finite or singular.

zraster.load() returns a Scene too (its meshes owned by zraster).)")
        .def(py::init(&scene_from_items), "items"_a)
        .def(
            "__len__", [](const PyScene& s) { return s.instances.size(); },
            "The number of instances.")
        .def_property_readonly(
            "triangle_count", [](const PyScene& s) { return s.triangle_count(); },
            "Triangles over all instances.")
        .def_property_readonly(
            "vertex_count",
            [](const PyScene& s) {
                std::size_t n = 0;
                for (const InstanceView& i : s.instances) n += s.meshes[i.mesh].positions.count;
                return n;
            },
            "Vertices over all instances.")
        .def_property_readonly(
            "bounds",
            [](const PyScene& s) {
                const std::vector<glm::vec3> world = s.world_positions();
                const Bounds3f b = Bounds3f::of(world);
                return py::make_tuple(to_numpy(glm::dvec3(b.lo)), to_numpy(glm::dvec3(b.hi)));
            },
            "(min, max): the world-space box of every instanced vertex, two float64 arrays of "
            "3 (min > max when the scene is empty).")
        .def_property_readonly(
            "source", [](const PyScene& s) { return s.spec; },
            "The path or procedural spec load() was given ('' for a Scene of Meshes).")
        .def_property_readonly(
            "materials", [](const PyScene& s) { return s.materials; },
            "The scene's materials (copies, zraster.Material), index 0 the default: a loaded "
            "scene's as the loader made them (docs/materials.md), a Scene of items' in item "
            "order (each Mesh's own, each Scene item's list whole).")
        .def_property_readonly(
            "warnings", [](const PyScene& s) { return s.warnings; },
            "Problems the loader found and worked around (a missing texture, ...).")
        .def("__repr__", [](const PyScene& s) {
            return "<zraster.Scene" + (s.spec.empty() ? std::string() : " '" + s.spec + "'") +
                   ": " + std::to_string(s.instances.size()) + " instances, " +
                   std::to_string(s.triangle_count()) + " triangles>";
        });

    m.def("load", &load, "path"_a, "isolation"_a = "worker", "allow_outside_references"_a = false,
          "max_instances"_a = py::int_(LoadOptions{}.max_instances),
          "max_triangles"_a = py::int_(LoadOptions{}.max_triangles),
          "max_texture_side"_a = py::int_(LoadOptions{}.max_texture_side),
          "max_texture_bytes"_a = py::int_(LoadOptions{}.max_texture_bytes),
          "max_geometry_bytes"_a = py::int_(LoadOptions{}.max_geometry_bytes),
          "max_triangulation_work"_a = py::int_(LoadOptions{}.max_triangulation_work),
          "max_materials"_a = py::int_(LoadOptions{}.max_materials),
          R"(Loads a scene: a mesh file or a procedural spec, as `zraster render` reads it.

path: a file (OBJ with MTL, PLY, STL, glTF 2.0 .gltf/.glb, 3DS, OFF and the other formats
  Assimp reads) or a procedural spec: builtin:default, builtin:sphere, builtin:cube, sphere:N,
  city:N[:SEED], soup:N[:SEED].
isolation: "worker" (the command's default: Assimp runs in a child process with memory and time
  limits, so a file that crashes it is refused like any bad file) or "in-process" (faster for
  many small files; a crash in Assimp ends Python). zraster's own OBJ reader always runs here.
allow_outside_references: read a model's external files (glTF buffers, textures, material
  libraries) outside its folder too.
max_instances, max_triangles: larger models are refused.
max_geometry_bytes: a glTF file whose accessors decode to more (each accessor once per primitive
  that reads it) is refused before it is read.
max_triangulation_work: an OBJ or PLY file whose polygons of more than 4 corners sum to more
  corners^2 is refused before it is read (their triangulation takes quadratic time).
max_materials: a model that defines more materials is refused (an OBJ's material libraries
  are counted before they are read).
max_texture_side, max_texture_bytes: textures wider or taller are reduced (halved as their mip
  levels are); the decoded bytes of a model's textures stay within the budget (a texture past it
  is not used). Both with a LoadWarning.

Raises InputError naming the file and the cause (missing, unreadable, malformed, too large).
Problems worked around (a missing texture, ...) are issued as zraster.LoadWarning (a
UserWarning, "PATH: what") and kept in Scene.warnings. The GIL is released while loading.)");
}

}  // namespace zraster::python
