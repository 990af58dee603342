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

// The farthest the near plane's clipped corners are from the eye: geometry closer than this may
// be cut away by the near plane.
double near_reach(const glm::mat4& view_projection, const glm::dvec2& margin,
                  const glm::dvec3& eye) {
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(view_projection));
    double reach = 0.0;
    for (const glm::dvec2 corner :
         {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
        const glm::dvec4 p = inverse * glm::dvec4(corner * (1.0 + margin), -1.0, 1.0);
        reach = std::max(reach, glm::length(glm::dvec3(p) / p.w - eye));
    }
    return std::isfinite(reach) ? reach * (1.0 + 1e-6) : HUGE_VAL;
}

// Whether the portal lies in `plane` and holds the disc of `radius` around `foot` in it.
bool portal_covers(const Portal& portal, const glm::dvec4& plane, const glm::dvec3& foot,
                   double radius) {
    const std::vector<glm::dvec3>& c = portal.corners;
    constexpr double kInPlane = 1e-6;
    for (const glm::dvec3& corner : c)
        if (std::abs(glm::dot(glm::dvec3(plane), corner) + plane.w) > kInPlane) return false;
    const glm::dvec3 normal = polygon_normal(c);
    for (std::size_t i = 0; i < c.size(); ++i) {
        const glm::dvec3 edge = glm::normalize(c[(i + 1) % c.size()] - c[i]);
        const double inside = glm::dot(glm::cross(normal, edge), foot - c[i]);
        if (inside < radius) return false;
    }
    return true;
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
        near_ = near_reach(in.view_projection, margin_, eye_);
    }

    // Whether every part of the camera cell's boundary within the near reach of the eye is a
    // portal: elsewhere the near plane could cut open a wall and show what lies behind it.
    bool clear_of_walls(std::uint32_t cell) const {
        for (const glm::dvec4& plane : graph_.cells[cell].volume.planes) {
            const glm::dvec3 n(plane);
            const double distance = glm::dot(n, eye_) + plane.w;
            if (distance > near_) continue;
            // An eye in the plane of the cell's faces sees the walls there edge on: their
            // triangles project to lines, and rounding can still give them a pixel of any depth.
            if (distance <= tolerance_) return false;
            const glm::dvec3 foot = eye_ - distance * n;
            const double radius = std::sqrt(std::max(near_ * near_ - distance * distance, 0.0));
            bool covered = false;
            for (const std::uint32_t p : graph_.cell_portals[cell])
                covered = covered || portal_covers(graph_.portals[p], plane, foot, radius);
            if (!covered) return false;
        }
        return true;
    }

    bool near_wall() const { return near_wall_; }

    // Whether the cells the near plane can reach from the eye's cell (through portals within
    // its reach) are clear of walls there (clear_of_walls); marks them in walk.on_path.
    bool near_cells_clear(std::uint32_t cell) {
        if (!clear_of_walls(cell)) return false;
        walk_.on_path[cell] = 1;
        for (const std::uint32_t p : graph_.cell_portals[cell]) {
            const Portal& portal = graph_.portals[p];
            const std::uint32_t next = portal.cells[0] == cell ? portal.cells[1] : portal.cells[0];
            if (walk_.on_path[next] ||
                distance_to_polygon(eye_, portal.corners, polygon_normal(portal.corners)) > near_)
                continue;
            if (!near_cells_clear(next)) return false;
        }
        return true;
    }

    // False when a bound was passed or the near plane cuts into a wall (near_wall).
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
            const bool seen = narrow(portal, next, walk_.regions[depth], walk_.regions[depth + 1]);
            if (near_wall_) {
                complete = false;
                break;
            }
            if (!seen) continue;
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
            // Standing in the doorway: the portal is open, and the near plane may cut into the
            // next cell's walls too.
            if (!clear_of_walls(next)) {
                near_wall_ = true;
                return false;
            }
            out = region;
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
    bool near_wall_ = false;
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
    walk.on_path.assign(graph.cells.size(), 0);
    walk.reached.assign(graph.cells.size(), 0);
    Walker walker(in, walk);
    if (in.camera.projection == Camera::Projection::Orthographic ||
        !walker.near_cells_clear(cell)) {
        walk.outcome = PortalOutcome::NearWall;
        keep_all(walk, instances);
    } else if (in.mode == PortalCull::Off) {  // the PVS alone
        for (std::size_t i = 0; i < instances; ++i)
            for (const std::uint32_t c : graph.instance_cells[i]) walk.kept[i] |= walk.allowed[c];
    } else {
        walk.on_path.assign(graph.cells.size(), 0);
        if (walker.run(cell)) {
            keep_reached(graph, in.world_boxes, walk);
        } else {
            walk.outcome = walker.near_wall() ? PortalOutcome::NearWall : PortalOutcome::OverBound;
            keep_all(walk, instances);
        }
        walk.visits = walk.visit_list.size();
    }
    walk.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace zraster::detail
