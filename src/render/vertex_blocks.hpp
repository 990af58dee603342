// Which vertices a frame must transform, given the clusters it culls (cluster_cull.hpp).
//
// A cluster culled whole is never read by the front end, so a vertex that only culled clusters
// use needs no transform, snap, world position or normal: on a closed mesh seen from outside
// that is most of the back half. Vertices go in blocks of kVertexBlock (consecutive indices);
// a block is skipped when every cluster using one of its vertices is culled, and a block no
// cluster uses is skipped too (no triangle reads it).
//
// The map from blocks to clusters is built once with the clusters' bounds. It holds for the
// indices it was built from: the vertex stage checks every cluster's index hash before it skips
// anything (a changed index could point into a skipped block), and the positions' hash after.
#pragma once
#include <zraster/mesh_view.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace zraster::detail {

inline constexpr std::size_t kVertexBlock = 64;

struct VertexBlockClusters {
    std::size_t blocks = 0;
    // The clusters using block b: clusters[offsets[b] .. offsets[b + 1]).
    std::vector<std::uint32_t> offsets;
    std::vector<std::uint32_t> clusters;
};

// For the mesh's clusters of kClusterTriangles triangles. Indices out of range are left out
// (their clusters are never culled, cluster_cull.hpp).
VertexBlockClusters build_vertex_block_clusters(const MeshView& mesh);

// needed[b] = 1 when a cluster using block b is not culled (culled[c] == 0), else 0; returns
// the number of vertices in skipped blocks (of `vertices` in all).
std::size_t needed_vertex_blocks(const VertexBlockClusters& map, const std::uint8_t* culled,
                                 std::size_t vertices, std::uint8_t* needed);

}  // namespace zraster::detail
