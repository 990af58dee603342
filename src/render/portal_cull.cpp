// The portal walk (portal_cull.hpp).
#include "render/portal_cull.hpp"

#include <zraster/instance_bvh.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "geometry/convex_polygon.hpp"

namespace zraster::detail {
namespace {

// Regions of less area than this (NDC units squared) are empty: a region always holds a disk
// of kPortalMarginPixels around every pixel center it must keep, far larger.
constexpr double kEmptyArea = 1e-12;

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return glm::length(p - (a + t * ab));
}

glm::dvec3 polygon_normal(const std::vector<glm::dvec3>& c) {
    glm::dvec3 n(0.0);
    for (std::size_t i = 0; i < c.size(); ++i) n += glm::cross(c[i], c[(i + 1) % c.size()]);
    return glm::normalize(n);
}

// Distance from p to the convex polygon.
double distance_to_polygon(const glm::dvec3& p, const std::vector<glm::dvec3>& c,
                           const glm::dvec3& normal) {
    bool inside = true;
    for (std::size_t i = 0; i < c.size(); ++i)
        inside &= glm::dot(glm::cross(c[(i + 1) % c.size()] - c[i], p - c[i]), normal) >= 0.0;
    if (inside) return std::abs(glm::dot(p - c[0], normal));
    double d = HUGE_VAL;
    for (std::size_t i = 0; i < c.size(); ++i)
        d = std::min(d, distance_to_segment(p, c[i], c[(i + 1) % c.size()]));
    return d;
}

class Walker {
  public:
    Walker(const PortalWalkInput& in, PortalWalk& walk)
        : in_(in),
          graph_(*in.graph),
          walk_(walk),
          view_projection_(in.view_projection),
          eye_(in.camera.position()),
          perspective_(in.camera.projection != Camera::Projection::Orthographic),
          margin_(2.0 * kPortalMarginPixels / in.width, 2.0 * kPortalMarginPixels / in.height),
          tolerance_(cell_tolerance(graph_)) {
        const auto frustum = frustum_planes(in.view_projection, in.camera.clip_depth_range());
        near_far_[0] = frustum[4];
        near_far_[1] = frustum[5];
        near_ = std::isfinite(in.camera.near) ? std::max(in.camera.near, tolerance_) : tolerance_;
    }

    // False when a bound was passed.
    bool run(std::uint32_t cell) {
        const glm::dvec2 half(1.0 + margin_.x, 1.0 + margin_.y);
        screen_ = {{-half.x, -half.y}, {half.x, -half.y}, {half.x, half.y}, {-half.x, half.y}};
        // (One region per depth, sized once: the walk holds references into it.)
        walk_.regions.resize(std::min(graph_.limits.max_walk_depth, graph_.cells.size()) + 2);
        walk_.regions[0] = screen_;
        return visit(cell, 0);
    }

  private:
    bool visit(std::uint32_t cell, std::size_t depth) {
        if (walk_.visit_list.size() >= graph_.limits.max_walk_visits ||
            depth + 2 >= walk_.regions.size())
            return false;
        add_visit(cell, walk_.regions[depth]);
        walk_.on_path[cell] = 1;
        bool complete = true;
        for (const std::uint32_t p : graph_.cell_portals[cell]) {
            const Portal& portal = graph_.portals[p];
            const std::uint32_t next = portal.cells[0] == cell ? portal.cells[1] : portal.cells[0];
            if (walk_.on_path[next] || !walk_.allowed[next]) continue;
            if (!narrow(portal, next, walk_.regions[depth], walk_.regions[depth + 1])) continue;
            if (!visit(next, depth + 1)) {
                complete = false;
                break;
            }
        }
        walk_.on_path[cell] = 0;
        return complete;
    }

