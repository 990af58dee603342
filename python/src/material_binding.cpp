// zraster.Material: a scene's materials as Python reads them (the C++ Material, copied), and the
// alpha mode names shared with Mesh's keywords.
#include <pybind11/stl.h>

#include "binding.hpp"
#include "errors.hpp"

namespace zraster::python {
namespace {

py::tuple rgb(const glm::vec3& c) {
    return py::make_tuple(c.x, c.y, c.z);
}

py::object texture_size(const std::shared_ptr<const Texture>& texture) {
    if (!texture) return py::none();
    return py::make_tuple(texture->width(), texture->height());
}

}  // namespace

const char* alpha_mode_name(AlphaMode mode) {
    switch (mode) {
        case AlphaMode::Opaque:
            return "opaque";
        case AlphaMode::Mask:
            return "mask";
        case AlphaMode::Blend:
            return "blend";
    }
    return "blend";
}

AlphaMode alpha_mode_argument(py::handle object, const std::string& argument) {
    if (!py::isinstance<py::str>(object))
        type_error(argument, "'opaque', 'mask' or 'blend'", object);
    const std::string name = object.cast<std::string>();
    for (AlphaMode mode : {AlphaMode::Opaque, AlphaMode::Mask, AlphaMode::Blend})
        if (name == alpha_mode_name(mode)) return mode;
    input_error(argument, "expected 'opaque', 'mask' or 'blend', got '" + name + "'");
}

void bind_material(py::module_& m) {
    py::class_<Material>(m, "Material",
                         R"(A material of a Scene (Scene.materials) or a Mesh (Mesh.material).

A read-only copy of zraster's C++ Material (include/zraster/material.hpp; what the loaders make
of each format's materials: docs/materials.md). Shading: color = base * (ambient + diffuse *
N.L) + specular * (N.H)^shininess, base = base_color times the base-color texture where there is
one. Alpha = opacity x the base-color texture's alpha x the opacity texture's red, and alpha_mode
says what it does: "opaque" (ignored), "mask" (fragments with alpha below alpha_cutoff are
discarded, the rest opaque) or "blend" (composited over what is behind; alpha 1 everywhere draws
opaque).)")
        .def_property_readonly("name", [](const Material& mat) { return mat.name; })
        .def_property_readonly(
            "base_color", [](const Material& mat) { return rgb(mat.base_color); },
            "(R, G, B) in 0..1.")
        .def_property_readonly(
            "opacity", [](const Material& mat) { return mat.opacity; },
            "The alpha factor in 0..1 (glTF baseColorFactor's alpha, MTL d).")
        .def_property_readonly(
            "alpha_mode", [](const Material& mat) { return alpha_mode_name(mat.alpha_mode); },
            "'opaque', 'mask' or 'blend'.")
        .def_property_readonly(
            "alpha_cutoff", [](const Material& mat) { return mat.alpha_cutoff; },
            "The alpha below which 'mask' discards a fragment.")
        .def_property_readonly(
            "double_sided", [](const Material& mat) { return mat.double_sided; },
            "glTF doubleSided: never back-face culled, back faces lit with the flipped normal "
            "(False for formats without the flag: OBJ, PLY, STL).")
        .def_property_readonly(
            "has_texture", [](const Material& mat) { return mat.base_color_texture != nullptr; },
            "Whether a base-color texture is bound (its alpha counts).")
        .def_property_readonly(
            "has_opacity_texture",
            [](const Material& mat) { return mat.opacity_texture != nullptr; },
            "Whether an opacity texture (MTL map_d, red channel) is bound.")
        .def_property_readonly(
            "texture_size",
            [](const Material& mat) { return texture_size(mat.base_color_texture); },
            "(width, height) of the base-color texture's first level, or None.")
        .def_property_readonly(
            "translucent_texture",
            [](const Material& mat) {
                return mat.base_color_texture != nullptr &&
                       mat.base_color_texture->has_translucent_texels();
            },
            "Whether the base-color texture has a texel with alpha below 255.")
        .def_property_readonly("ambient", [](const Material& mat) { return mat.ambient; })
        .def_property_readonly("diffuse", [](const Material& mat) { return mat.diffuse; })
        .def_property_readonly(
            "specular", [](const Material& mat) { return rgb(mat.specular); }, "(R, G, B).")
        .def_property_readonly("shininess", [](const Material& mat) { return mat.shininess; })
        .def("__repr__", [](const Material& mat) {
            std::string s = "<zraster.Material '" + mat.name +
                            "': " + alpha_mode_name(mat.alpha_mode) + ", opacity " +
                            py::str(py::float_(mat.opacity)).cast<std::string>();
            if (mat.alpha_mode == AlphaMode::Mask)
                s += ", cutoff " + py::str(py::float_(mat.alpha_cutoff)).cast<std::string>();
            if (mat.base_color_texture)
                s += ", texture " + std::to_string(mat.base_color_texture->width()) + "x" +
                     std::to_string(mat.base_color_texture->height());
            if (mat.opacity_texture) s += ", opacity texture";
            if (mat.double_sided) s += ", double-sided";
            return s + ">";
        });
}

}  // namespace zraster::python
