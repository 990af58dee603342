// Sutherland-Hodgman polygon clipping in 2D against a convex window (Sutherland & Hodgman 1974,
// "Reentrant polygon clipping", Communications of the ACM 17(1)).
//
// What: the polygon is clipped against one window edge's half-plane at a time; each stage walks
// the polygon's edges and emits the inside vertices plus the crossing points, so the output of one
// stage is a polygon again and feeds the next.
// Cost: O(n x m) for n polygon vertices and m window edges: per stage one signed distance per
// vertex and one division per crossing edge. The output has at most n + m vertices for a convex
// input, more (up to 3n/2 per stage) for a concave one.
// When: clipping polygons (not segments) against convex regions: the screen rectangle, a guard
// band, a convex portal. The subject may be concave, but the output is then one polygon with
// zero-width bridges along the window boundary (see polygon_clip.hpp); for concave windows, or
// when the pieces must come out separate, use Weiler-Atherton or Greiner-Hormann instead.
#include <zraster/polygon_clip.hpp>

namespace zraster {

std::vector<glm::dvec2> clip_polygon_sutherland_hodgman(std::span<const glm::dvec2> polygon,
                                                        const ConvexWindow& window) {
    std::vector<glm::dvec2> current(polygon.begin(), polygon.end()), next;
    std::vector<double> distance;
    for (std::size_t e = 0; e < window.vertices.size() && !current.empty(); ++e) {
        const glm::dvec2 normal = window.inward_normals[e];
        const glm::dvec2 origin = window.vertices[e];
        const std::size_t n = current.size();
        distance.resize(n);
        for (std::size_t i = 0; i < n; ++i) distance[i] = glm::dot(normal, current[i] - origin);
        next.clear();
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = i + 1 == n ? 0 : i + 1;
            const bool i_in = distance[i] >= 0.0, j_in = distance[j] >= 0.0;
            if (i_in) next.push_back(current[i]);
            if (i_in == j_in) continue;
            // From the inside vertex towards the outside one, as in homogeneous_clip.cpp: an edge
            // shared by two polygons (in either direction) is cut at the same point.
            const std::size_t in = i_in ? i : j, out = i_in ? j : i;
            const double t = distance[in] / (distance[in] - distance[out]);
            glm::dvec2 p = current[in] + t * (current[out] - current[in]);
            // On an axis-aligned edge put the point exactly on the boundary, so bridges and
            // pieces on it line up exactly.
            if (normal.y == 0.0) p.x = origin.x;
            if (normal.x == 0.0) p.y = origin.y;
            next.push_back(p);
        }
        std::swap(current, next);
    }
    if (current.size() < 3) current.clear();
    return current;
}

}  // namespace zraster
