// Convex polygon helpers (convex_polygon.hpp).
#include "geometry/convex_polygon.hpp"

#include <algorithm>

namespace zraster::detail {
namespace {

// One Sutherland-Hodgman pass with a signed distance function.
template <class Point, class Distance>
void clip_by(std::vector<Point>& polygon, std::vector<Point>& scratch, Distance distance) {
    scratch.clear();
    const std::size_t n = polygon.size();
    if (n == 0) return;
    for (std::size_t i = 0; i < n; ++i) {
        const Point& a = polygon[i];
        const Point& b = polygon[(i + 1) % n];
        const double da = distance(a), db = distance(b);
        if (da >= 0.0) scratch.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) scratch.push_back(a + (b - a) * (da / (da - db)));
    }
    polygon.swap(scratch);
}

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

void clip_polygon(std::vector<glm::dvec3>& polygon, const glm::dvec4& plane,
                  std::vector<glm::dvec3>& scratch) {
    clip_by(polygon, scratch,
            [&](const glm::dvec3& p) { return glm::dot(glm::dvec3(plane), p) + plane.w; });
}

void clip_homogeneous(std::vector<glm::dvec3>& polygon, const glm::dvec3& half_plane,
                      std::vector<glm::dvec3>& scratch) {
    clip_by(polygon, scratch, [&](const glm::dvec3& p) { return glm::dot(half_plane, p); });
}

void convex_hull(std::vector<glm::dvec2>& points, std::vector<glm::dvec2>& scratch) {
    std::sort(points.begin(), points.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return;
    scratch.assign(2 * points.size(), glm::dvec2(0.0));
    std::size_t k = 0;
    for (const glm::dvec2& p : points) {  // lower hull
        while (k >= 2 && cross(scratch[k - 2], scratch[k - 1], p) <= 0.0) --k;
        scratch[k++] = p;
    }
    const std::size_t lower = k + 1;
    for (std::size_t i = points.size() - 1; i-- > 0;) {  // upper hull
        while (k >= lower && cross(scratch[k - 2], scratch[k - 1], points[i]) <= 0.0) --k;
        scratch[k++] = points[i];
    }
    scratch.resize(k - 1);  // (the last point is the first)
    points.swap(scratch);
}

double twice_area(const std::vector<glm::dvec2>& polygon) {
    double sum = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec2& a = polygon[i];
        const glm::dvec2& b = polygon[(i + 1) % polygon.size()];
        sum += a.x * b.y - a.y * b.x;
    }
    return sum;
}

void clip_to_convex(std::vector<glm::dvec2>& polygon, const std::vector<glm::dvec2>& window,
                    std::vector<glm::dvec2>& scratch) {
    for (std::size_t i = 0; i < window.size() && !polygon.empty(); ++i) {
        const glm::dvec2 a = window[i];
        const glm::dvec2 b = window[(i + 1) % window.size()];
        clip_by(polygon, scratch, [&](const glm::dvec2& p) { return cross(a, b, p); });
    }
}

}  // namespace zraster::detail
