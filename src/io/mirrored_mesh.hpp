// Meshes drawn through a mirroring placement (a node transform of negative determinant): the
// loader draws a copy whose triangles turn the other way, so that the mesh's outside still faces
// out (glTF 2.0: "the determinant of the node's global transform defines the winding order").
#pragma once
#include <zraster/mesh.hpp>

namespace zraster::io {

// A copy of `mesh` with each triangle's second and third corners swapped (normals, uvs and
// colors unchanged: they belong to the corners), named "<name> (mirrored)".
Mesh with_winding_reversed(const Mesh& mesh);

}  // namespace zraster::io
