// A scene of many instances for the render tests: 12 x 12 instances of three meshes on a grid
// (the instance BVH culls from 64 instances on; the occlusion culler finds occluders and hidden
// instances among them; some are partly off screen).
#pragma once
#include <zraster/scene.hpp>
#include <zraster/scenes.hpp>

#include <glm/gtc/matrix_transform.hpp>

namespace zraster::test {

// Every `flat_every`-th instance overrides the shading mode with Flat (0: none does).
inline Scene instance_grid(int flat_every = 0) {
    std::vector<Mesh> meshes;
    meshes.push_back(make_uv_sphere(0.4f, 8, 16));
    meshes.push_back(make_box(glm::vec3(0.3f, 0.5f, 0.3f)));
    meshes.push_back(make_torus(0.35f, 0.1f, 12, 8));
    Scene scene = scene_from_meshes(std::move(meshes));
    scene.instances.clear();
    for (int i = 0; i < 144; ++i) {
        Instance instance;
        instance.mesh = std::uint32_t(i % 3);
        instance.transform = glm::translate(
            glm::mat4(1.0f), glm::vec3(float(i % 12) - 5.5f, 0.0f, -float(i / 12) * 1.2f));
        if (flat_every > 0 && i % flat_every == 0) instance.shading = ShadingMode::Flat;
        scene.instances.push_back(instance);
    }
    return scene;
}

}  // namespace zraster::test
