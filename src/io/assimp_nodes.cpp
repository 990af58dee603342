#include "io/assimp_nodes.hpp"

#include <zraster/error.hpp>

#include <assimp/scene.h>

#include <string>

#include <utility>

namespace zraster::io {

glm::mat4 to_glm(const aiMatrix4x4& m) {
    return glm::mat4(m.a1, m.b1, m.c1, m.d1,   // column 0
                     m.a2, m.b2, m.c2, m.d2,   // column 1
                     m.a3, m.b3, m.c3, m.d3,   // column 2
                     m.a4, m.b4, m.c4, m.d4);  // column 3: translation
}

std::vector<NodeMesh> collect_node_meshes(const aiScene& scene, std::size_t max_instances,
                                          const std::string& file) {
    std::vector<NodeMesh> out;
    if (scene.mRootNode == nullptr) return out;
    // An explicit stack: a hostile file can nest nodes deeper than the call stack allows.
    std::vector<std::pair<const aiNode*, glm::mat4>> stack{{scene.mRootNode, glm::mat4(1.0f)}};
    while (!stack.empty()) {
        const auto [node, parent] = stack.back();
        stack.pop_back();
        const glm::mat4 transform = parent * to_glm(node->mTransformation);
        if (node->mNumMeshes > max_instances - out.size())
            throw LimitExceeded(file, "max_instances",
                                "the node hierarchy places more than " +
                                    std::to_string(max_instances) + " meshes (max_instances)");
        for (unsigned i = 0; i < node->mNumMeshes; ++i)
            out.push_back({node->mMeshes[i], transform, node->mName.C_Str()});
        for (unsigned c = node->mNumChildren; c-- > 0;)
            stack.emplace_back(node->mChildren[c], transform);
    }
    return out;
}

}  // namespace zraster::io
