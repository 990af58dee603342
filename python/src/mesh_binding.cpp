// zraster.Mesh: a triangle mesh over the caller's numpy arrays.
#include <zraster/load.hpp>
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

// Vertex colors: (N, 4) or (N, 3) real numbers in 0..1, or uint8 (scaled by 1 / 255); RGB gets
// alpha 1. Referenced when float32 RGBA rows (as float_rows references), else copied as such.
FloatRows vertex_colors(const py::object& colors, std::size_t positions) {
    py::array a = py::array::ensure(colors);
    const bool rgb = a && a.ndim() == 2 && a.shape(1) == 3;
    const bool bytes = a && a.dtype().kind() == 'u' && a.itemsize() == 1;
    FloatRows rows;
    if (rgb || bytes) {
        const py::module_ numpy = py::module_::import("numpy");
        py::object rgba = numpy.attr("asarray")(a, "dtype"_a = "float32");
        if (bytes) rgba = rgba.attr("__truediv__")(py::float_(255.0)).attr("astype")("float32");
        if (rgb)
            rgba = numpy.attr("concatenate")(
                py::make_tuple(
                    rgba, numpy.attr("ones")(py::make_tuple(a.shape(0), 1), "dtype"_a = "float32")),
                "axis"_a = 1);
        rows = per_vertex(rgba, 4, "colors", "color", positions);
        rows.copied = true;
    } else {
        rows = per_vertex(colors, 4, "colors", "color", positions);
    }
    for (std::size_t i = 0; i < rows.view.count; ++i)
        for (std::size_t c = 0; c < 4; ++c) {
            const float v =
                rows.view.data[(i * (rows.view.stride ? rows.view.stride : 16)) / 4 + c];
            if (v < 0.0f || v > 1.0f)
                input_error("colors", "row " + std::to_string(i) +
                                          " has a component outside 0..1 (" + std::to_string(v) +
                                          ")");
        }
    return rows;
}

// The base color from `color`: RGB and an optional alpha, each in 0..1.
void set_color(Material& material, const py::object& color) {
    const std::size_t n =
        py::isinstance<py::sequence>(color) && !py::isinstance<py::str>(color) ? py::len(color) : 0;
    if (n != 3 && n != 4) type_error("color", "3 or 4 numbers (RGB or RGBA in 0..1)", color);
    const glm::dvec4 c = vector_n(color, int(n), "color");
    for (std::size_t k = 0; k < n; ++k)
        if (c[int(k)] < 0.0 || c[int(k)] > 1.0)
            input_error("color",
                        "components must be in 0..1, got " + py::str(color).cast<std::string>());
    material.base_color = glm::vec3(c);
    if (n == 4) material.opacity = float(c.w);
}

// The mesh's own material, when any of its keywords is given: zraster's default Material with
// what they set. A texture without a color multiplies white, as a glTF baseColorTexture does.
std::optional<Material> mesh_material(const std::string& name, bool has_uvs,
                                      const py::object& color, const py::object& texture,
                                      const py::object& alpha_mode, const py::object& alpha_cutoff,
                                      const py::object& double_sided) {
    if (color.is_none() && texture.is_none() && alpha_mode.is_none() && alpha_cutoff.is_none() &&
        double_sided.is_none())
        return std::nullopt;
    Material material;
    material.name = name;
    if (!texture.is_none()) {
        material.base_color_texture =
            texture_image(texture, "texture", LoadOptions{}.max_texture_side);
        if (!has_uvs)
            input_error("texture", "a texture needs uvs: give uvs= (one (u, v) per position)");
        material.base_color = glm::vec3(1.0f);
    }
    if (!color.is_none()) set_color(material, color);
    if (!alpha_mode.is_none()) material.alpha_mode = alpha_mode_argument(alpha_mode, "alpha_mode");
    // As the glTF loader makes an OPAQUE material: opacity 1, so that a reader of Material that
    // does not look at alpha_mode (the A-buffer) draws it opaque too.
    if (material.alpha_mode == AlphaMode::Opaque) material.opacity = 1.0f;
    if (!alpha_cutoff.is_none()) {
        const double cutoff = finite_number(alpha_cutoff, "alpha_cutoff");
        if (cutoff < 0.0 || cutoff > 1.0)
            input_error("alpha_cutoff", "must be in 0..1, got " + std::to_string(cutoff));
        material.alpha_cutoff = float(cutoff);
    }
    if (!double_sided.is_none()) {
        if (!py::isinstance<py::bool_>(double_sided))
            type_error("double_sided", "True or False", double_sided);
        material.double_sided = double_sided.cast<bool>();
    }
    return material;
}

std::shared_ptr<PyMesh> make_mesh(const py::object& positions, const py::object& indices,
                                  const py::object& normals, const py::object& uvs,
                                  const py::object& color, std::string name,
                                  const py::object& texture, const py::object& alpha_mode,
                                  const py::object& alpha_cutoff, const py::object& colors,
                                  const py::object& double_sided) {
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
    if (!colors.is_none()) {
        const FloatRows c = vertex_colors(colors, p.view.count);
        mesh->colors = c.array;
        mesh->colors_copied = c.copied;
        mesh->view.colors = c.view;
    }
    mesh->material =
        mesh_material(name, !uvs.is_none(), color, texture, alpha_mode, alpha_cutoff, double_sided);
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
                     m.name, py::none(), py::none(), py::none(), py::none(), py::none());
}

py::object optional_array(const py::array& a) {
    return a ? py::object(a) : py::none();
}

}  // namespace

