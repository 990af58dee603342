#include "io/drawable_check.hpp"

#include <zraster/error.hpp>

#include <glm/glm.hpp>

#include <cstring>

namespace zraster::io {
namespace {

// In double: corners a float apart near 1e-30 still give a nonzero cross product. As placed: a
// node scaled by 0 flattens whatever it places.
glm::dvec3 placed(const glm::dmat4& transform, const glm::vec3& p) {
    const glm::dvec4 q = transform * glm::dvec4(glm::dvec3(p), 1.0);
    return q.w != 0.0 ? glm::dvec3(q) / q.w : glm::dvec3(0.0);
}

bool has_area(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
              const glm::dmat4& transform) {
    const glm::dvec3 pa = placed(transform, a);
    const glm::dvec3 n = glm::cross(placed(transform, b) - pa, placed(transform, c) - pa);
    return n.x != 0.0 || n.y != 0.0 || n.z != 0.0;
}

bool has_area(const Mesh& mesh, std::size_t first, const glm::dmat4& transform) {
    return has_area(mesh.positions[mesh.indices[first]], mesh.positions[mesh.indices[first + 1]],
                    mesh.positions[mesh.indices[first + 2]], transform);
}

std::size_t index_at(const IndexView& v, std::size_t i) {
    if (v.type == IndexType::UInt16) return static_cast<const std::uint16_t*>(v.data)[i];
    return static_cast<const std::uint32_t*>(v.data)[i];
}

glm::vec3 position_at(const AttributeView& v, std::size_t i) {
    glm::vec3 p;
    std::memcpy(&p, reinterpret_cast<const char*>(v.data) + i * (v.stride ? v.stride : 12), 12);
    return p;
}

[[noreturn]] void refuse(const std::string& file, std::size_t triangles) {
    throw InputError(file, "every one of its " + std::to_string(triangles) +
                               " triangles has zero area as placed (repeated or collinear corners, "
                               "or a transform that flattens them): nothing to draw");
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
    refuse(file, triangles);
}

void check_some_triangle_has_area(const SceneView& scene, const std::string& name) {
    std::size_t triangles = 0;
    for (const InstanceView& instance : scene.instances) {
        if (instance.mesh >= scene.meshes.size()) continue;
        const MeshView& mesh = scene.meshes[instance.mesh];
        if (mesh.positions.data == nullptr || mesh.indices.data == nullptr) continue;
        const glm::dmat4 transform(instance.transform);
        for (std::size_t i = 0; i + 2 < mesh.indices.count; i += 3) {
            const std::size_t a = index_at(mesh.indices, i), b = index_at(mesh.indices, i + 1),
                              c = index_at(mesh.indices, i + 2);
            const std::size_t n = mesh.positions.count;
            if (a >= n || b >= n || c >= n) return;  // the renderer's error, not this one
            if (has_area(position_at(mesh.positions, a), position_at(mesh.positions, b),
                         position_at(mesh.positions, c), transform))
                return;
            ++triangles;
        }
    }
    if (triangles == 0) throw InputError(name, "no triangles: nothing to draw");
    refuse(name, triangles);
}

}  // namespace zraster::io
