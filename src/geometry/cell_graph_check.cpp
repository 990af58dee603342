// validate_cell_graph: the checks that make portal culling exact for a scene (portals.hpp).
#include <zraster/error.hpp>
#include <zraster/instance_bvh.hpp>
#include <zraster/portals.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace zraster {
namespace {

std::string cell_label(const CellGraph& graph, std::size_t c) {
    return "cells[" + std::to_string(c) + "] '" + graph.cells[c].name + "'";
}

std::string instance_label(std::span<const std::string> names, std::size_t i) {
    return "instance " + std::to_string(i) +
           (i < names.size() && !names[i].empty() ? " '" + names[i] + "'" : std::string());
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check_counts(const CellGraph& graph, std::size_t instances, const std::string& source) {
    const CellGraphLimits& limits = graph.limits;
    if (graph.cells.empty()) throw InputError(source, "cells: there are none");
    if (graph.cells.size() > limits.max_cells)
        throw InputError(source, "cells: " + std::to_string(graph.cells.size()) +
                                     " cells, more than the limit of " +
                                     std::to_string(limits.max_cells));
    if (graph.portals.size() > limits.max_portals)
        throw InputError(source, "portals: " + std::to_string(graph.portals.size()) +
                                     " portals, more than the limit of " +
                                     std::to_string(limits.max_portals));
    for (std::size_t c = 0; c < graph.cells.size(); ++c) {
        const Cell& cell = graph.cells[c];
        if (cell.volume.corners.empty())
            throw InputError(source, cell_label(graph, c) + ": has no volume");
        for (const std::uint32_t i : cell.instances)
            if (i >= instances)
                throw InputError(source, cell_label(graph, c) + ": instance " + std::to_string(i) +
                                             " is not in the scene (" + std::to_string(instances) +
                                             " instances)");
    }
}

// Newell's normal: its length is twice the polygon's area, also for non-planar input.
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& corners) {
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3& a = corners[i];
        const glm::dvec3& b = corners[(i + 1) % corners.size()];
        n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                        (a.x - b.x) * (a.y + b.y));
    }
    return n;
}

// Convex: every turn the same way (straight runs allowed) and one turn around in all.
bool convex(const std::vector<glm::dvec3>& corners, const glm::dvec3& normal, double tolerance) {
    const std::size_t n = corners.size();
    double turning = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 e0 = corners[(i + 1) % n] - corners[i];
        const glm::dvec3 e1 = corners[(i + 2) % n] - corners[(i + 1) % n];
        if (glm::length(e0) <= tolerance || glm::length(e1) <= tolerance) return false;
        const double sine = glm::dot(glm::cross(e0, e1), normal);
        if (sine < -tolerance * (glm::length(e0) + glm::length(e1))) return false;
        turning += std::atan2(sine, glm::dot(e0, e1));
    }
    return std::abs(turning - 2.0 * std::numbers::pi) < 1e-6;
}

bool inside(const CellVolume& volume, const glm::dvec3& p, double tolerance) {
    for (const glm::dvec4& plane : volume.planes)
        if (glm::dot(glm::dvec3(plane), p) + plane.w < -tolerance) return false;
    return true;
}

void check_portal(const CellGraph& graph, std::size_t index, double tolerance,
                  const std::string& source) {
    const Portal& portal = graph.portals[index];
    const std::string label = "portals[" + std::to_string(index) + "]";
    const auto fail = [&](const std::string& cause) {
        throw InputError(source, label + ": " + cause);
    };
    for (const std::uint32_t c : portal.cells)
        if (c >= graph.cells.size())
            fail("names cell " + std::to_string(c) + ", which does not exist (" +
                 std::to_string(graph.cells.size()) + " cells)");
    if (portal.cells[0] == portal.cells[1])
        fail("joins " + cell_label(graph, portal.cells[0]) + " to itself");
    if (portal.corners.size() < 3 || portal.corners.size() > graph.limits.max_portal_corners)
        fail(std::to_string(portal.corners.size()) + " corners (a portal has 3 to " +
             std::to_string(graph.limits.max_portal_corners) + ")");
    for (const glm::dvec3& p : portal.corners)
        if (!finite(p)) fail("a corner is not finite");
    const glm::dvec3 newell = newell_normal(portal.corners);
    if (glm::length(newell) <= tolerance * tolerance) fail("has no area");
    const glm::dvec3 normal = glm::normalize(newell);
    glm::dvec3 centroid(0.0);
    for (const glm::dvec3& p : portal.corners) centroid += p;
    centroid /= double(portal.corners.size());
    for (std::size_t k = 0; k < portal.corners.size(); ++k) {
        const double off = std::abs(glm::dot(portal.corners[k] - centroid, normal));
        if (off > tolerance)
            fail("is not planar (corner " + std::to_string(k) + " is " + std::to_string(off) +
                 " off the portal's plane)");
    }
    if (!convex(portal.corners, normal, tolerance)) fail("is not convex");
    for (const std::uint32_t c : portal.cells)
        for (std::size_t k = 0; k < portal.corners.size(); ++k)
            if (!inside(graph.cells[c].volume, portal.corners[k], tolerance))
                fail("corner " + std::to_string(k) + " lies outside " + cell_label(graph, c));
    // On the boundary of both cells: in the plane of a face of each, the two cells on opposite
    // sides of it. Corners inside a cell are not enough: a portal through a cell's interior, or
    // between cells that overlap, lets a ray pass from one cell to the other without crossing it,
    // which the walk (and the PVS) cannot follow.
    glm::dvec3 inward[2];
    for (int side = 0; side < 2; ++side) {
        const std::uint32_t c = portal.cells[side];
        const glm::dvec3* face = nullptr;
        for (const glm::dvec4& plane : graph.cells[c].volume.planes) {
            const double length = glm::length(glm::dvec3(plane));
            const bool holds_all =
                std::all_of(portal.corners.begin(), portal.corners.end(), [&](const glm::dvec3& p) {
                    return std::abs(glm::dot(glm::dvec3(plane), p) + plane.w) <= tolerance * length;
                });
            if (holds_all) {
                inward[side] = glm::dvec3(plane) / length;
                face = &inward[side];
                break;
            }
        }
        if (face == nullptr)
            fail("does not lie in a face of " + cell_label(graph, c) +
                 " (a portal is on the boundary of both its cells)");
    }
    if (glm::dot(inward[0], inward[1]) >= 0.0)
        fail("has " + cell_label(graph, portal.cells[0]) + " and " +
             cell_label(graph, portal.cells[1]) +
             " on the same side (a portal joins cells on either side of it)");
}

