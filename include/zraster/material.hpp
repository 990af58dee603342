// Surface description used by the shading stage.
#pragma once
#include <zraster/texture.hpp>

#include <memory>
#include <string>

namespace zraster {

// color = base * (ambient + diffuse * sum(light * max(N.L, 0))) + specular * sum(light *
// spec^shininess) where base = base_color * texture(uv) when a texture is bound. The defaults
// reproduce the benchmark scenes' "phong" shading (docs/bench-scenes.md).
struct Material {
    std::string name = "default";
    glm::vec3 base_color{0.8f, 0.75f, 0.7f};
    float ambient = 0.15f;
    float diffuse = 0.85f;
    glm::vec3 specular{0.25f};
    float shininess = 32.0f;
    float opacity = 1.0f;
    std::shared_ptr<const Texture> base_color_texture;  // null: none
};

}  // namespace zraster
