// See cluster_cache.hpp.
#include "render/cluster_cache.hpp"

#include <algorithm>

#include "render/frame.hpp"

namespace zraster::detail {

// Bounds are kept only if at least this fraction of a mesh's clusters could be culled.
constexpr std::size_t kWorthItDivisor = 16;

void attach_clusters(Frame& frame) {
    ClusterCache& cache = frame.cluster_cache;
    ++cache.frame;
    for (auto& [mesh, e] : cache.entries) e.recorded = false;
    if (frame.cluster_verdicts.size() < frame.instances.size())  // (the vertex stage sizes it)
        frame.cluster_verdicts.resize(frame.instances.size());
    for (std::size_t i = 0; i < frame.instances.size(); ++i) {
        FrameInstance& fi = frame.instances[i];
        fi.clusters = nullptr;
        // Verdicts the vertex stage made hold only with the bounds attached below.
        const std::uint8_t* verdicts = fi.culled_clusters;
        const bool indices_checked = fi.cluster_indices_checked;
        fi.culled_clusters = nullptr;
        fi.cluster_indices_checked = false;
        const MeshView& mesh = *fi.mesh->view;
        if (!cluster_culling_applies(*frame.options, mesh)) continue;
        const auto [entry, first_sighting] = cache.entries.try_emplace(mesh_key(mesh));
        ClusterCache::Entry& e = entry->second;
        e.last_frame = cache.frame;
        if (!fi.positions_hashed) continue;  // not worth it (wants_positions_hash)
        const bool same = !first_sighting && e.positions == mesh.positions.count &&
                          e.indices == mesh.indices.count && e.positions_hash == fi.positions_hash;
        if (!same) {  // first sighting, or changed: remember it
            e.positions = mesh.positions.count;
            e.indices = mesh.indices.count;
            e.positions_hash = fi.positions_hash;
            e.clusters.reset();
            e.not_worth_it = false;
            e.recorded = true;
        }
        // A mesh seen for the first time gets its bounds at once, so that a kept Renderer
        // allocates nothing after its first frame; one that changed gets them once it is seen
        // unchanged (an animated mesh would have them rebuilt every frame, for nothing).
        if (!e.clusters && !e.not_worth_it && (first_sighting || !e.recorded)) {
            const std::vector<ClusterBounds> bounds = build_cluster_bounds(mesh);
            const auto cullable = std::count_if(
                bounds.begin(), bounds.end(), [](const ClusterBounds& b) { return b.cullable(); });
            e.not_worth_it = std::size_t(cullable) * kWorthItDivisor < bounds.size();
            if (!e.not_worth_it) e.clusters = std::make_unique<MeshClusters>(bounds, mesh);
        }
        // (Bounds found stale by the vertex stage are dropped after the frame.)
        fi.clusters = e.clusters && !e.clusters->stale ? e.clusters.get() : nullptr;
        if (fi.clusters) {
            fi.cluster_view =
                make_cluster_view(fi.mvp, frame.clip_settings, instance_setup(frame, fi));
            fi.culled_clusters = verdicts;
            fi.cluster_indices_checked = verdicts != nullptr && indices_checked;
            // The vertex stage's scratch for these bounds, sized with them: the next frame
            // that culls with them allocates nothing.
            frame.cluster_verdicts[i].reserve(fi.clusters->arrays.count);
            frame.needed_vertex_blocks.reserve(fi.clusters->blocks.blocks);
        }
    }
    // Meshes not drawn for a while are forgotten (memory stays bounded by the recent frames').
    std::erase_if(cache.entries, [&](const auto& entry) {
        return cache.frame - entry.second.last_frame >= ClusterCache::kForgetAfterFrames;
    });
}

void drop_stale_clusters(Frame& frame) {
    for (auto& [mesh, e] : frame.cluster_cache.entries)
        if (e.clusters && e.clusters->stale) {
            e.clusters.reset();
            e.positions = ~std::size_t{0};  // never "same": seen twice more before rebuilding
        }
}

}  // namespace zraster::detail
