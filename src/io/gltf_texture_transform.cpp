#include "io/gltf_texture_transform.hpp"

#include <zraster/error.hpp>

#include <cmath>

#include "io/gltf_document.hpp"

namespace zraster::io {

namespace {

using json = nlohmann::json;

bool numbers(const json& value, std::size_t count) {
    if (!value.is_array() || value.size() != count) return false;
    for (const json& v : value)
        if (!v.is_number()) return false;
    return true;
}

// Every KHR_texture_transform under `node`, `where` its JSON path ("/materials/0/...").
void check_under(const json& node, const std::string& where, const std::string& file) {
    if (node.is_array()) {
        for (std::size_t i = 0; i < node.size(); ++i)
            check_under(node[i], where + "/" + std::to_string(i), file);
        return;
    }
    if (!node.is_object()) return;
    for (const auto& [key, value] : node.items()) {
        if (key == "KHR_texture_transform" && where.ends_with("/extensions")) {
            const std::string name = where + "/KHR_texture_transform";
            const auto refuse = [&](const std::string& member, const char* rule) {
                throw InputError(file,
                                 "malformed glTF file: " + name + " '" + member + "' is " + rule);
            };
            if (!value.is_object())
                throw InputError(file, "malformed glTF file: " + name + " is not an object");
            if (value.contains("offset") && !numbers(value["offset"], 2))
                refuse("offset", "not 2 numbers");
            if (value.contains("scale") && !numbers(value["scale"], 2))
                refuse("scale", "not 2 numbers");
            if (value.contains("rotation") && !value["rotation"].is_number())
                refuse("rotation", "not a number");
            if (value.contains("texCoord") && !value["texCoord"].is_number_unsigned())
                refuse("texCoord", "not a whole number of 0 or more");
            continue;
        }
        check_under(value, where + "/" + key, file);
    }
}

}  // namespace

void check_gltf_texture_transforms(const json& document, const std::string& file) {
    check_under(document, "", file);
}

std::vector<std::optional<TextureTransform>> gltf_base_color_transforms(
    const std::filesystem::path& path) {
    const std::string text = gltf_document(path);
    if (text.empty() || text.find("KHR_texture_transform") == std::string::npos) return {};
    const json document = json::parse(text, nullptr, false);
    if (!document.is_object() || !document.contains("materials") ||
        !document["materials"].is_array())
        return {};
    std::vector<std::optional<TextureTransform>> transforms;
    bool any = false;
    for (const json& material : document["materials"]) {
        transforms.emplace_back();
        const json* t = nullptr;
        if (material.is_object() && material.contains("pbrMetallicRoughness")) {
            const json& pbr = material["pbrMetallicRoughness"];
            if (pbr.is_object() && pbr.contains("baseColorTexture")) {
                const json& info = pbr["baseColorTexture"];
                if (info.is_object() && info.contains("extensions") &&
                    info["extensions"].is_object() &&
                    info["extensions"].contains("KHR_texture_transform"))
                    t = &info["extensions"]["KHR_texture_transform"];
            }
        }
        if (t == nullptr || !t->is_object()) continue;  // (checked before the import)
        TextureTransform transform;
        if (t->contains("offset"))
            for (int k = 0; k < 2; ++k) transform.offset[k] = (*t)["offset"][k].get<float>();
        if (t->contains("scale"))
            for (int k = 0; k < 2; ++k) transform.scale[k] = (*t)["scale"][k].get<float>();
        if (t->contains("rotation")) transform.rotation = (*t)["rotation"].get<float>();
        transforms.back() = transform;
        any = true;
    }
    if (!any) return {};
    return transforms;
}

void apply_texture_transform(const TextureTransform& t, std::vector<glm::vec2>& uvs) {
    // The extension's reference: uv' = translation * rotation * scale * uv, with GLSL's
    // mat3(cos, sin, 0, -sin, cos, 0, 0, 0, 1) (columns) as the rotation. glTF's texture
    // coordinates are zraster's (v = 0 at the image's first row): no flip.
    const float c = std::cos(t.rotation), s = std::sin(t.rotation);
    for (glm::vec2& uv : uvs) {
        const float u = uv.x * t.scale[0];
        const float v = uv.y * t.scale[1];
        uv = glm::vec2(c * u - s * v + t.offset[0], s * u + c * v + t.offset[1]);
    }
}

}  // namespace zraster::io
