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

std::string triple(const glm::vec3& v) {
    return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")";
}

// Material values outside the ranges shading assumes (docs/limits.md) are replaced, each with one
// warning naming the material, the value read and the value used; nothing non-finite is kept.

// A color of fractions: components clamped into 0..1; a non-finite one gives `fallback`.
glm::vec3 color_in_range(const glm::vec3& color, const char* what, const glm::vec3& fallback,
                         const std::string& label, std::vector<std::string>& warnings) {
    if (!finite(color)) {
        warnings.push_back(label + ": " + what + " " + triple(color) +
                           " is not finite, using the default " + triple(fallback));
        return fallback;
    }
    const glm::vec3 kept = glm::clamp(color, glm::vec3(0.0f), glm::vec3(1.0f));
    if (kept != color)
        warnings.push_back(label + ": " + what + " " + triple(color) + " is outside 0..1, using " +
                           triple(kept));
    return kept;
}

// A fraction (opacity, alpha): clamped into 0..1; NaN gives `fallback`.
float fraction_in_range(float value, const char* what, float fallback, const std::string& label,
                        std::vector<std::string>& warnings) {
    if (value >= 0.0f && value <= 1.0f) return value;
    const float kept = std::isnan(value) ? fallback : std::clamp(value, 0.0f, 1.0f);
    warnings.push_back(label + ": " + what + " " + number(value) + " is outside 0..1, using " +
                       number(kept));
    return kept;
}

// Shininess, the Phong exponent: 1..1024, 0 meaning "not given" (OBJ's Ns 0, Assimp's default).
// glTF has none: Assimp derives it from roughnessFactor as 1000 (1 - r)^2, so the factor is what
// is checked there (0..1), and a small exponent from a valid factor is raised to 1 silently.
std::optional<float> shininess_of(const aiMaterial& material, bool gltf, const std::string& label,
                                  std::vector<std::string>& warnings) {
    float shininess = 0.0f;
    if (material.Get(AI_MATKEY_SHININESS, shininess) != AI_SUCCESS) return std::nullopt;
    if (gltf) {
        float roughness = 1.0f;
        if (material.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness) == AI_SUCCESS &&
            !(roughness >= 0.0f && roughness <= 1.0f)) {
            const float kept = std::isnan(roughness) ? 1.0f : std::clamp(roughness, 0.0f, 1.0f);
            warnings.push_back(label + ": roughnessFactor " + number(roughness) +
                               " is outside 0..1, using " + number(kept));
            shininess = (1.0f - kept) * (1.0f - kept) * 1000.0f;
        }
        if (!(shininess > 0.0f)) return std::nullopt;
        return std::clamp(shininess, 1.0f, 1024.0f);
    }
    if (shininess == 0.0f) return std::nullopt;
    if (std::isnan(shininess) || shininess < 0.0f) {
        warnings.push_back(label + ": shininess " + number(shininess) +
                           " is not in 1..1024, using the default " + number(Material{}.shininess));
        return std::nullopt;
    }
    if (shininess < 1.0f)
        warnings.push_back(label + ": shininess " + number(shininess) + " is below 1, using 1");
    if (shininess > 1024.0f)
        warnings.push_back(label + ": shininess " + number(shininess) +
                           " is past 1024, using 1024");
    return std::clamp(shininess, 1.0f, 1024.0f);
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
        if (const std::optional<aiColor4D> base = get_color(material, AI_MATKEY_BASE_COLOR))
            out.opacity =
                fraction_in_range(base->a, "baseColorFactor alpha", 1.0f, label, warnings);
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

    const std::string label = "material '" + out.name + "'";

    std::optional<aiColor4D> base = get_color(material, AI_MATKEY_BASE_COLOR);
    if (!base) base = get_color(material, AI_MATKEY_COLOR_DIFFUSE);
    if (base)
        out.base_color = color_in_range({base->r, base->g, base->b}, "base color",
                                        Material{}.base_color, label, warnings);

    if (auto specular = get_color(material, AI_MATKEY_COLOR_SPECULAR)) {
        glm::vec3 s{specular->r, specular->g, specular->b};
        if (auto strength = get_float(material, AI_MATKEY_SHININESS_STRENGTH);
            strength && *strength >= 0.0f)
            s *= *strength;
        // Not bounded above: a strength may make it brighter than 1 on purpose.
        if (!finite(s) || glm::any(glm::lessThan(s, glm::vec3(0.0f)))) {
            const glm::vec3 kept = finite(s) ? glm::max(s, glm::vec3(0.0f)) : out.specular;
            warnings.push_back(label + ": specular color " + triple(s) +
                               (finite(s) ? " is negative, using " : " is not finite, using ") +
                               triple(kept));
            s = kept;
        }
        out.specular = s;
    }
    const bool gltf = get_string(material, AI_MATKEY_GLTF_ALPHAMODE).has_value();
    if (std::optional<float> shininess = shininess_of(material, gltf, label, warnings))
        out.shininess = *shininess;

    if (auto mode = get_string(material, AI_MATKEY_GLTF_ALPHAMODE)) {
        convert_gltf_alpha(material, *mode, out, warnings);
        return out;
    }
    // Every other format: Assimp's opacity (MTL d or 1 - Tr, FBX Opacity, 3DS transparency...),
    // else the diffuse color's alpha, blended (alpha 1 everywhere draws opaque).
    out.alpha_mode = AlphaMode::Blend;
    float opacity = 1.0f;
    if (material.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS)
        out.opacity = fraction_in_range(opacity, "opacity", 1.0f, label, warnings);
    else if (base)
        out.opacity = fraction_in_range(base->a, "diffuse alpha", 1.0f, label, warnings);
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
