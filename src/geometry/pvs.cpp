// Potentially visible sets by portal sequences with separating planes (portals.hpp): Teller &
// Sequin 1991 ("Visibility preprocessing for interactive walkthroughs") bound the lines through
// a portal sequence with the planes that separate two of its portals; this is the conservative
// form of it that clips each next portal to those planes (as Quake's vis does) instead of
// solving for a stabbing line.
#include <zraster/portals.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "geometry/convex_polygon.hpp"

namespace zraster {
namespace {

using Polygon = std::vector<glm::dvec3>;

glm::dvec3 centroid(const std::vector<glm::dvec3>& points) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& p : points) sum += p;
    return sum / double(points.size());
}

// The portal's plane, normalized, facing `toward` (positive on its side).
glm::dvec4 portal_plane(const Portal& portal, const glm::dvec3& toward) {
    const Polygon& c = portal.corners;
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < c.size(); ++i) n += glm::cross(c[i], c[(i + 1) % c.size()]);
    n = glm::normalize(n);
    const double d = -glm::dot(n, centroid(c));
    return glm::dot(n, toward) + d >= 0.0 ? glm::dvec4(n, d) : -glm::dvec4(n, d);
}

class PvsSearch {
  public:
    PvsSearch(const CellGraph& graph, const PvsOptions& options)
        : graph_(graph), options_(options), on_path_(graph.cells.size(), 0) {
        for (const Cell& cell : graph.cells) cell_centers_.push_back(centroid(cell.volume.corners));
    }

    // The cells seen from `source`; false when the step bound was hit.
    bool run(std::uint32_t source, std::vector<std::uint8_t>& seen, std::uint64_t& steps) {
        steps_ = 0;
        seen_ = &seen;
        seen[source] = 1;
        on_path_[source] = 1;
        bool complete = true;
        for (const std::uint32_t p : graph_.cell_portals[source]) {
            const std::uint32_t next = other(p, source);
            seen[next] = 1;
            const glm::dvec4 plane = portal_plane(graph_.portals[p], cell_centers_[next]);
            on_path_[next] = 1;
            complete = complete && follow(next, p, graph_.portals[p].corners, plane,
                                          graph_.portals[p].corners, plane, 1);
            on_path_[next] = 0;
        }
        on_path_[source] = 0;
        steps += steps_;
        return complete;
    }

  private:
    std::uint32_t other(std::uint32_t portal, std::uint32_t cell) const {
        const auto& cells = graph_.portals[portal].cells;
        return cells[0] == cell ? cells[1] : cells[0];
    }

    void clip(Polygon& q, const glm::dvec4& plane) {
        detail::clip_polygon(q, plane + glm::dvec4(0, 0, 0, options_.slack), scratch_);
    }

    // Planes through an edge of one portal and a corner of the other with `from` on their
    // negative side and `to` on their positive side.
    void clip_by_separators(Polygon& q, const Polygon& from, const Polygon& to) {
        for (int pass = 0; pass < 2 && !q.empty(); ++pass) {
            const Polygon& edges = pass == 0 ? from : to;
            const Polygon& apexes = pass == 0 ? to : from;
            for (std::size_t e = 0; e < edges.size() && !q.empty(); ++e) {
                const glm::dvec3 a = edges[e], b = edges[(e + 1) % edges.size()];
                for (const glm::dvec3& v : apexes) {
                    glm::dvec3 n = glm::cross(b - a, v - a);
                    const double length = glm::length(n);
                    if (!(length > 1e-12)) continue;
                    n /= length;
                    glm::dvec4 plane(n, -glm::dot(n, a));
                    if (separates(-plane, from, to))
                        plane = -plane;
                    else if (!separates(plane, from, to))
                        continue;
                    clip(q, plane);
                    if (q.empty()) return;
                }
            }
        }
    }

    static bool separates(const glm::dvec4& plane, const Polygon& from, const Polygon& to) {
        constexpr double kOn = 1e-9;
        for (const glm::dvec3& p : from)
            if (glm::dot(glm::dvec3(plane), p) + plane.w > kOn) return false;
        for (const glm::dvec3& p : to)
            if (glm::dot(glm::dvec3(plane), p) + plane.w < -kOn) return false;
        return true;
    }

    // In `cell`, entered through `entry` (clipped: `last`, plane `last_plane`), from the source
    // portal `source` (plane `source_plane`).
    bool follow(std::uint32_t cell, std::uint32_t entry, const Polygon& source,
                const glm::dvec4& source_plane, const Polygon& last, const glm::dvec4& last_plane,
                std::size_t depth) {
        if (depth > graph_.cells.size()) return false;
        for (const std::uint32_t p : graph_.cell_portals[cell]) {
            const std::uint32_t next = other(p, cell);
            if (p == entry || on_path_[next]) continue;
            if (++steps_ > options_.max_steps_per_cell) return false;
            Polygon q = graph_.portals[p].corners;
            clip(q, source_plane);
            if (!q.empty()) clip(q, last_plane);
            if (!q.empty() && &last != &source) clip_by_separators(q, source, last);
            if (q.empty()) continue;
            (*seen_)[next] = 1;
            const glm::dvec4 plane = portal_plane(graph_.portals[p], cell_centers_[next]);
            on_path_[next] = 1;
            const bool complete = follow(next, p, source, source_plane, q, plane, depth + 1);
            on_path_[next] = 0;
            if (!complete) return false;
        }
        return true;
    }

    const CellGraph& graph_;
    const PvsOptions& options_;
    std::vector<std::uint8_t> on_path_;
    std::vector<glm::dvec3> cell_centers_;
    std::vector<std::uint8_t>* seen_ = nullptr;
    std::size_t steps_ = 0;
    Polygon scratch_;
};

// Every cell connected to `source` through portals: the fallback past the step bound.
void connected_cells(const CellGraph& graph, std::uint32_t source,
                     std::vector<std::uint8_t>& seen) {
    std::vector<std::uint32_t> stack{source};
    seen[source] = 1;
    while (!stack.empty()) {
        const std::uint32_t cell = stack.back();
        stack.pop_back();
        for (const std::uint32_t p : graph.cell_portals[cell])
            for (const std::uint32_t next : graph.portals[p].cells)
                if (!seen[next]) {
                    seen[next] = 1;
                    stack.push_back(next);
                }
    }
}

}  // namespace

PotentiallyVisibleSets compute_pvs(const CellGraph& graph, const PvsOptions& options) {
    assert(graph.cell_portals.size() == graph.cells.size());
    PotentiallyVisibleSets out;
    const std::size_t n = graph.cells.size();
    out.visible.resize(n);
    out.bounded.assign(n, 0);
    PvsSearch search(graph, options);
    std::vector<std::uint8_t> seen;
    for (std::uint32_t s = 0; s < n; ++s) {
        seen.assign(n, 0);
        if (!search.run(s, seen, out.steps)) {
            out.bounded[s] = 1;
            connected_cells(graph, s, seen);
        }
        for (std::uint32_t c = 0; c < n; ++c)
            if (seen[c]) out.visible[s].push_back(c);
    }
    return out;
}

}  // namespace zraster