void bind_mesh(py::module_& m) {
    py::class_<PyMesh, std::shared_ptr<PyMesh>>(m, "Mesh", R"(A triangle mesh over numpy arrays.

Mesh(positions, indices, normals=None, uvs=None, color=None, name="", texture=None,
     alpha_mode=None, alpha_cutoff=None, colors=None, double_sided=None)

positions: (N, 3) real numbers, object space.
indices:   (M, 3) or flat (3M,) integers in 0..N-1; counter-clockwise triangles face the viewer.
normals:   optional (N, 3), one unit normal per position. Absent: angle-weighted vertex normals
           are computed here, as the file loaders do (`computed_normals` is then True).
uvs:       optional (N, 2) texture coordinates, v = 0 at the image's top row.
color:     optional base color (R, G, B) or (R, G, B, A), components in 0..1, of the mesh's
           own material. A is the material's opacity.
texture:   optional base-color image, (H, W, 3) or (H, W, 4) uint8, or floats in [0, 1]
           (scaled by 255, rounded); row 0 is the image's top row, as in an image file. Needs
           uvs. Copied into a zraster texture with its mip levels, as a loaded model's texture
           (reduced past 8192 texels a side as load() reduces it); its alpha counts. Without
           `color` the base color is white (the texture's colors as they are).
alpha_mode: optional "blend" (the default: composited over what is behind it where alpha is
           below 1, opaque where alpha is 1 everywhere), "mask" (fragments with alpha below
           alpha_cutoff are discarded, the rest opaque) or "opaque" (alpha ignored; the
           material's opacity is 1 then, as the glTF loader makes an OPAQUE material).
alpha_cutoff: optional, in 0..1 (default 0.5): the "mask" threshold.
colors:    optional per-vertex colors, (N, 4) RGBA or (N, 3) RGB (alpha 1), real numbers in
           0..1 or uint8 (scaled by 1/255), as a glTF COLOR_0: interpolated over each triangle,
           they multiply the base color (and the texture), and their alpha the material's.
double_sided: optional True or False (default False): a double-sided material is never
           back-face culled and its back faces are lit with the flipped normal, as glTF's
           doubleSided (RenderOptions.material_sides).

Alpha = A x the texture's alpha x the vertex alpha. With none of color, texture, alpha_mode, alpha_cutoff, double_sided the mesh
has no material of its own and is drawn with zraster's default material. `material` returns
the mesh's material (a zraster.Material) or None.

Nothing is copied when the arrays already have a layout zraster reads: float32 rows of
adjacent floats (C order, or any row stride, e.g. a column slice of an interleaved array) and
C-contiguous uint32, int32 or uint16 indices. Anything else (float64, int64, Fortran order,
lists) is copied once, here, into float32 / uint32. The Mesh keeps the arrays referenced;
`copied` says which were copied. A referenced array's later changes show in later renders (the
checks - shapes, finite values, indices in range - are made here, once). The texture is always
copied.

Raises InputError (naming the argument) for wrong shapes, non-finite values, indices out of
range, a color, vertex color or alpha_cutoff out of 0..1, an unknown alpha_mode, float texels out of [0, 1]
or a texture without uvs, and TypeError for arguments of the wrong type (a texture of a dtype
other than uint8 or float).)")
        .def(py::init(&make_mesh), "positions"_a, "indices"_a, "normals"_a = py::none(),
             "uvs"_a = py::none(), "color"_a = py::none(), "name"_a = "", "texture"_a = py::none(),
             "alpha_mode"_a = py::none(), "alpha_cutoff"_a = py::none(), "colors"_a = py::none(),
             "double_sided"_a = py::none())
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
            "colors", [](const PyMesh& mesh) { return optional_array(mesh.colors); },
            "The (N, 4) float32 vertex colors (RGBA), or None.")
        .def_property_readonly(
            "color",
            [](const PyMesh& mesh) -> py::object {
                if (!mesh.material) return py::none();
                const Material& mat = *mesh.material;
                return py::make_tuple(mat.base_color.x, mat.base_color.y, mat.base_color.z,
                                      mat.opacity);
            },
            "The base color (R, G, B, A) of the mesh's material, or None (the default).")
        .def_property_readonly(
            "material",
            [](const PyMesh& mesh) -> py::object {
                if (!mesh.material) return py::none();
                return py::cast(*mesh.material);
            },
            "The mesh's own material (a zraster.Material), or None (the scene's default).")
        .def_property_readonly(
            "texture",
            [](const PyMesh& mesh) -> py::object {
                if (!mesh.material || !mesh.material->base_color_texture) return py::none();
                const Texture& t = *mesh.material->base_color_texture;
                py::array_t<std::uint8_t> image(
                    {py::ssize_t(t.height()), py::ssize_t(t.width()), py::ssize_t(4)});
                const std::span<const std::uint8_t> rgba = t.level_rgba(0);
                std::memcpy(image.mutable_data(), rgba.data(), rgba.size());
                return image;
            },
            "The texture's first level as an (H, W, 4) uint8 RGBA copy, or None.")
        .def_property_readonly("name", [](const PyMesh& mesh) { return mesh.name; })
        .def_property_readonly(
            "copied",
            [](const PyMesh& mesh) {
                py::dict d;
                d["positions"] = mesh.positions_copied;
                d["indices"] = mesh.indices_copied;
                d["normals"] = mesh.normals_copied;
                d["uvs"] = mesh.uvs_copied;
                d["colors"] = mesh.colors_copied;
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
