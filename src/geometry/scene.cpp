#include <zraster/scene.hpp>

#include <cassert>

namespace zraster {

Bounds3f Scene::bounds() const {
    Bounds3f b;
    for (const Instance& instance : instances) {
        assert(instance.mesh < meshes.size());
        b.extend(meshes[instance.mesh].bounds.transformed(instance.transform));
    }
    return b;
}

std::vector<glm::vec3> Scene::world_positions() const {
    std::vector<glm::vec3> out;
    out.reserve(vertex_count());
    for (const Instance& instance : instances) {
        assert(instance.mesh < meshes.size());
        for (const glm::vec3& p : meshes[instance.mesh].positions) {
            const glm::vec4 q = instance.transform * glm::vec4(p, 1.0f);
            out.push_back(glm::vec3(q) / q.w);
        }
    }
    return out;
}

std::size_t Scene::triangle_count() const {
    std::size_t n = 0;
    for (const Instance& instance : instances) n += meshes[instance.mesh].triangle_count();
    return n;
}

std::size_t Scene::vertex_count() const {
    std::size_t n = 0;
    for (const Instance& instance : instances) n += meshes[instance.mesh].vertex_count();
    return n;
}

Scene scene_from_meshes(std::vector<Mesh> meshes) {
    Scene scene;
    scene.meshes = std::move(meshes);
    for (std::uint32_t i = 0; i < scene.meshes.size(); ++i) {
        // Bounds are part of the mesh contract; recomputing here keeps callers from forgetting.
        update_bounds(scene.meshes[i]);
        Instance instance;
        instance.mesh = i;
        instance.name = scene.meshes[i].name;
        scene.instances.push_back(std::move(instance));
    }
    return scene;
}

}  // namespace zraster
