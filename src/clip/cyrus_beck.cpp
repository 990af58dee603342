// Cyrus-Beck line clipping against a convex window (Cyrus & Beck 1978, "Generalized two- and
// three-dimensional clipping", Computers & Graphics 3(1)).
//
// What: the segment is a + t d, t in [0, 1]. For each window edge with inward normal n through
// point v, dot(n, a + t d - v) >= 0 is an inequality in t: the line enters the half-plane
// (dot(n, d) > 0) or leaves it (dot(n, d) < 0) at t = -dot(n, a - v) / dot(n, d), or is parallel
// to it (dot(n, d) = 0). The kept part is [max of entries and 0, min of exits and 1], if not empty.
// Liang-Barsky is exactly this with the four axis-aligned normals of a rectangle.
// Cost: the signed distances of both endpoints to every edge (2 dot products per edge) decide the
// trivial cases; a crossing segment then costs one dot product and one division per edge: O(n).
// When: convex windows that are not axis-aligned rectangles (rotated viewports, convex portals,
// the kernel of a star-shaped region). For rectangles Liang-Barsky does the same with fewer
// operations.
#include <zraster/line_clip.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace zraster {
namespace {

double cross(const glm::dvec2& u, const glm::dvec2& v) {
    return u.x * v.y - u.y * v.x;
}

}  // namespace

ConvexWindow make_convex_window(std::span<const glm::dvec2> polygon) {
    const std::size_t n = polygon.size();
    if (n < 3) throw std::invalid_argument("convex window: fewer than 3 vertices");
    double twice_area = 0.0;
    for (std::size_t i = 0; i < n; ++i) twice_area += cross(polygon[i], polygon[(i + 1) % n]);
    if (!(twice_area != 0.0)) throw std::invalid_argument("convex window: zero or undefined area");
    ConvexWindow w;
    w.vertices.assign(polygon.begin(), polygon.end());
    if (twice_area < 0.0) std::reverse(w.vertices.begin(), w.vertices.end());
    w.inward_normals.resize(n);
    double turning = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 e = w.vertices[(i + 1) % n] - w.vertices[i];
        const glm::dvec2 next = w.vertices[(i + 2) % n] - w.vertices[(i + 1) % n];
        if (e == glm::dvec2(0.0)) throw std::invalid_argument("convex window: repeated vertex");
        if (cross(e, next) < 0.0) throw std::invalid_argument("convex window: not convex");
        turning += std::atan2(cross(e, next), glm::dot(e, next));
        // The left normal of a counter-clockwise edge points inside. Axis-aligned edges get exact
        // unit normals so that a rectangle reproduces Liang-Barsky's arithmetic exactly.
        if (e.x == 0.0)
            w.inward_normals[i] = {e.y > 0.0 ? -1.0 : 1.0, 0.0};
        else if (e.y == 0.0)
            w.inward_normals[i] = {0.0, e.x > 0.0 ? 1.0 : -1.0};
        else
            w.inward_normals[i] = glm::dvec2(-e.y, e.x) / glm::length(e);
    }
    // Left turns only, but winding more than once (a pentagram) is not convex either: the
    // exterior angles of a convex polygon sum to exactly one turn.
    if (turning > 3.0 * std::acos(-1.0))
        throw std::invalid_argument("convex window: self-intersecting (winds more than once)");
    return w;
}

ConvexWindow make_convex_window(const ClipRect& r) {
    if (!(r.x_min < r.x_max && r.y_min < r.y_max))
        throw std::invalid_argument("convex window: empty rectangle");
    const glm::dvec2 corners[4] = {
        {r.x_min, r.y_min}, {r.x_max, r.y_min}, {r.x_max, r.y_max}, {r.x_min, r.y_max}};
    return make_convex_window(corners);
}

ClippedLine2 clip_line_cyrus_beck(glm::dvec2 a, glm::dvec2 b, const ConvexWindow& w,
                                  LineClipStats* stats) {
    LineClipStats s;
    s.segments = 1;
    ClippedLine2 result;
    const std::size_t n = w.vertices.size();
    // The generalized outcode test: the signed distances of both endpoints to each edge. Both
    // inside every edge: accept; both outside one edge: reject. No division yet.
    bool all_inside = true, common_outside = false;
    for (std::size_t i = 0; i < n && !common_outside; ++i) {
        const double da = glm::dot(w.inward_normals[i], a - w.vertices[i]);
        const double db = glm::dot(w.inward_normals[i], b - w.vertices[i]);
        all_inside = all_inside && da >= 0.0 && db >= 0.0;
        common_outside = da < 0.0 && db < 0.0;
    }
    if (common_outside) {
        ++s.trivial_rejects;
    } else if (all_inside) {
        ++s.trivial_accepts;
        result = {true, a, b};
    } else {
        const glm::dvec2 d = b - a;
        double t0 = 0.0, t1 = 1.0;
        bool entered = false, left = false, visible = true;
        for (std::size_t i = 0; i < n && visible; ++i) {
            const double num = glm::dot(w.inward_normals[i], a - w.vertices[i]);
            const double den = glm::dot(w.inward_normals[i], d);
            if (den == 0.0) {
                visible = num >= 0.0;  // parallel to this edge: inside its half-plane, or not
                continue;
            }
            const double t = -(num / den);
            ++s.subdivisions;
            if (den > 0.0) {
                if (t > t0) t0 = t, entered = true;
            } else {
                if (t < t1) t1 = t, left = true;
            }
            visible = t0 <= t1;
        }
        // An end that was not moved keeps its input value (a + 1 * d need not round to b).
        if (visible) result = {true, entered ? a + t0 * d : a, left ? a + t1 * d : b};
    }
    if (stats) *stats += s;
    return result;
}

}  // namespace zraster
