// See include/zraster/mesh_view.hpp.
#include <zraster/mesh_view.hpp>

namespace zraster {
namespace {

template <class Vector>
const float* floats_of(const std::vector<Vector>& v) {
    return v.empty() ? nullptr : &v[0].x;
}

}  // namespace

MeshView view_of(const Mesh& mesh) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float) &&
                  sizeof(glm::vec2) == 2 * sizeof(float) && sizeof(glm::vec4) == 4 * sizeof(float));
    MeshView view;
    view.positions = {floats_of(mesh.positions), mesh.positions.size(), sizeof(glm::vec3)};
    view.normals = {floats_of(mesh.normals), mesh.normals.size(), sizeof(glm::vec3)};
    view.uvs = {floats_of(mesh.uvs), mesh.uvs.size(), sizeof(glm::vec2)};
    view.colors = {floats_of(mesh.colors), mesh.colors.size(), sizeof(glm::vec4)};
    view.indices = {mesh.indices.data(), mesh.indices.size(), IndexType::UInt32};
    view.material = mesh.material;
    if (!mesh.bounds.empty() || mesh.positions.empty()) view.bounds = mesh.bounds;
    view.name = mesh.name;
    return view;
}

SceneView view_of(const Scene& scene, std::vector<MeshView>& meshes,
                  std::vector<InstanceView>& instances) {
    meshes.resize(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        meshes[m] = view_of(scene.meshes[m]);
        if (meshes[m].material >= scene.materials.size()) meshes[m].material = 0;
    }
    instances.resize(scene.instances.size());
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& instance = scene.instances[i];
        instances[i] = {instance.mesh, instance.transform, instance.shading};
    }
    return {meshes, scene.materials, instances, scene.cells.get()};
}

}  // namespace zraster
