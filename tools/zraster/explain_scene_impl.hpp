// recolored_scene's template body (explain_scene.hpp).
#pragma once
#include <zraster/material.hpp>

namespace zraster::cli {

template <typename ClassOf>
Scene recolored_scene(const Scene& scene, const std::vector<glm::vec3>& colors, ClassOf class_of) {
    Scene out;
    out.name = scene.name;
    out.materials.clear();
    for (const glm::vec3& c : colors) {
        Material m;
        m.base_color = c;
        out.materials.push_back(m);
    }
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes[instance.mesh];
        for (std::uint32_t c = 0; c < colors.size(); ++c) {
            Mesh part;
            part.name = mesh.name;
            part.positions = mesh.positions;
            part.normals = mesh.normals;
            part.material = c;
            for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
                if (class_of(i, t) == int(c))
                    part.indices.insert(part.indices.end(),
                                        mesh.indices.begin() + std::ptrdiff_t(3 * t),
                                        mesh.indices.begin() + std::ptrdiff_t(3 * t + 3));
            if (part.indices.empty()) continue;
            part.bounds = mesh.bounds;
            Instance copy = instance;
            copy.mesh = std::uint32_t(out.meshes.size());
            copy.shading = ShadingMode::Flat;
            out.meshes.push_back(std::move(part));
            out.instances.push_back(std::move(copy));
        }
    }
    return out;
}

}  // namespace zraster::cli
