// See cluster_cull.hpp for the bound and why it is exact. The constants below and in
// cluster_constants.hpp are safety margins, each far above the rounding it covers. The SIMD twin
// of cluster_is_culled() (cluster_kernel.cpp) repeats its operations in the same order.
#include "render/cluster_cull.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "render/cluster_constants.hpp"
#include "render/mesh_access.hpp"
#include "render/word_hash.hpp"

namespace zraster::detail {
namespace {

// |computed n - true n| <= kCrossError * |e1| |e2| for n = e1 x e2 from float positions in
// double (a few roundings of 2^-53 each).
constexpr double kCrossError = 0x1p-48;
// Triangles with |n| below this fraction of |e1| |e2| are too thin for the normal's direction
// to be trusted: their cluster is never culled.
constexpr double kThinTriangle = 0x1p-30;
// Clusters whose normal cone is wider than acos(kMinCos) are never culled whole: not worth a
// test per frame.
constexpr double kMinCos = 0.05;

void bound_cluster(const MeshView& view, std::size_t first, std::size_t end, ClusterBounds& out) {
    out = ClusterBounds{};
    const FrameMesh mesh = frame_mesh(view);
    out.index_hash = cluster_index_hash(view, first / kClusterTriangles);
    const std::size_t vertex_total = mesh.vertex_count();
    std::array<glm::dvec3, kClusterTriangles> unit_normal;
    std::array<double, kClusterTriangles> angle_error;
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL), normal_sum(0.0);
    double min_area = HUGE_VAL, max_edge_squared = 0.0;
    for (std::size_t t = first; t < end; ++t) {
        std::array<glm::dvec3, 3> p;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh.index(3 * t + k);
            if (i >= vertex_total) return;  // the front end reports it; never culled
            p[k] = glm::dvec3(mesh.position(i));
            if (!std::isfinite(p[k].x) || !std::isfinite(p[k].y) || !std::isfinite(p[k].z)) return;
            lo = glm::min(lo, p[k]);
            hi = glm::max(hi, p[k]);
        }
        const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
        const glm::dvec3 n = glm::cross(e1, e2);
        // (Squared lengths where they do: a million triangles' square roots add up.)
        const double length = std::sqrt(glm::dot(n, n));
        const double e1_squared = glm::dot(e1, e1), e2_squared = glm::dot(e2, e2);
        const double scale = std::sqrt(e1_squared * e2_squared) * (1.0 + kSlack);
        if (!(length > kThinTriangle * scale)) return;  // degenerate or nearly so
        const double inverse_length = 1.0 / length;
        unit_normal[t - first] = n * inverse_length;
        normal_sum += unit_normal[t - first];
        // |n / |n| - true unit normal| <= 2 |error| / (|n| - |error|).
        angle_error[t - first] = 4.0 * kCrossError * scale * inverse_length;
        min_area = std::min(min_area, length - kCrossError * scale);
        const glm::dvec3 e3 = p[2] - p[1];
        max_edge_squared = std::max({max_edge_squared, e1_squared, e2_squared, glm::dot(e3, e3)});
    }
    const double max_edge = std::sqrt(max_edge_squared);
    const double sum_length = glm::length(normal_sum);
    if (!(sum_length > 0.0)) return;
    const glm::dvec3 axis = normal_sum / sum_length;
    double cos_angle = 1.0;
    for (std::size_t t = 0; t < end - first; ++t)
        cos_angle = std::min(cos_angle, glm::dot(unit_normal[t], axis) - angle_error[t]);
    cos_angle -= kSlack;
    if (!(cos_angle > kMinCos) || !(min_area > 0.0)) return;
    // The box: the cone's axis and two unit vectors perpendicular to it.
    const glm::dvec3 helper = std::abs(axis.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, helper));
    const std::array<glm::dvec3, 3> frame{axis, u, glm::cross(axis, u)};
    glm::dvec3 t_lo(HUGE_VAL), t_hi(-HUGE_VAL);
    for (std::size_t t = first; t < end; ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec3 p(mesh.position(mesh.index(3 * t + k)));
            const glm::dvec3 along(glm::dot(frame[0], p), glm::dot(frame[1], p),
                                   glm::dot(frame[2], p));
            t_lo = glm::min(t_lo, along);
            t_hi = glm::max(t_hi, along);
        }
    const glm::dvec3 mid = 0.5 * (t_lo + t_hi);
    out.box_center = mid.x * frame[0] + mid.y * frame[1] + mid.z * frame[2];
    for (std::size_t k = 0; k < 3; ++k) out.box_axis[k] = frame[k];
    // Rounding of the frame and of the coordinates: a relative slack of the whole extent.
    const double slack = kSlack * glm::length(glm::max(glm::abs(lo), glm::abs(hi)));
    out.box_half = 0.5 * (t_hi - t_lo) * (1.0 + kSlack) + slack;
    out.max_abs = glm::max(glm::abs(lo), glm::abs(hi));
    out.cos_angle = cos_angle;
    out.sin_angle = std::min(1.0, std::sqrt(std::max(0.0, 1.0 - cos_angle * cos_angle)) + kSlack);
    out.max_edge = max_edge * (1.0 + kSlack);
    out.min_double_area = min_area * (1.0 - kSlack);
}

}  // namespace