// Whether the box (grown by the tolerance) meets the cell: separated along a box axis or a cell
// plane means no. (Edge-edge axes are not tried: at worst a box near a polyhedron's edge is
// taken as touching it, and must be listed there.)
bool touches(const CellVolume& volume, const Bounds3f& box, double tolerance) {
    const glm::dvec3 lo = glm::dvec3(box.lo) - tolerance, hi = glm::dvec3(box.hi) + tolerance;
    if (glm::any(glm::lessThan(hi, volume.lo)) || glm::any(glm::greaterThan(lo, volume.hi)))
        return false;
    for (const glm::dvec4& plane : volume.planes) {
        const glm::dvec3 n(plane);
        const glm::dvec3 far(n.x >= 0 ? hi.x : lo.x, n.y >= 0 ? hi.y : lo.y,
                             n.z >= 0 ? hi.z : lo.z);
        if (glm::dot(n, far) + plane.w < 0.0) return false;
    }
    return true;
}

void check_instances(CellGraph& graph, std::span<const Bounds3f> boxes,
                     std::span<const std::string> names, double tolerance,
                     const std::string& source) {
    graph.instance_cells.assign(boxes.size(), {});
    for (std::uint32_t c = 0; c < graph.cells.size(); ++c)
        for (const std::uint32_t i : graph.cells[c].instances) graph.instance_cells[i].push_back(c);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        std::vector<std::uint32_t>& cells = graph.instance_cells[i];
        std::sort(cells.begin(), cells.end());
        cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
        if (cells.empty()) throw InputError(source, instance_label(names, i) + " is in no cell");
    }
    // Which cells each instance's box touches, through a BVH of the cells' boxes.
    std::vector<Bounds3f> cell_boxes;
    for (const Cell& cell : graph.cells)
        cell_boxes.push_back(Bounds3f{glm::vec3(cell.volume.lo), glm::vec3(cell.volume.hi)});
    const InstanceBvh bvh(cell_boxes);
    std::vector<std::uint32_t> near;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Bounds3f& box = boxes[i];
        if (box.empty()) continue;
        const glm::vec3 lo = box.lo - float(tolerance), hi = box.hi + float(tolerance);
        const glm::vec4 planes[6] = {{1, 0, 0, -lo.x}, {-1, 0, 0, hi.x}, {0, 1, 0, -lo.y},
                                     {0, -1, 0, hi.y}, {0, 0, 1, -lo.z}, {0, 0, -1, hi.z}};
        near.clear();
        bvh.query(planes, near);
        for (const std::uint32_t c : near) {
            if (std::binary_search(graph.instance_cells[i].begin(), graph.instance_cells[i].end(),
                                   c) ||
                !touches(graph.cells[c].volume, box, tolerance))
                continue;
            throw InputError(source, instance_label(names, i) + " reaches into " +
                                         cell_label(graph, c) +
                                         ", which does not list it (list an instance in every "
                                         "cell its bounds touch)");
        }
    }
}

}  // namespace

void validate_cell_graph(CellGraph& graph, std::span<const Bounds3f> instance_boxes,
                         std::span<const std::string> instance_names, const std::string& source) {
    check_counts(graph, instance_boxes.size(), source);
    const double tolerance = cell_tolerance(graph);
    for (std::size_t p = 0; p < graph.portals.size(); ++p)
        check_portal(graph, p, tolerance, source);
    check_instances(graph, instance_boxes, instance_names, tolerance, source);
    graph.cell_portals.assign(graph.cells.size(), {});
    for (std::uint32_t p = 0; p < graph.portals.size(); ++p)
        for (const std::uint32_t c : graph.portals[p].cells) graph.cell_portals[c].push_back(p);
    if (!graph.pvs.empty() && graph.pvs.size() != graph.cells.size())
        throw InputError(source, "the potentially visible sets are for " +
                                     std::to_string(graph.pvs.size()) + " cells, the graph has " +
                                     std::to_string(graph.cells.size()));
}

}  // namespace zraster
