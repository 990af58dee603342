// Surface description used by the shading stage.
#pragma once
#include <zraster/texture.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace zraster {

// What a material's alpha does (glTF's alphaMode). A fragment's alpha is the material's opacity
// times the base-color texture's alpha times the opacity texture's red channel times the mesh's
// interpolated vertex alpha (Mesh::colors) (each where present).
enum class AlphaMode : std::uint8_t {
    Opaque,  // alpha is ignored: drawn opaque (glTF OPAQUE)
    Mask,    // alpha test: fragments with alpha below alpha_cutoff are discarded, the rest opaque
    Blend,   // composited over what is behind it, nearest last; alpha 1 everywhere is opaque
};

// color = base * (ambient + diffuse * sum(light * max(N.L, 0))) + specular * sum(light *
// spec^shininess) where base = base_color * texture(uv) when a texture is bound, times the
// interpolated vertex color where the mesh has colors. The defaults
// reproduce the benchmark scenes' "phong" shading (docs/bench-scenes.md).
struct Material {
    std::string name = "default";
    glm::vec3 base_color{0.8f, 0.75f, 0.7f};
    float ambient = 0.15f;
    float diffuse = 0.85f;
    glm::vec3 specular{0.25f};
    float shininess = 32.0f;
    // Alpha factor in [0, 1]: glTF baseColorFactor's alpha, MTL d (or 1 - Tr).
    float opacity = 1.0f;
    // Blend by default: a material whose alpha is 1 everywhere is drawn as opaque, one with
    // opacity or texture alpha below 1 is blended (OBJ's d, a texture with an alpha channel).
    AlphaMode alpha_mode = AlphaMode::Blend;
    float alpha_cutoff = 0.5f;  // Mask: glTF alphaCutoff
    // glTF doubleSided: never back-face culled, back faces lit with the flipped normal (where
    // RenderOptions::material_sides is on, the default). False (glTF's default, and every format
    // without such a flag: OBJ, PLY, STL): RenderOptions::cull and two_sided_lighting decide.
    bool double_sided = false;
    std::shared_ptr<const Texture> base_color_texture;  // null: none; its alpha counts
    std::shared_ptr<const Texture> opacity_texture;     // null: none; MTL map_d, red channel
};

}  // namespace zraster