std::uint64_t cluster_index_hash(const MeshView& mesh, std::size_t c) {
    const std::size_t first = c * kClusterTriangles;
    const std::size_t end = std::min(first + kClusterTriangles, triangle_count(mesh));
    const std::size_t count = 3 * (end - first);
    if (const std::uint32_t* indices = packed_indices32(mesh.indices))
        return hash_words(indices + 3 * first, count, 3 * first);
    std::array<std::uint32_t, 3 * kClusterTriangles> widened;
    widen_indices(mesh.indices, 3 * first, count, widened.data());
    return hash_words(widened.data(), count, 3 * first);
}

std::vector<ClusterBounds> build_cluster_bounds(const Mesh& mesh) {
    return build_cluster_bounds(view_of(mesh));
}

std::vector<ClusterBounds> build_cluster_bounds(const MeshView& mesh) {
    std::vector<ClusterBounds> clusters(cluster_count(mesh));
    const std::size_t triangles = triangle_count(mesh);
    tbb::parallel_for(std::size_t{0}, clusters.size(), [&](std::size_t c) {
        const std::size_t first = c * kClusterTriangles;
        bound_cluster(mesh, first, std::min(triangles, first + kClusterTriangles), clusters[c]);
    });
    return clusters;
}

ClusterView make_cluster_view(const glm::mat4& mvp, const ClipSettings& clip,
                              const SetupSettings& setup) {
    ClusterView v;
    if (setup.cull == CullMode::None) return v;
    for (int r = 0; r < 4; ++r) {
        v.row[r] = glm::dvec4(mvp[0][r], mvp[1][r], mvp[2][r], mvp[3][r]);
        v.abs_row[r] = glm::abs(v.row[r]);
        v.row_length[r] = glm::length(glm::dvec3(v.row[r]));
    }
    const glm::dvec3 a1(v.row[0]), a2(v.row[1]), a3(v.row[3]);  // x, y, w
    const glm::dvec3 c1 = glm::cross(a2, a3), c2 = glm::cross(a3, a1), c3 = glm::cross(a1, a2);
    v.det = glm::dot(a1, c1);
    v.abs_det = std::abs(v.det);
    v.adj_b = v.row[0].w * c1 + v.row[1].w * c2 + v.row[3].w * c3;
    // n . G > 0 means a negative window area: counter-clockwise with y up.
    const bool positive_is_front = setup.front_face == FrontFace::CounterClockwise;
    v.culled_sign = (setup.cull == CullMode::Back) != positive_is_front ? 1.0 : -1.0;
    v.half_width = 0.5 * setup.viewport.width;
    v.half_height = 0.5 * setup.viewport.height;
    v.area_scale = v.half_width * v.half_height;
    v.guard_x = clip.guard_x;
    v.guard_y = clip.guard_y;
    v.zero_to_one = clip.depth_range == ClipDepthRange::ZeroToOne;
    v.enabled = std::isfinite(v.det) && std::isfinite(v.adj_b.x) && std::isfinite(v.adj_b.y) &&
                std::isfinite(v.adj_b.z);
    return v;
}

