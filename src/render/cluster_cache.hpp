// Cluster bounds (cluster_cull.hpp) kept from frame to frame by a Renderer, per mesh.
//
// Bounds cost about as much to build as they save in a frame. A Renderer builds them in the first
// frame that draws a mesh (so that later frames allocate nothing; a one-shot render never builds
// them) and keeps them while the mesh stays unchanged; a mesh that changed gets new ones once it
// is seen unchanged in two frames (an animated one is not bounded every frame, for nothing).
// "Unchanged" is checked, never assumed: the vertex stage hashes the positions it reads anyway
// (word_hash.hpp) and the cache compares that hash and the array sizes; the indices, which it does
// not read, are hashed per cluster when a cluster is about to be culled (a mismatch makes the front
// end classify that cluster's triangles after all), or all of them before the vertex stage skips
// vertices (vertex_blocks.hpp; a mismatch culls nothing that frame). Either way the mesh's bounds
// are dropped after the frame. A mesh whose bounds turn out nearly all uncullable (normals every
// way, as in a triangle soup) is then left alone, unhashed, while its sizes stay. With
// RenderOptions::static_meshes nothing is hashed: the caller promises the meshes do not change, and
// only their array sizes are compared.
//
// A mesh is known by its arrays' addresses (MeshKey): the same for an owning Scene's mesh frame
// after frame and for a caller's MeshView rebuilt every frame over the same buffers.
#pragma once
#include <zraster/mesh_view.hpp>
#include <zraster/render.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "render/cluster_cull.hpp"
#include "render/vertex_blocks.hpp"

namespace zraster::detail {

struct MeshClusters {
    MeshClusters(const std::vector<ClusterBounds>& bounds, const MeshView& mesh)
        : arrays(bounds), blocks(build_vertex_block_clusters(mesh)) {}
    ClusterArrays arrays;
    VertexBlockClusters blocks;  // which clusters use which vertices (vertex_blocks.hpp)
    // Set by the vertex stage or the front end (any thread) when a cluster's indices no longer
    // match its hash.
    mutable std::atomic<bool> stale{false};
};

// The positions' hash recorded for every mesh under RenderOptions::static_meshes.
inline constexpr std::uint64_t kStaticMeshHash = 0;

// Meshes smaller than this are not worth their bounds' upkeep.
inline constexpr std::size_t kMinClusteredTriangles = 4096;

// Whether a frame with these options can cull clusters of this mesh (then the vertex stage
// hashes its positions). User clip planes would turn culled triangles into rejected ones.
inline bool cluster_culling_applies(const RenderOptions& options, const MeshView& mesh) {
    return options.cluster_culling && options.cull != CullMode::None &&
           options.clip_planes.empty() && mesh.indices.count / 3 >= kMinClusteredTriangles;
}

// The cache's key of a mesh: where its positions and indices are, how they are laid out and
// how many there are. (With the counts: two views of one buffer in a frame with different
// counts must not share an entry, whose bounds the first one's instances already hold.)
struct MeshKey {
    const void* positions = nullptr;
    std::size_t position_count = 0, position_stride = 0;  // stride resolved: never 0
    const void* indices = nullptr;
    std::size_t index_count = 0;
    IndexType index_type = IndexType::UInt32;
    bool operator==(const MeshKey&) const = default;
};

inline MeshKey mesh_key(const MeshView& mesh) {
    const std::size_t stride =
        mesh.positions.stride == 0 ? 3 * sizeof(float) : mesh.positions.stride;
    return {mesh.positions.data, mesh.positions.count, stride,
            mesh.indices.data,   mesh.indices.count,   mesh.indices.type};
}

struct MeshKeyHash {
    std::size_t operator()(const MeshKey& k) const {
        const auto mix = [](std::size_t h, std::size_t v) {
            return (h ^ v) * std::size_t{0x100000001b3};
        };
        std::size_t h = std::size_t{0xcbf29ce484222325};
        h = mix(h, reinterpret_cast<std::uintptr_t>(k.positions));
        h = mix(h, k.position_count);
        h = mix(h, k.position_stride);
        h = mix(h, reinterpret_cast<std::uintptr_t>(k.indices));
        h = mix(h, k.index_count);
        return mix(h, static_cast<std::size_t>(k.index_type));
    }
};

struct ClusterCache {
    struct Entry {
        std::size_t positions = 0, indices = 0;
        std::uint64_t positions_hash = 0;
        std::unique_ptr<MeshClusters> clusters;  // null until built
        // Bounds were built and too few clusters could ever be culled (a triangle soup): the
        // mesh is not hashed or bounded again while its array sizes stay.
        bool not_worth_it = false;
        std::uint64_t last_frame = 0;  // the frame (ClusterCache::frame) it was last drawn in
        bool recorded = false;         // (re)recorded in the current frame: not seen unchanged yet
    };
    std::unordered_map<MeshKey, Entry, MeshKeyHash> entries;
    std::uint64_t frame = 0;  // frames attached so far
    // A mesh not drawn in this many frames in a row is forgotten. (Not at once: a Renderer
    // drawing two scenes in turn, say two passes, keeps both meshes' bounds and makes no
    // allocation for them frame after frame.)
    static constexpr std::uint64_t kForgetAfterFrames = 8;
    // False for a frame that is not kept (the one-shot render()): nothing would be reused.
    bool kept = true;

    // The bounds kept for this mesh from earlier frames, while its array sizes match (the
    // vertex stage checks the rest before it relies on them: indices, positions' hash).
    const MeshClusters* kept_clusters(const MeshView& mesh) const {
        const auto it = entries.find(mesh_key(mesh));
        if (!kept || it == entries.end() || !it->second.clusters) return nullptr;
        const Entry& e = it->second;
        const bool sizes = e.positions == mesh.positions.count && e.indices == mesh.indices.count;
        return sizes && !e.clusters->stale ? e.clusters.get() : nullptr;
    }
    // Whether these are the positions the kept bounds were made for (by their hash).
    bool same_positions(const MeshView& mesh, std::uint64_t positions_hash) const {
        const auto it = entries.find(mesh_key(mesh));
        return it != entries.end() && it->second.positions_hash == positions_hash;
    }

    // Whether the vertex stage should hash this mesh's positions (options permitting).
    bool wants_positions_hash(const MeshView& mesh) const {
        if (!kept) return false;
        const auto it = entries.find(mesh_key(mesh));
        return it == entries.end() || !it->second.not_worth_it ||
               it->second.positions != mesh.positions.count ||
               it->second.indices != mesh.indices.count;
    }
};

}  // namespace zraster::detail
