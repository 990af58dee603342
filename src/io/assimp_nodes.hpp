// The node hierarchy: which meshes each node places, with the node's accumulated transform.
#pragma once
#include <assimp/matrix4x4.h>
#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

struct aiScene;

namespace zraster::io {

struct NodeMesh {
    unsigned mesh = 0;  // index into aiScene::mMeshes
    glm::mat4 transform{1.0f};
    std::string node_name;
};

// Assimp matrices are row-major (a4 is the x translation); glm's are column-major.
glm::mat4 to_glm(const aiMatrix4x4& m);

// Depth-first, parents before children, in file order. Throws InputError naming `file` when the
// hierarchy places more than `max_instances` meshes (LoadOptions::max_instances), before
// placing more.
std::vector<NodeMesh> collect_node_meshes(const aiScene& scene, std::size_t max_instances,
                                          const std::string& file);

}  // namespace zraster::io
