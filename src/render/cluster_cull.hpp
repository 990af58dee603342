// Back-face culling of whole clusters of triangles, before the front end reads their vertices.
//
// A mesh's triangles are cut into clusters of kClusterTriangles consecutive triangles. Each gets,
// once (cluster_cache.hpp keeps them from frame to frame), bounds in object space: a box holding
// its vertices (oriented along the normals' mean), a cone holding its unit face normals, its
// smallest doubled triangle area and longest edge. Per frame, cluster_is_culled() proves from these
// alone that every triangle of the cluster is one the exact path (classify_triangle on the snapped
// vertices) culls: no triangle is clipped, each keeps a non-zero snapped area, and its sign is the
// culled one.
//
// Why it is exact. With M the mvp, A its x, y, w rows' 3x3 part and b their 4th column, the
// clip positions c_i = A p_i + b of a triangle satisfy
//   det[c0 c1 c2] = n . G(p0),   n = (p1 - p0) x (p2 - p0),   G(p) = det(A) p + adj(A) b,
// and its doubled window area (y down, as the classifier measures it) is
//   -(W H / 4) det[c0 c1 c2] / (w0 w1 w2).
// The cone and box bound n . G(p0) away from 0 with a known sign, so the true area is at
// least (W H / 4) * min |n| * margin / w_max^3. The snapped area differs from the true one by at
// most 4 delta (extent_x + extent_y) + 8 delta^2, delta being the largest error of a snapped
// coordinate (1/512 pixel of snapping, the float transform's rounding through the divide, the
// double divide) and extent the triangle's window extent (longest edge through the projection's
// derivative). A cluster is culled only if the first exceeds twice the second, and if the box
// lies inside the guard band, in front of the near plane and behind the far one with room for
// the same rounding, so that every vertex's outcode is 0 and no triangle is clipped.
// (Here G(p) = det(A) (p - eye) for a perspective camera: the eye's side of the plane.)
#pragma once
#include <zraster/clip.hpp>
#include <zraster/mesh.hpp>
#include <zraster/mesh_view.hpp>
#include <zraster/raster.hpp>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace zraster::detail {

inline constexpr std::size_t kClusterTriangles = 64;

struct ClusterBounds {
    // A box oriented along the normal cone's axis (thin for a flat cluster), holding every
    // vertex of the cluster's triangles, and a bound of their coordinates' magnitudes.
    glm::dvec3 box_center{0.0};
    glm::dvec3 box_axis[3] = {};  // orthonormal (up to rounding, which the slack covers)
    glm::dvec3 box_half{0.0};
    glm::dvec3 max_abs{0.0};
    // The normal cone: its axis is box_axis[0]; every true unit face normal n satisfies
    // n . box_axis[0] >= cos_angle.
    double cos_angle = 0.0, sin_angle = 1.0;  // sin_angle >= sqrt(1 - cos_angle^2)
    double min_double_area = 0.0;  // lower bound of |n| over its triangles (0: never culled)
    double max_edge = 0.0;         // upper bound of its triangles' edge lengths
    std::uint64_t index_hash = 0;  // hash_words of its indices (cluster_cache.hpp checks it)
    bool cullable() const { return min_double_area > 0.0; }
};

// Cluster c is the mesh's triangles [c * kClusterTriangles, min((c + 1) * kClusterTriangles,
// triangle count)); this many clusters cover the mesh.
inline std::size_t cluster_count(std::size_t triangles) {
    return (triangles + kClusterTriangles - 1) / kClusterTriangles;
}
inline std::size_t cluster_count(const MeshView& mesh) {
    return cluster_count(mesh.indices.count / 3);
}
inline std::size_t cluster_count(const Mesh& mesh) {
    return cluster_count(mesh.triangle_count());
}

// The hash of cluster c's indices (hash_words over triangles [c * kClusterTriangles, ...)):
// ClusterBounds::index_hash when the bounds were built, and what tells later frames that the
// bounds still describe the mesh's triangles.
// 16-bit indices are hashed as the 32-bit words they widen to.
std::uint64_t cluster_index_hash(const MeshView& mesh, std::size_t c);

// The clusters of a mesh (in parallel). Clusters with an index out of range, a non-finite
// position, a triangle degenerate or nearly so in object space, or normals spread too wide to
// ever be culled whole are marked never culled.
std::vector<ClusterBounds> build_cluster_bounds(const MeshView& mesh);
std::vector<ClusterBounds> build_cluster_bounds(const Mesh& mesh);

// The per-frame, per-instance part of the test: the mvp's rows and their derived quantities.
struct ClusterView {
    bool enabled = false;  // false when the cull mode is None
    // Rows of the mvp (x, y, z, w), their absolute values, and the lengths of their first three
    // components.
    glm::dvec4 row[4], abs_row[4];
    double row_length[4] = {};
    double det = 0.0, abs_det = 0.0;  // det(A)
    glm::dvec3 adj_b{0.0};            // adj(A) b
    double culled_sign = 1.0;         // the sign of n . G(p0) of the triangles the cull mode culls
    double half_width = 0.0, half_height = 0.0, area_scale = 0.0;  // W/2, H/2, W*H/4
    double guard_x = 1.0, guard_y = 1.0;
    bool zero_to_one = false;  // clip depth range [0, w] instead of [-w, w]
};

ClusterView make_cluster_view(const glm::mat4& mvp, const ClipSettings& clip,
                              const SetupSettings& setup);

// True only if the exact path culls every triangle of the cluster (see above); false when it
// cannot tell.
bool cluster_is_culled(const ClusterView& view, const ClusterBounds& cluster);

// The same bounds, one array per field, for testing many clusters at once (what a frame does).
struct ClusterArrays {
    std::size_t count = 0;
    std::vector<double> center[3], axis[3][3], half[3], max_abs[3];
    std::vector<double> cos_angle, sin_angle, min_double_area, max_edge;
    std::vector<std::uint64_t> index_hash;
    explicit ClusterArrays(const std::vector<ClusterBounds>& bounds);
    ClusterBounds operator[](std::size_t c) const;
};

// culled[i] = cluster_is_culled(view, clusters[first + i]) for i < count: a SIMD version (the
// same operations in the same order, a cluster per lane) and the scalar reference.
void clusters_culled(const ClusterView& view, const ClusterArrays& clusters, std::size_t first,
                     std::size_t count, std::uint8_t* culled);
void clusters_culled_scalar(const ClusterView& view, const ClusterArrays& clusters,
                            std::size_t first, std::size_t count, std::uint8_t* culled);

}  // namespace zraster::detail
