// Vertex sharing, for meshes that lost it and for normals computed across split vertices.
//
// Assimp's OBJ importer emits one vertex per face corner, so an OBJ arrives as a triangle soup
// three times larger than the file. Welding bitwise-equal vertices restores the sharing without
// changing any attribute. Normals computed on a soup would be face normals (faceted shading), so
// missing normals are computed over equal *positions*: texture seams (same position, different
// uv) and duplicated vertices along patch seams do not show as shading seams either.
#pragma once
#include <zraster/mesh.hpp>

namespace zraster::io {

// Merges vertices whose position, normal and uv (those present) are bitwise equal (-0 == +0).
// Keeps first-occurrence order; rewrites indices.
void weld_identical_vertices(Mesh& mesh);

// Angle-weighted normals of the surface in which vertices at equal positions are one vertex.
std::vector<glm::vec3> normals_over_shared_positions(const Mesh& mesh);

}  // namespace zraster::io
