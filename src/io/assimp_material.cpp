#include "io/assimp_material.hpp"

#include "io/text_util.hpp"

#include <assimp/material.h>

#include <algorithm>
#include <cmath>

namespace zraster::io {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::optional<aiColor4D> get_color(const aiMaterial& m, const char* key, unsigned type,
                                   unsigned index) {
    aiColor4D c;
    if (m.Get(key, type, index, c) != AI_SUCCESS) return std::nullopt;
    return c;
}

std::optional<float> get_float(const aiMaterial& m, const char* key, unsigned type,
                               unsigned index) {
    float f = 0.0f;
    if (m.Get(key, type, index, f) != AI_SUCCESS || !std::isfinite(f)) return std::nullopt;
    return f;
}

}  // namespace

std::string material_name(const aiMaterial& material) {
    aiString name;
    if (material.Get(AI_MATKEY_NAME, name) != AI_SUCCESS) return {};
    return std::string(trim(name.C_Str()));
}

bool is_placeholder_material(const aiMaterial& material) {
    const std::string name = material_name(material);
    // AI_DEFAULT_MATERIAL_NAME, and the 3DS importer's own default.
    if (name == AI_DEFAULT_MATERIAL_NAME || name == "%%%DEFAULT") return true;
    // PLY, OFF and STL materials are nameless defaults; glTF's nameless materials carry a base
    // color, and any material with a texture is the file's.
    return name.empty() && !get_color(material, AI_MATKEY_BASE_COLOR) &&
           !base_color_texture_reference(material);
}

Material convert_material(const aiMaterial& material) {
    Material out;
    const std::string name = material_name(material);
    if (!name.empty()) out.name = name;

    std::optional<aiColor4D> base = get_color(material, AI_MATKEY_BASE_COLOR);
    if (!base) base = get_color(material, AI_MATKEY_COLOR_DIFFUSE);
    if (base && finite({base->r, base->g, base->b})) out.base_color = {base->r, base->g, base->b};

    if (auto specular = get_color(material, AI_MATKEY_COLOR_SPECULAR)) {
        glm::vec3 s{specular->r, specular->g, specular->b};
        if (auto strength = get_float(material, AI_MATKEY_SHININESS_STRENGTH);
            strength && *strength >= 0.0f)
            s *= *strength;
        if (finite(s)) out.specular = glm::max(s, glm::vec3(0.0f));
    }
    // Zero means "not given" for OBJ (Ns 0 with Ks 0) and glTF, where Assimp stores 0.
    if (auto shininess = get_float(material, AI_MATKEY_SHININESS); shininess && *shininess > 0.0f)
        out.shininess = std::clamp(*shininess, 1.0f, 1024.0f);

    if (auto opacity = get_float(material, AI_MATKEY_OPACITY))
        out.opacity = std::clamp(*opacity, 0.0f, 1.0f);
    else if (base && std::isfinite(base->a))
        out.opacity = std::clamp(base->a, 0.0f, 1.0f);
    return out;
}

std::optional<std::string> base_color_texture_reference(const aiMaterial& material) {
    for (aiTextureType type : {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE}) {
        aiString path;
        if (material.GetTextureCount(type) > 0 &&
            material.GetTexture(type, 0, &path) == AI_SUCCESS) {
            std::string reference(trim(path.C_Str()));
            if (!reference.empty()) return reference;
        }
    }
    return std::nullopt;
}

}  // namespace zraster::io
