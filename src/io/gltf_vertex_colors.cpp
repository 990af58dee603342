// See gltf_vertex_colors.hpp.
#include "io/gltf_vertex_colors.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <fstream>
#include <string>

namespace zraster::io {
namespace {

using nlohmann::json;

std::uint32_t little_u32(const std::array<char, 20>& b, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k)
        v |= std::uint32_t(static_cast<unsigned char>(b[at + k])) << (8 * k);
    return v;
}

// The glTF document: a GLB's JSON chunk, or a file of JSON whole; empty for anything else.
std::string gltf_document(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 20> header{};
    if (!in.read(header.data(), header.size())) return {};
    if (std::string_view(header.data(), 4) == "glTF") {
        if (little_u32(header, 4) != 2 || std::string_view(header.data() + 16, 4) != "JSON")
            return {};
        std::string text(little_u32(header, 12), '\0');
        if (!in.read(text.data(), std::streamsize(text.size()))) return {};
        return text;
    }
    // Assimp reads a glTF under any name: a JSON object is taken as one (the parse decides).
    const std::string_view start(header.data(), header.size());
    const std::size_t first = start.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos || start[first] != '{') return {};
    in.seekg(0);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

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
