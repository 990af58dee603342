// Mesh building: the triangles and vertices of each output mesh, built in parallel, one mesh per
// task, from the resolved corners of its faces.
//
// The Assimp path makes one vertex per face corner and welds equal vertices afterwards. The same
// vertices, in the same order, come out here directly: each v, vt and vn value first gets the
// index of the first equal value (after normalisation and the v flip, -0 == +0), and a mesh vertex
// is one distinct triple of those indices, in first-corner order. Quads are split as Assimp's
// triangulation splits them (a fan from a concave corner), computed with Assimp's own vector
// operations so that it decides exactly as Assimp does.
#pragma once
#include <zraster/mesh.hpp>

#include "io/obj_chunk_parser.hpp"
#include "io/obj_structure.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace zraster::io::obj {

// Every v, vt and vn value of the file, in file order.
struct Attributes {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec3> normals;
    // For each value, the index of the first equal one; empty: identity.
    std::vector<std::uint32_t> first_position, first_uv, first_normal;
};

// Fills first_position, and first_uv and first_normal when some face has such indices.
void index_equal_values(const std::vector<Chunk>& chunks, Attributes& attributes);

struct MeshOutcome {
    Mesh mesh;
    // A non-finite position (convert_mesh's error): the global position and the mesh vertex.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> non_finite;
    bool normals_recomputed = false;  // unusable file normals replaced (recomputed_normals.hpp)
};

// The meshes `output` lists (indices into `meshes`, with their triangles counted), in that order.
// The chunks' corner indices must be resolved, and `face_prefix[k]` is the number of faces before
// chunk k.
std::vector<MeshOutcome> build_meshes(const std::vector<Chunk>& chunks,
                                      const std::vector<std::size_t>& face_prefix,
                                      const Attributes& attributes,
                                      const std::vector<MeshPlan>& meshes,
                                      const std::vector<std::uint32_t>& output);

}  // namespace zraster::io::obj