bool cluster_is_culled(const ClusterView& v, const ClusterBounds& c) {
    if (!v.enabled || !c.cullable()) return false;
    // The cone and box: s (n . G(p)) >= margin for every triangle, s the culled sign. At the
    // box's center g = G(center); over the box, n . (p - center) is at most the box's half
    // thickness along the axis plus sin_angle times its other half extents.
    const glm::dvec3 g = v.det * c.box_center + v.adj_b;
    const double along = v.culled_sign * glm::dot(c.box_axis[0], g);
    if (!(along > 0.0)) return false;  // facing the culled way at most partly
    const double across = std::sqrt(std::max(0.0, glm::dot(g, g) - along * along));
    const double spread = v.abs_det * (c.box_half.x + c.sin_angle * (c.box_half.y + c.box_half.z));
    const double margin = c.cos_angle * along - c.sin_angle * across - spread -
                          kMarginSlack * (along + across + spread);
    if (!(margin > 0.0)) return false;

    // The cluster in clip space, per row r of the mvp: the value at the box's center, its
    // spread over the box, and the rounding of the float transform. And the most a row changes
    // along a triangle's edge d: each box axis' component of d is at most the box's extent
    // along it and at most the longest edge.
    const glm::dvec4 center(c.box_center, 1.0);
    const glm::dvec4 extent(c.max_abs, 1.0);  // bounds |p|
    const glm::dvec3 edge_along(std::min(2.0 * c.box_half.x, c.max_edge),
                                std::min(2.0 * c.box_half.y, c.max_edge),
                                std::min(2.0 * c.box_half.z, c.max_edge));
    struct RowBounds {
        double value, reach, error, edge_change;
    };
    const auto row_bounds = [&](int r) {
        const glm::dvec3 row(v.row[r]);
        const glm::dvec3 on_axes(std::abs(glm::dot(row, c.box_axis[0])),
                                 std::abs(glm::dot(row, c.box_axis[1])),
                                 std::abs(glm::dot(row, c.box_axis[2])));
        const double error = kClipError * glm::dot(v.abs_row[r], extent);
        return RowBounds{glm::dot(v.row[r], center), glm::dot(on_axes, c.box_half) + error, error,
                         glm::dot(on_axes, edge_along) + kSlack * v.row_length[r] * c.max_edge};
    };
    const RowBounds bx = row_bounds(0), by = row_bounds(1), bz = row_bounds(2), bw = row_bounds(3);
    const double w_lo = bw.value - bw.reach, w_hi = bw.value + bw.reach;
    if (!(w_lo > 0.0) || !(w_hi < 1e30)) return false;
    // Inside the guard band with room for the float products (|x| <= guard * w in float).
    const double x_hi = std::abs(bx.value) + bx.reach, y_hi = std::abs(by.value) + by.reach;
    if (!(x_hi <= v.guard_x * w_lo * kShrink) || !(y_hi <= v.guard_y * w_lo * kShrink))
        return false;
    const double near_distance = v.zero_to_one ? bz.value - bz.reach : bz.value - bz.reach + w_lo;
    if (!(near_distance > 0.0) || !(w_lo - (bz.value + bz.reach) > 0.0)) return false;

    // delta: the largest error of a snapped coordinate, in pixels.
    const double inv_w = 1.0 / w_lo;
    const double ndc_x = x_hi * inv_w, ndc_y = y_hi * inv_w;  // bounds of |x / w|, |y / w|
    const double double_error = 0x1p-48 * (ndc_x + ndc_y + 2.0) * (v.half_width + v.half_height);
    const double delta_x = v.half_width * (bx.error + ndc_x * bw.error) * inv_w;
    const double delta_y = v.half_height * (by.error + ndc_y * bw.error) * inv_w;
    const double delta = std::max(delta_x, delta_y) + 1.0 / 512.0 + double_error;
    // Window extents of a triangle: x/w changes along an edge d by at most
    // (|x/w| |w . d| + |x . d|) / w.
    const double extent_x = v.half_width * (ndc_x * bw.edge_change + bx.edge_change) * inv_w;
    const double extent_y = v.half_height * (ndc_y * bw.edge_change + by.edge_change) * inv_w;
    const double area = v.area_scale * c.min_double_area * margin / (w_hi * w_hi * w_hi);
    const double area_error = 4.0 * delta * (extent_x + extent_y) + 8.0 * delta * delta;
    return area > 2.0 * area_error;
}

ClusterArrays::ClusterArrays(const std::vector<ClusterBounds>& bounds) : count(bounds.size()) {
    const auto fill = [&](std::vector<double>& field, auto get) {
        field.resize(count);
        for (std::size_t c = 0; c < count; ++c) field[c] = get(bounds[c]);
    };
    for (int k = 0; k < 3; ++k) {
        fill(center[k], [k](const ClusterBounds& b) { return b.box_center[k]; });
        fill(half[k], [k](const ClusterBounds& b) { return b.box_half[k]; });
        fill(max_abs[k], [k](const ClusterBounds& b) { return b.max_abs[k]; });
        for (int j = 0; j < 3; ++j)
            fill(axis[k][j], [k, j](const ClusterBounds& b) { return b.box_axis[k][j]; });
    }
    fill(cos_angle, [](const ClusterBounds& b) { return b.cos_angle; });
    fill(sin_angle, [](const ClusterBounds& b) { return b.sin_angle; });
    fill(min_double_area, [](const ClusterBounds& b) { return b.min_double_area; });
    fill(max_edge, [](const ClusterBounds& b) { return b.max_edge; });
    index_hash.resize(count);
    for (std::size_t c = 0; c < count; ++c) index_hash[c] = bounds[c].index_hash;
}

ClusterBounds ClusterArrays::operator[](std::size_t c) const {
    ClusterBounds b;
    for (int k = 0; k < 3; ++k) {
        b.box_center[k] = center[k][c];
        b.box_half[k] = half[k][c];
        b.max_abs[k] = max_abs[k][c];
        for (int j = 0; j < 3; ++j) b.box_axis[k][j] = axis[k][j][c];
    }
    b.cos_angle = cos_angle[c];
    b.sin_angle = sin_angle[c];
    b.min_double_area = min_double_area[c];
    b.max_edge = max_edge[c];
    b.index_hash = index_hash[c];
    return b;
}

}  // namespace zraster::detail