    // The region beyond `portal` seen through `region`; false when nothing is seen through it.
    bool narrow(const Portal& portal, std::uint32_t next, const std::vector<glm::dvec2>& region,
                std::vector<glm::dvec2>& out) {
        const glm::dvec3 normal = polygon_normal(portal.corners);
        if (distance_to_polygon(eye_, portal.corners, normal) <= near_) {
            out = region;  // standing in the doorway: the portal is open
            return true;
        }
        if (perspective_ && !eye_faces(portal, normal, next)) return false;
        // The portal's part in the screen's cone, in homogeneous coordinates (x, y, w): rays
        // through it all have w > 0, so the divide below is safe.
        std::vector<glm::dvec3>& h = walk_.clipped;
        h.clear();
        for (const glm::dvec3& corner : portal.corners) {
            const glm::dvec4 c = view_projection_ * glm::dvec4(corner, 1.0);
            h.push_back({c.x, c.y, c.w});
        }
        const glm::dvec2 half(1.0 + margin_.x, 1.0 + margin_.y);
        for (const glm::dvec3& edge : {glm::dvec3(1, 0, half.x), glm::dvec3(-1, 0, half.x),
                                       glm::dvec3(0, 1, half.y), glm::dvec3(0, -1, half.y)})
            clip_homogeneous(h, edge, walk_.scratch3);
        if (h.empty()) return false;
        out.clear();
        glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
        for (const glm::dvec3& q : h) {
            if (!(q.z > 0.0)) {  // (only the eye itself: keep the whole region)
                out = region;
                return true;
            }
            const glm::dvec2 ndc(q.x / q.z, q.y / q.z);
            lo = glm::min(lo, ndc);
            hi = glm::max(hi, ndc);
            for (const glm::dvec2 corner :
                 {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
                out.push_back(ndc + corner * margin_);
        }
        if (in_.mode == PortalCull::Rectangles) {
            lo -= margin_;
            hi += margin_;
            out = {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
        } else {
            convex_hull(out, walk_.scratch2);
        }
        clip_to_convex(out, region, walk_.scratch2);
        return out.size() >= 3 && twice_area(out) > kEmptyArea;
    }

    // Whether the eye is on the near side of the portal as seen going into `next` (only then can
    // a ray from it pass through into `next`); unsure counts as yes.
    bool eye_faces(const Portal& portal, const glm::dvec3& normal, std::uint32_t next) const {
        const CellVolume& volume = graph_.cells[next].volume;
        glm::dvec3 center(0.0);
        for (const glm::dvec3& c : volume.corners) center += c;
        center /= double(volume.corners.size());
        const double side = glm::dot(center - portal.corners[0], normal);
        const double eye = glm::dot(eye_ - portal.corners[0], normal);
        return side > 0.0 ? eye <= tolerance_ : eye >= -tolerance_;
    }

    // The region's edges as world planes through the eye (clip-space a x + b y + c w >= 0,
    // brought back by the transposed view-projection), with the near and far planes.
    void add_visit(std::uint32_t cell, const std::vector<glm::dvec2>& region) {
        PortalWalk::Visit v;
        v.cell = cell;
        v.first_plane = static_cast<std::uint32_t>(walk_.planes.size());
        const glm::dmat4 transposed = glm::transpose(view_projection_);
        for (std::size_t i = 0; i < region.size(); ++i) {
            const glm::dvec2 a = region[i], b = region[(i + 1) % region.size()];
            const double ea = a.y - b.y, eb = b.x - a.x;
            const glm::dvec4 plane = transposed * glm::dvec4(ea, eb, 0.0, -(ea * a.x + eb * a.y));
            const double length = glm::length(glm::dvec3(plane));
            if (length > 0.0) walk_.planes.push_back(glm::vec4(plane / length));
        }
        walk_.planes.push_back(near_far_[0]);
        walk_.planes.push_back(near_far_[1]);
        v.plane_count = static_cast<std::uint32_t>(walk_.planes.size()) - v.first_plane;
        walk_.visit_list.push_back(v);
        if (!walk_.reached[cell]) ++walk_.cells_visited;
        walk_.reached[cell] = 1;
    }

    const PortalWalkInput& in_;
    const CellGraph& graph_;
    PortalWalk& walk_;
    glm::dmat4 view_projection_;
    glm::dvec3 eye_;
    bool perspective_;
    glm::dvec2 margin_;
    double tolerance_, near_ = 0.0;
    glm::vec4 near_far_[2];
    std::vector<glm::dvec2> screen_;
};

void keep_all(PortalWalk& walk, std::size_t instances) {
    walk.kept.assign(instances, 1);
}

// Marks the instances whose box is inside some visit's region.
void keep_reached(const CellGraph& graph, std::span<const Bounds3f> boxes, PortalWalk& walk) {
    for (const PortalWalk::Visit& v : walk.visit_list) {
        const std::span<const glm::vec4> planes(walk.planes.data() + v.first_plane, v.plane_count);
        for (const std::uint32_t i : graph.cells[v.cell].instances)
            if (!walk.kept[i] && !outside_planes(boxes[i], planes)) walk.kept[i] = 1;
    }
}

}  // namespace

void walk_portals(const PortalWalkInput& in, PortalWalk& walk) {
    const auto start = std::chrono::steady_clock::now();
    const CellGraph& graph = *in.graph;
    const std::size_t instances = in.world_boxes.size();
    walk.cells_visited = walk.visits = walk.pvs_cells = 0;
    walk.visit_list.clear();
    walk.planes.clear();
    walk.camera_cell = find_cell(graph, in.camera.position());
    if (walk.camera_cell < 0) {
        walk.outcome = PortalOutcome::CameraOutside;
        keep_all(walk, instances);
        return;
    }
    const auto cell = static_cast<std::uint32_t>(walk.camera_cell);
    walk.allowed.assign(graph.cells.size(), graph.pvs.empty() ? 1 : 0);
    if (!graph.pvs.empty()) {
        for (const std::uint32_t c : graph.pvs[cell]) walk.allowed[c] = 1;
        walk.pvs_cells = graph.pvs[cell].size();
    }
    walk.kept.assign(instances, 0);
    walk.outcome = PortalOutcome::Culled;
    if (in.mode == PortalCull::Off) {  // the PVS alone
        for (std::size_t i = 0; i < instances; ++i)
            for (const std::uint32_t c : graph.instance_cells[i]) walk.kept[i] |= walk.allowed[c];
    } else {
        walk.on_path.assign(graph.cells.size(), 0);
        walk.reached.assign(graph.cells.size(), 0);
        Walker walker(in, walk);
        if (walker.run(cell)) {
            keep_reached(graph, in.world_boxes, walk);
        } else {
            walk.outcome = PortalOutcome::OverBound;
            keep_all(walk, instances);
        }
        walk.visits = walk.visit_list.size();
    }
    walk.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace zraster::detail
