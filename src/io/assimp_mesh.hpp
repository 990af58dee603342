// One triangulated Assimp mesh to a zraster Mesh: positions, unit normals (computed when the file
// has none), uv channel 0, vertex color set 0, indices and bounds.
#pragma once
#include <zraster/mesh.hpp>

#include "io/gltf_vertex_colors.hpp"

#include <string>
#include <vector>

struct aiMesh;

namespace zraster::io {

struct MeshConversion {
    std::string label;  // names the mesh in messages
    std::string file;   // for InputError
    // Merge bitwise-equal vertices: Assimp's OBJ importer emits one vertex per face corner,
    // which other importers do not, so OBJ meshes get their sharing back this way.
    bool weld = false;
    // What Assimp's vertex alpha means (glTF COLOR_0 of type VEC3 arrives with alpha 0).
    GltfColorAlpha color_alpha = GltfColorAlpha::AsRead;
    // Off for OBJ: zraster's own OBJ reader does not read the `v x y z r g b` colors, and the
    // files it leaves to Assimp must load as it would load them.
    bool vertex_colors = true;
};

// Throws InputError for non-finite positions or indices out of range; non-finite uvs are zeroed
// with a warning cause appended to `warnings`. Unusable normals (not finite, zero) are replaced by
// computed ones; *normals_recomputed (when given) is set to whether any were.
Mesh convert_mesh(const aiMesh& source, const MeshConversion& how,
                  std::vector<std::string>& warnings, bool* normals_recomputed = nullptr);

}  // namespace zraster::io
