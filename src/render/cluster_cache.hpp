// Cluster bounds (cluster_cull.hpp) kept from frame to frame by a Renderer, per mesh.
//
// Bounds cost about as much to build as they save in a frame, so they are built only for a mesh
// seen unchanged in two frames in a row (a one-shot render never builds them) and kept while it
// stays so. "Unchanged" is checked, never assumed: the vertex stage hashes the positions it
// reads anyway (word_hash.hpp) and the cache compares that hash and the array sizes; the
// indices, which it does not read, are hashed per cluster when a cluster is about to be culled,
// and a mismatch makes the front end classify that cluster's triangles after all and drops the
// mesh's bounds after the frame.
#pragma once
#include <zraster/mesh.hpp>
#include <zraster/render.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "render/cluster_cull.hpp"

namespace zraster::detail {

struct MeshClusters {
    std::vector<ClusterBounds> bounds;
    // Set by the front end (any thread) when a cluster's indices no longer match its hash.
    mutable std::atomic<bool> stale{false};
};

// Meshes smaller than this are not worth their bounds' upkeep.
inline constexpr std::size_t kMinClusteredTriangles = 4096;

// Whether a frame with these options can cull clusters of this mesh (then the vertex stage
// hashes its positions). User clip planes would turn culled triangles into rejected ones.
inline bool cluster_culling_applies(const RenderOptions& options, const Mesh& mesh) {
    return options.cluster_culling && options.cull != CullMode::None &&
           options.clip_planes.empty() && mesh.triangle_count() >= kMinClusteredTriangles;
}

struct ClusterCache {
    struct Entry {
        const Mesh* mesh = nullptr;
        std::size_t positions = 0, indices = 0;
        std::uint64_t positions_hash = 0;
        std::unique_ptr<MeshClusters> clusters;  // null until seen unchanged twice
        bool seen = false;                       // in the current frame
    };
    std::vector<Entry> entries;
};

}  // namespace zraster::detail
