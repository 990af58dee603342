// See gltf_vertex_colors.hpp.
#include "io/gltf_vertex_colors.hpp"

#include "io/gltf_document.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace zraster::io {

using nlohmann::json;

GltfColorAlpha gltf_color_alpha(const std::filesystem::path& path) {
    const json document = json::parse(gltf_document(path), nullptr, false);
    if (!document.is_object()) return GltfColorAlpha::AsRead;
    const auto accessors = document.find("accessors");
    const auto meshes = document.find("meshes");
    if (accessors == document.end() || !accessors->is_array() || meshes == document.end() ||
        !meshes->is_array())
        return GltfColorAlpha::AsRead;
    bool rgb = false, rgba = false;
    for (const json& mesh : *meshes) {
        const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (primitives == mesh.end() || !primitives->is_array()) continue;
        for (const json& primitive : *primitives) {
            if (!primitive.is_object()) continue;
            const auto attributes = primitive.find("attributes");
            if (attributes == primitive.end() || !attributes->is_object()) continue;
            const auto color = attributes->find("COLOR_0");
            if (color == attributes->end() || !color->is_number_unsigned()) continue;
            const std::uint64_t index = color->get<std::uint64_t>();
            if (index >= accessors->size() || !(*accessors)[index].is_object()) continue;
            const json& accessor = (*accessors)[index];
            const auto type = accessor.find("type");
            if (type == accessor.end() || !type->is_string()) continue;
            rgb |= type->get<std::string>() == "VEC3";
            rgba |= type->get<std::string>() == "VEC4";
        }
    }
    if (!rgb) return GltfColorAlpha::AsRead;
    return rgba ? GltfColorAlpha::OpaqueWhereZero : GltfColorAlpha::Opaque;
}

}  // namespace zraster::io
