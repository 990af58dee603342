// See cluster_cache.hpp.
#include "render/cluster_cache.hpp"

#include <algorithm>

#include "render/frame.hpp"

namespace zraster::detail {

void attach_clusters(Frame& frame) {
    ClusterCache& cache = frame.cluster_cache;
    for (ClusterCache::Entry& e : cache.entries) e.seen = false;
    for (FrameInstance& fi : frame.instances) {
        fi.clusters = nullptr;
        if (!fi.positions_hashed) continue;
        const Mesh& mesh = *fi.mesh;
        auto it = std::find_if(cache.entries.begin(), cache.entries.end(),
                               [&](const ClusterCache::Entry& e) { return e.mesh == &mesh; });
        if (it == cache.entries.end()) it = cache.entries.emplace(cache.entries.end());
        ClusterCache::Entry& e = *it;
        const bool same = e.mesh == &mesh && e.positions == mesh.positions.size() &&
                          e.indices == mesh.indices.size() && e.positions_hash == fi.positions_hash;
        if (!same) {  // first sighting, or changed: remember it, build next time
            e.mesh = &mesh;
            e.positions = mesh.positions.size();
            e.indices = mesh.indices.size();
            e.positions_hash = fi.positions_hash;
            e.clusters.reset();
        } else if (!e.clusters && !e.seen) {
            e.clusters = std::make_unique<MeshClusters>();
            e.clusters->bounds = build_cluster_bounds(mesh);
        }
        e.seen = true;
        fi.clusters = e.clusters.get();
        if (fi.clusters)
            fi.cluster_view = make_cluster_view(fi.mvp, frame.clip_settings, frame.setup_settings);
    }
    // Meshes not drawn in this frame are forgotten (memory stays bounded by the last frame's).
    std::erase_if(cache.entries, [](const ClusterCache::Entry& e) { return !e.seen; });
}

void drop_stale_clusters(Frame& frame) {
    for (ClusterCache::Entry& e : frame.cluster_cache.entries)
        if (e.clusters && e.clusters->stale) {
            e.clusters.reset();
            e.positions_hash = 0;
            e.positions = ~std::size_t{0};  // never "same": seen twice more before rebuilding
        }
}

}  // namespace zraster::detail
