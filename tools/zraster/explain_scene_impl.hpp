// recolored_scene's template body (explain_scene.hpp).
#pragma once
#include <zraster/material.hpp>

#include <map>
#include <tuple>

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
    // Instances of one mesh whose triangles fall in the same classes share the recolored parts
    // (the culling pictures color whole instances of building:256x256 alike: one copy of the
    // mesh per class, not one per instance).
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::size_t>, std::vector<std::uint32_t>>
        made;  // (mesh, class, hash of the kept indices) -> parts
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        const Mesh& mesh = scene.meshes[instance.mesh];
        for (std::uint32_t c = 0; c < colors.size(); ++c) {
            std::vector<std::uint32_t> indices;
            for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
                if (class_of(i, t) == int(c))
                    indices.insert(indices.end(), mesh.indices.begin() + std::ptrdiff_t(3 * t),
                                   mesh.indices.begin() + std::ptrdiff_t(3 * t + 3));
            if (indices.empty()) continue;
            std::size_t hash = indices.size();
            for (const std::uint32_t k : indices) hash = hash * 1000003u ^ k;
            std::vector<std::uint32_t>& candidates = made[{instance.mesh, c, hash}];
            std::uint32_t part_index = std::uint32_t(out.meshes.size());
            for (const std::uint32_t m : candidates)
                if (out.meshes[m].indices == indices) part_index = m;
            if (part_index == out.meshes.size()) {
                Mesh part;
                part.name = mesh.name;
                part.positions = mesh.positions;
                part.normals = mesh.normals;
                part.material = c;
                part.indices = std::move(indices);
                part.bounds = mesh.bounds;
                candidates.push_back(part_index);
                out.meshes.push_back(std::move(part));
            }
            Instance copy = instance;
            copy.mesh = part_index;
            copy.shading = ShadingMode::Flat;
            out.instances.push_back(std::move(copy));
        }
    }
    return out;
}

}  // namespace zraster::cli
