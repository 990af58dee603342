// zraster.Mesh: a triangle mesh over the caller's numpy arrays.
#include <zraster/mesh.hpp>
#include <zraster/scenes.hpp>

#include <pybind11/stl.h>

#include <cmath>
#include <cstring>

#include "arrays.hpp"
#include "binding.hpp"
#include "errors.hpp"

namespace zraster::python {
namespace {

using namespace pybind11::literals;

// Angle-weighted vertex normals, as the loaders compute them for files without normals.
py::array computed_normals(const AttributeView& positions, const IndexView& indices) {
    Mesh m;
    m.positions.resize(positions.count);
    const std::size_t stride = positions.stride ? positions.stride : 12;
    for (std::size_t k = 0; k < positions.count; ++k)
        std::memcpy(&m.positions[k], reinterpret_cast<const char*>(positions.data) + k * stride,
                    12);
    m.indices.resize(indices.count);
    for (std::size_t k = 0; k < indices.count; ++k)
        m.indices[k] = indices.type == IndexType::UInt16
                           ? static_cast<const std::uint16_t*>(indices.data)[k]
                           : static_cast<const std::uint32_t*>(indices.data)[k];
    compute_angle_weighted_normals(m);
    py::array_t<float> normals({py::ssize_t(m.normals.size()), py::ssize_t(3)});
    std::memcpy(normals.mutable_data(), m.normals.data(), m.normals.size() * 12);
    return normals;
}

// An attribute of `columns` floats per vertex: one row per position, else an InputError.
FloatRows per_vertex(const py::object& rows, std::size_t columns, const char* argument,
                     const char* element, std::size_t positions) {
    FloatRows r = float_rows(rows, columns, argument);
    if (r.view.count != positions)
        input_error(argument, std::to_string(r.view.count) + " rows for " +
                                  std::to_string(positions) + " positions: give one " + element +
                                  " per position");
    return r;
}

std::shared_ptr<PyMesh> make_mesh(const py::object& positions, const py::object& indices,
                                  const py::object& normals, const py::object& uvs,
                                  const py::object& color, std::string name) {
    auto mesh = std::make_shared<PyMesh>();
    FloatRows p = float_rows(positions, 3, "positions");
    mesh->positions = p.array;
    mesh->positions_copied = p.copied;
    mesh->view.positions = p.view;
    Indices i = triangle_indices(indices, p.view.count, "indices");
    mesh->indices = i.array;
    mesh->indices_copied = i.copied;
    mesh->view.indices = i.view;
    if (normals.is_none() && p.view.count > 0) {
        mesh->normals = computed_normals(p.view, i.view);
        mesh->normals_computed = true;
        mesh->view.normals = {static_cast<const float*>(mesh->normals.data()), p.view.count, 0};
    } else if (!normals.is_none()) {
        const FloatRows n = per_vertex(normals, 3, "normals", "normal", p.view.count);
        mesh->normals = n.array;
        mesh->normals_copied = n.copied;
        mesh->view.normals = n.view;
    }
    if (!uvs.is_none()) {
        const FloatRows t = per_vertex(uvs, 2, "uvs", "uv", p.view.count);
        mesh->uvs = t.array;
        mesh->uvs_copied = t.copied;
        mesh->view.uvs = t.view;
    }
    if (!color.is_none()) {
        const std::size_t n = py::isinstance<py::sequence>(color) && !py::isinstance<py::str>(color)
                                  ? py::len(color)
                                  : 0;
        if (n != 3 && n != 4) type_error("color", "3 or 4 numbers (RGB or RGBA in 0..1)", color);
        const glm::dvec4 c = vector_n(color, int(n), "color");
        for (std::size_t k = 0; k < n; ++k)
            if (c[int(k)] < 0.0 || c[int(k)] > 1.0)
                input_error("color", "components must be in 0..1, got " +
                                         py::str(color).cast<std::string>());
        Material material;
        material.name = name;
        material.base_color = glm::vec3(c);
        if (n == 4) material.opacity = float(c.w);
        mesh->material = material;
    }
    mesh->name = std::move(name);
    return mesh;
}

// A mesh made by zraster (the procedural primitives), as numpy arrays the Mesh owns.
std::shared_ptr<PyMesh> mesh_from(const Mesh& m, const py::object& color) {
    const auto n = py::ssize_t(m.positions.size());
    py::array_t<float> positions({n, py::ssize_t(3)}), normals({n, py::ssize_t(3)}),
        uvs({n, py::ssize_t(2)});
    py::array_t<std::uint32_t> indices({py::ssize_t(m.indices.size() / 3), py::ssize_t(3)});
    std::memcpy(positions.mutable_data(), m.positions.data(), m.positions.size() * 12);
    if (m.normals.size() == m.positions.size())
        std::memcpy(normals.mutable_data(), m.normals.data(), m.normals.size() * 12);
    if (m.uvs.size() == m.positions.size())
        std::memcpy(uvs.mutable_data(), m.uvs.data(), m.uvs.size() * 8);
    std::memcpy(indices.mutable_data(), m.indices.data(), (m.indices.size() / 3) * 12);
    return make_mesh(positions, indices,
                     m.normals.size() == m.positions.size() ? py::object(normals) : py::none(),
                     m.uvs.size() == m.positions.size() ? py::object(uvs) : py::none(), color,
                     m.name);
}

py::object optional_array(const py::array& a) {
    return a ? py::object(a) : py::none();
}

}  // namespace

void bind_mesh(py::module_& m) {
    py::class_<PyMesh, std::shared_ptr<PyMesh>>(m, "Mesh", R"(A triangle mesh over numpy arrays.

Mesh(positions, indices, normals=None, uvs=None, color=None, name="")

positions: (N, 3) real numbers, object space.
indices:   (M, 3) or flat (3M,) integers in 0..N-1; counter-clockwise triangles face the viewer.
normals:   optional (N, 3), one unit normal per position. Absent: angle-weighted vertex normals
           are computed here, as the file loaders do (`computed_normals` is then True).
uvs:       optional (N, 2) texture coordinates, v = 0 at the image's top row.
color:     optional base color (R, G, B) or (R, G, B, A), components in 0..1, of the mesh's
           own material (absent: zraster's default material; A < 1 is drawn transparent only
           with visibility="abuffer").

Nothing is copied when the arrays already have a layout zraster reads: float32 rows of
adjacent floats (C order, or any row stride, e.g. a column slice of an interleaved array) and
C-contiguous uint32, int32 or uint16 indices. Anything else (float64, int64, Fortran order,
lists) is copied once, here, into float32 / uint32. The Mesh keeps the arrays referenced;
`copied` says which were copied. A referenced array's later changes show in later renders (the
checks - shapes, finite values, indices in range - are made here, once).

Raises InputError (naming the argument) for wrong shapes, non-finite values, indices out of
range or a color out of 0..1, and TypeError for arguments that are no arrays of numbers.)")
        .def(py::init(&make_mesh), "positions"_a, "indices"_a, "normals"_a = py::none(),
             "uvs"_a = py::none(), "color"_a = py::none(), "name"_a = "")
        .def_static(
            "uv_sphere",
            [](float radius, int stacks, int slices, const py::object& color) {
                if (!(radius > 0.0f) || !std::isfinite(radius))
                    input_error("radius", "must be positive and finite");
                if (stacks < 2 || slices < 3 || stacks > 4096 || slices > 4096)
                    input_error("stacks", "need 2 <= stacks <= 4096 and 3 <= slices <= 4096");
                return mesh_from(make_uv_sphere(radius, stacks, slices), color);
            },
            "radius"_a = 1.0f, "stacks"_a = 32, "slices"_a = 64, "color"_a = py::none(),
            "A UV sphere centred at the origin, with normals and uvs (zraster's primitive).")
        .def_static(
            "box",
            [](const py::object& half_extent, const py::object& color) {
                const glm::dvec4 h = vector_n(half_extent, 3, "half_extent");
                if (!(h.x > 0 && h.y > 0 && h.z > 0))
                    input_error("half_extent", "components must be positive");
                return mesh_from(make_box(glm::vec3(h)), color);
            },
            "half_extent"_a = py::make_tuple(0.5, 0.5, 0.5), "color"_a = py::none(),
            "An axis-aligned box centred at the origin, with normals and uvs.")
        .def_property_readonly(
            "positions", [](const PyMesh& mesh) { return mesh.positions; },
            "The (N, 3) positions: the array given, or its float32 copy.")
        .def_property_readonly(
            "indices", [](const PyMesh& mesh) { return mesh.indices; },
            "The indices: the array given, or its uint32 copy.")
        .def_property_readonly(
            "normals", [](const PyMesh& mesh) { return optional_array(mesh.normals); },
            "The (N, 3) normals, or None.")
        .def_property_readonly(
            "uvs", [](const PyMesh& mesh) { return optional_array(mesh.uvs); },
            "The (N, 2) uvs, or None.")
        .def_property_readonly(
            "color",
            [](const PyMesh& mesh) -> py::object {
                if (!mesh.material) return py::none();
                const Material& mat = *mesh.material;
                return py::make_tuple(mat.base_color.x, mat.base_color.y, mat.base_color.z,
                                      mat.opacity);
            },
            "The base color (R, G, B, A) of the mesh's material, or None (the default).")
        .def_property_readonly("name", [](const PyMesh& mesh) { return mesh.name; })
        .def_property_readonly(
            "copied",
            [](const PyMesh& mesh) {
                py::dict d;
                d["positions"] = mesh.positions_copied;
                d["indices"] = mesh.indices_copied;
                d["normals"] = mesh.normals_copied;
                d["uvs"] = mesh.uvs_copied;
                return d;
            },
            "Which arrays were copied (True) rather than referenced (False).")
        .def_property_readonly(
            "computed_normals", [](const PyMesh& mesh) { return mesh.normals_computed; },
            "True when the normals were computed (none were given).")
        .def_property_readonly("vertex_count",
                               [](const PyMesh& mesh) { return mesh.view.positions.count; })
        .def_property_readonly("triangle_count",
                               [](const PyMesh& mesh) { return mesh.view.indices.count / 3; })
        .def("__repr__", [](const PyMesh& mesh) {
            return "<zraster.Mesh '" + mesh.name +
                   "': " + std::to_string(mesh.view.positions.count) + " vertices, " +
                   std::to_string(mesh.view.indices.count / 3) + " triangles>";
        });
}

}  // namespace zraster::python
