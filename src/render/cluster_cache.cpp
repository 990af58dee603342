// See cluster_cache.hpp.
#include "render/cluster_cache.hpp"

#include <algorithm>

#include "render/frame.hpp"

namespace zraster::detail {

// Bounds are kept only if at least this fraction of a mesh's clusters could be culled.
constexpr std::size_t kWorthItDivisor = 16;

void attach_clusters(Frame& frame) {
    ClusterCache& cache = frame.cluster_cache;
    for (auto& [mesh, e] : cache.entries) e.seen = e.recorded = false;
    for (FrameInstance& fi : frame.instances) {
        fi.clusters = nullptr;
        // Verdicts the vertex stage made hold only with the bounds attached below.
        const std::uint8_t* verdicts = fi.culled_clusters;
        const bool indices_checked = fi.cluster_indices_checked;
        fi.culled_clusters = nullptr;
        fi.cluster_indices_checked = false;
        const Mesh& mesh = *fi.mesh;
        if (!cluster_culling_applies(*frame.options, mesh)) continue;
        ClusterCache::Entry& e = cache.entries[&mesh];
        e.seen = true;
        if (!fi.positions_hashed) continue;  // not worth it (wants_positions_hash)
        const bool same = e.positions == mesh.positions.size() &&
                          e.indices == mesh.indices.size() && e.positions_hash == fi.positions_hash;
        if (!same) {  // first sighting, or changed: remember it, build next time
            e.positions = mesh.positions.size();
            e.indices = mesh.indices.size();
            e.positions_hash = fi.positions_hash;
            e.clusters.reset();
            e.not_worth_it = false;
            e.recorded = true;
        } else if (!e.clusters && !e.not_worth_it && !e.recorded) {
            const std::vector<ClusterBounds> bounds = build_cluster_bounds(mesh);
            const auto cullable = std::count_if(
                bounds.begin(), bounds.end(), [](const ClusterBounds& b) { return b.cullable(); });
            e.not_worth_it = std::size_t(cullable) * kWorthItDivisor < bounds.size();
            if (!e.not_worth_it) e.clusters = std::make_unique<MeshClusters>(bounds, mesh);
        }
        // (Bounds found stale by the vertex stage are dropped after the frame.)
        fi.clusters = e.clusters && !e.clusters->stale ? e.clusters.get() : nullptr;
        if (fi.clusters) {
            fi.cluster_view = make_cluster_view(fi.mvp, frame.clip_settings, frame.setup_settings);
            fi.culled_clusters = verdicts;
            fi.cluster_indices_checked = verdicts != nullptr && indices_checked;
        }
    }
    // Meshes not drawn in this frame are forgotten (memory stays bounded by the last frame's).
    std::erase_if(cache.entries, [](const auto& entry) { return !entry.second.seen; });
}

void drop_stale_clusters(Frame& frame) {
    for (auto& [mesh, e] : frame.cluster_cache.entries)
        if (e.clusters && e.clusters->stale) {
            e.clusters.reset();
            e.positions = ~std::size_t{0};  // never "same": seen twice more before rebuilding
        }
}

}  // namespace zraster::detail
