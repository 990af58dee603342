#include "io/assimp_material.hpp"

#include "io/text_util.hpp"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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

std::optional<std::string> get_string(const aiMaterial& m, const char* key, unsigned type,
                                      unsigned index) {
    aiString s;
    if (m.Get(key, type, index, s) != AI_SUCCESS) return std::nullopt;
    return std::string(s.C_Str());
}

std::optional<std::string> texture_reference(const aiMaterial& material, aiTextureType type) {
    aiString path;
    if (material.GetTextureCount(type) > 0 && material.GetTexture(type, 0, &path) == AI_SUCCESS) {
        std::string reference(trim(path.C_Str()));
        if (!reference.empty()) return reference;
    }
    return std::nullopt;
}

std::string number(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", double(v));
    return buffer;
}

// glTF 2.0's alpha (section 3.9.4 of the specification). Assimp's glTF2 importer always sets
// alphaMode ("OPAQUE" when the file has none, as the specification's default) and alphaCutoff
// (0.5 by default), and copies baseColorFactor's alpha to AI_MATKEY_OPACITY as well: opacity is
// taken from the base color alone so that the factor counts once.
void convert_gltf_alpha(const aiMaterial& material, const std::string& mode, Material& out,
                        std::vector<std::string>& warnings) {
    const std::string label = "material '" + out.name + "'";
    if (mode == "MASK") {
        out.alpha_mode = AlphaMode::Mask;
    } else if (mode == "BLEND") {
        out.alpha_mode = AlphaMode::Blend;
    } else {
        if (mode != "OPAQUE")
            warnings.push_back(label + ": alphaMode '" + mode +
                               "' is not OPAQUE, MASK or BLEND, drawn opaque (glTF's default)");
        out.alpha_mode = AlphaMode::Opaque;
    }
    // OPAQUE ignores alpha: opacity stays 1 so that a reader of Material that does not look at
    // alpha_mode (the A-buffer) still draws it opaque.
    if (out.alpha_mode != AlphaMode::Opaque) {
        const std::optional<aiColor4D> base = get_color(material, AI_MATKEY_BASE_COLOR);
        if (base && std::isfinite(base->a)) out.opacity = std::clamp(base->a, 0.0f, 1.0f);
    }
    // The specification bounds alphaCutoff below by 0 only; zraster keeps it in [0, 1] (1 already
    // keeps only fully opaque texels). NaN, which JSON cannot spell, takes the default.
    float cutoff = 0.5f;
    if (material.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff) != AI_SUCCESS) cutoff = 0.5f;
    if (!(cutoff >= 0.0f && cutoff <= 1.0f)) {
        const float kept = std::isnan(cutoff) ? 0.5f : std::clamp(cutoff, 0.0f, 1.0f);
        if (out.alpha_mode == AlphaMode::Mask)
            warnings.push_back(label + ": alphaCutoff " + number(cutoff) +
                               " is outside [0, 1], using " + number(kept));
        cutoff = kept;
    }
    out.alpha_cutoff = cutoff;
    // doubleSided (default false): Assimp's glTF2 importer sets AI_MATKEY_TWOSIDED from it. Read
    // for glTF only: other formats' two-sided flags (3DS, FBX) keep the behaviour they had.
    int two_sided = 0;
    out.double_sided = material.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS && two_sided != 0;
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

bool is_skeleton_placeholder_material(const aiMaterial& material) {
    // SkeletonMeshBuilder::CreateMaterial gives it these two properties and no others.
    return material.mNumProperties == 2 && material_name(material) == "SkeletonMaterial";
}

Material convert_material(const aiMaterial& material, const std::string& fallback_name,
                          std::vector<std::string>& warnings) {
    Material out;
    const std::string name = material_name(material);
    out.name = name.empty() ? fallback_name : name;

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
    if (auto shininess = get_float(material, AI_MATKEY_SHININESS); shininess && *shininess > 0.0f) {
        out.shininess = std::clamp(*shininess, 1.0f, 1024.0f);
        if (*shininess > 1024.0f)
            warnings.push_back("material '" + out.name + "': shininess " + number(*shininess) +
                               " is past 1024, using 1024");
    }

    if (auto mode = get_string(material, AI_MATKEY_GLTF_ALPHAMODE)) {
        convert_gltf_alpha(material, *mode, out, warnings);
        return out;
    }
    // Every other format: Assimp's opacity (MTL d or 1 - Tr, FBX Opacity, 3DS transparency...),
    // else the diffuse color's alpha, blended (alpha 1 everywhere draws opaque).
    out.alpha_mode = AlphaMode::Blend;
    if (auto opacity = get_float(material, AI_MATKEY_OPACITY)) {
        out.opacity = std::clamp(*opacity, 0.0f, 1.0f);
        if (out.opacity != *opacity)
            warnings.push_back("material '" + out.name + "': opacity " + number(*opacity) +
                               " is outside 0..1, using " + number(out.opacity));
    } else if (base && std::isfinite(base->a))
        out.opacity = std::clamp(base->a, 0.0f, 1.0f);
    return out;
}

std::optional<std::string> base_color_texture_reference(const aiMaterial& material) {
    if (auto reference = texture_reference(material, aiTextureType_BASE_COLOR)) return reference;
    return texture_reference(material, aiTextureType_DIFFUSE);
}

std::optional<std::string> opacity_texture_reference(const aiMaterial& material) {
    return texture_reference(material, aiTextureType_OPACITY);
}

}  // namespace zraster::io
