// See vertex_blocks.hpp.
#include "render/vertex_blocks.hpp"

#include <algorithm>

#include "render/cluster_cull.hpp"
#include "render/mesh_access.hpp"

namespace zraster::detail {

VertexBlockClusters build_vertex_block_clusters(const MeshView& mesh) {
    VertexBlockClusters map;
    const std::size_t vertices = mesh.positions.count;
    map.blocks = (vertices + kVertexBlock - 1) / kVertexBlock;
    const std::size_t triangles = triangle_count(mesh), clusters = cluster_count(mesh);
    // (block, cluster) pairs, each once: a cluster's blocks are few (its triangles are
    // neighbours), so a sorted list per cluster is short.
    std::vector<std::uint32_t> counts(map.blocks + 1, 0);
    std::vector<std::uint32_t> cluster_blocks, cluster_offsets{0};
    std::vector<std::uint32_t> local;
    for (std::size_t c = 0; c < clusters; ++c) {
        local.clear();
        const std::size_t lo = 3 * c * kClusterTriangles;
        const std::size_t hi = 3 * std::min(triangles, (c + 1) * kClusterTriangles);
        for (std::size_t i = lo; i < hi; ++i)
            if (const std::uint32_t index = load_index(mesh.indices, i); index < vertices)
                local.push_back(static_cast<std::uint32_t>(index / kVertexBlock));
        std::sort(local.begin(), local.end());
        local.erase(std::unique(local.begin(), local.end()), local.end());
        for (const std::uint32_t b : local) ++counts[b + 1];
        cluster_blocks.insert(cluster_blocks.end(), local.begin(), local.end());
        cluster_offsets.push_back(static_cast<std::uint32_t>(cluster_blocks.size()));
    }
    for (std::size_t b = 0; b < map.blocks; ++b) counts[b + 1] += counts[b];
    map.offsets = counts;
    map.clusters.resize(cluster_blocks.size());
    for (std::size_t c = 0; c < clusters; ++c)
        for (std::uint32_t k = cluster_offsets[c]; k < cluster_offsets[c + 1]; ++k)
            map.clusters[counts[cluster_blocks[k]]++] = static_cast<std::uint32_t>(c);
    return map;
}

std::size_t needed_vertex_blocks(const VertexBlockClusters& map, const std::uint8_t* culled,
                                 std::size_t vertices, std::uint8_t* needed) {
    std::size_t skipped = 0;
    for (std::size_t b = 0; b < map.blocks; ++b) {
        std::uint8_t need = 0;
        for (std::uint32_t k = map.offsets[b]; k < map.offsets[b + 1]; ++k)
            need |= culled[map.clusters[k]] == 0;
        needed[b] = need;
        if (!need) skipped += std::min(kVertexBlock, vertices - b * kVertexBlock);
    }
    return skipped;
}

}  // namespace zraster::detail
