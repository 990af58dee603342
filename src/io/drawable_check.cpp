#include "io/drawable_check.hpp"

#include <zraster/error.hpp>

#include <glm/glm.hpp>

namespace zraster::io {
namespace {

// In double: corners a float apart near 1e-30 still give a nonzero cross product. As placed: a
// node scaled by 0 flattens whatever it places.
glm::dvec3 placed(const glm::dmat4& transform, const glm::vec3& p) {
    const glm::dvec4 q = transform * glm::dvec4(glm::dvec3(p), 1.0);
    return q.w != 0.0 ? glm::dvec3(q) / q.w : glm::dvec3(0.0);
}

bool has_area(const Mesh& mesh, std::size_t first, const glm::dmat4& transform) {
    const glm::dvec3 a = placed(transform, mesh.positions[mesh.indices[first]]);
    const glm::dvec3 b = placed(transform, mesh.positions[mesh.indices[first + 1]]);
    const glm::dvec3 c = placed(transform, mesh.positions[mesh.indices[first + 2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    return n.x != 0.0 || n.y != 0.0 || n.z != 0.0;
}

}  // namespace

void check_some_triangle_has_area(const Scene& scene, const std::string& file) {
    std::size_t triangles = 0;
    for (const Instance& instance : scene.instances) {
        if (instance.mesh >= scene.meshes.size()) continue;
        const Mesh& mesh = scene.meshes[instance.mesh];
        const glm::dmat4 transform(instance.transform);
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            if (has_area(mesh, i, transform)) return;
            ++triangles;
        }
    }
    if (triangles == 0) return;  // (nothing placed: the loaders say so themselves)
    throw InputError(file, "every one of its " + std::to_string(triangles) +
                               " triangles has zero area as placed (repeated or collinear corners, "
                               "or a transform that flattens them): nothing to draw");
}

}  // namespace zraster::io
