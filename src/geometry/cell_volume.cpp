// Convex cell volumes: boxes, and intersections of half-spaces with their corners found from
// every triple of planes (a cell has at most CellGraphLimits::max_cell_planes planes).
#include <zraster/error.hpp>
#include <zraster/portals.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace zraster {
namespace {

bool finite(const glm::dvec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

double plane_distance(const glm::dvec4& plane, const glm::dvec3& p) {
    return glm::dot(glm::dvec3(plane), p) + plane.w;
}

// Unbounded exactly when some direction u != 0 has dot(n, u) >= 0 for every normal: such a cone
// has an extreme ray where two of the planes meet (u = +-n_i x n_j), or all normals lie in one
// plane.
bool unbounded(const std::vector<glm::dvec4>& planes) {
    bool three_dimensional = false;
    for (std::size_t i = 0; i < planes.size(); ++i)
        for (std::size_t j = i + 1; j < planes.size(); ++j) {
            const glm::dvec3 ray = glm::cross(glm::dvec3(planes[i]), glm::dvec3(planes[j]));
            if (glm::length(ray) < 1e-9) continue;
            for (const double sign : {1.0, -1.0}) {
                const glm::dvec3 u = sign * glm::normalize(ray);
                bool escapes = true;
                for (const glm::dvec4& p : planes) {
                    if (glm::dot(glm::dvec3(p), u) < -1e-9) {
                        escapes = false;
                        break;
                    }
                }
                if (escapes) return true;
            }
            for (const glm::dvec4& p : planes)
                three_dimensional |= std::abs(glm::dot(glm::dvec3(p), ray)) > 1e-9;
        }
    return !three_dimensional;
}

void set_bounds(CellVolume& volume) {
    volume.lo = volume.hi = volume.corners.front();
    for (const glm::dvec3& c : volume.corners) {
        volume.lo = glm::min(volume.lo, c);
        volume.hi = glm::max(volume.hi, c);
    }
}

}  // namespace

CellVolume box_volume(const glm::dvec3& lo, const glm::dvec3& hi) {
    CellVolume v;
    v.planes = {{1, 0, 0, -lo.x}, {-1, 0, 0, hi.x}, {0, 1, 0, -lo.y},
                {0, -1, 0, hi.y}, {0, 0, 1, -lo.z}, {0, 0, -1, hi.z}};
    for (int i = 0; i < 8; ++i)
        v.corners.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    v.lo = lo;
    v.hi = hi;
    return v;
}

CellVolume convex_volume(std::span<const glm::dvec4> planes) {
    CellVolume v;
    for (std::size_t i = 0; i < planes.size(); ++i) {
        const double length = glm::length(glm::dvec3(planes[i]));
        if (!finite(planes[i]) || !(length > 0.0))
            throw InputError("", "plane " + std::to_string(i) +
                                     " has a zero or non-finite normal (or a non-finite offset)");
        v.planes.push_back(planes[i] / length);
    }
    if (v.planes.size() < 4 || unbounded(v.planes))
        throw InputError("",
                         "the planes bound no finite volume (a cell needs at least 4 planes "
                         "whose inward normals point every way)");
    double scale = 1.0;
    for (const glm::dvec4& p : v.planes) scale = std::max(scale, std::abs(p.w));
    const double tolerance = kCellTolerance * scale;
    const std::size_t n = v.planes.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            for (std::size_t k = j + 1; k < n; ++k) {
                const glm::dmat3 m = glm::transpose(glm::dmat3(
                    glm::dvec3(v.planes[i]), glm::dvec3(v.planes[j]), glm::dvec3(v.planes[k])));
                if (std::abs(glm::determinant(m)) < 1e-12) continue;
                const glm::dvec3 p =
                    glm::inverse(m) * -glm::dvec3(v.planes[i].w, v.planes[j].w, v.planes[k].w);
                bool inside = true;
                for (const glm::dvec4& plane : v.planes)
                    inside &= plane_distance(plane, p) >= -tolerance;
                bool known = false;
                for (const glm::dvec3& c : v.corners) known |= glm::length(c - p) <= tolerance;
                if (inside && !known) v.corners.push_back(p);
            }
    if (v.corners.size() < 4) throw InputError("", "the planes bound no volume (empty or flat)");
    set_bounds(v);
    const glm::dvec3 extent = v.hi - v.lo;
    if (std::min({extent.x, extent.y, extent.z}) <= tolerance)
        throw InputError("", "the planes bound no volume (flat)");
    return v;
}

double cell_tolerance(const CellGraph& graph) {
    double scale = 1.0;
    for (const Cell& cell : graph.cells)
        scale = std::max({scale, glm::length(cell.volume.lo), glm::length(cell.volume.hi)});
    return kCellTolerance * scale;
}

std::int64_t find_cell(const CellGraph& graph, const glm::dvec3& p) {
    const double tolerance = cell_tolerance(graph);
    for (std::size_t c = 0; c < graph.cells.size(); ++c) {
        bool inside = true;
        for (const glm::dvec4& plane : graph.cells[c].volume.planes)
            inside &= plane_distance(plane, p) >= -tolerance;
        if (inside) return std::int64_t(c);
    }
    return -1;
}

}  // namespace zraster
