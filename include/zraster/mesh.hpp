// Triangle meshes as plain arrays: what the pipeline consumes. No file format leaks in here.
#pragma once
#include <zraster/bounds.hpp>
#include <zraster/export.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace zraster {

struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  // empty or one per position, unit length
    std::vector<glm::vec2> uvs;      // empty or one per position; v = 0 at the image's top row
    // Empty or one per position: RGBA in [0, 1] multiplying the material's base color and alpha
    // (glTF COLOR_0, PLY red/green/blue/alpha), interpolated over each triangle.
    std::vector<glm::vec4> colors;
    std::vector<std::uint32_t> indices;  // three per triangle; counter-clockwise = front
    std::uint32_t material = 0;          // index into Scene::materials
    Bounds3f bounds;                     // of positions, in the mesh's own space

    std::size_t triangle_count() const { return indices.size() / 3; }
    std::size_t vertex_count() const { return positions.size(); }
};

// Angle-weighted vertex normals (Thürmer & Wüthrich 1998): each triangle adds its unit face normal
// weighted by its interior angle at the vertex. Degenerate triangles add nothing; a vertex that
// gets no contribution gets (0, 1, 0). Replaces mesh.normals.
ZRASTER_API void compute_angle_weighted_normals(Mesh& mesh);

// Unit face normal of each triangle, (0, 1, 0) for a degenerate one.
ZRASTER_API std::vector<glm::vec3> compute_face_normals(const Mesh& mesh);

// Recomputes mesh.bounds from mesh.positions.
ZRASTER_API void update_bounds(Mesh& mesh);

}  // namespace zraster
