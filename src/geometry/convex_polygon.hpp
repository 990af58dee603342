// Convex polygons in double precision: clipping by a half-space (Sutherland & Hodgman 1974, one
// plane at a time), the 2D convex hull (Andrew's monotone chain, 1979) and the signed area. The
// portal walk (src/render/portal_cull.cpp) and the PVS (pvs.cpp) are built on these.
#pragma once
#include <glm/glm.hpp>

#include <vector>

namespace zraster::detail {

// Keeps the part of `polygon` where dot(plane.xyz, p) + plane.w >= 0. A convex polygon stays
// convex; degenerate input (a segment, a point) is clipped the same way.
void clip_polygon(std::vector<glm::dvec3>& polygon, const glm::dvec4& plane,
                  std::vector<glm::dvec3>& scratch);

// The same for homogeneous 2D points (x, y, w) and a half-plane a x + b y + c w >= 0.
void clip_homogeneous(std::vector<glm::dvec3>& polygon, const glm::dvec3& half_plane,
                      std::vector<glm::dvec3>& scratch);

// The convex hull of `points`, counter-clockwise, collinear points dropped (at least the
// distinct extreme points: 1 or 2 for degenerate input).
void convex_hull(std::vector<glm::dvec2>& points, std::vector<glm::dvec2>& scratch);

// Twice the signed area (counter-clockwise positive).
double twice_area(const std::vector<glm::dvec2>& polygon);

// Keeps the part of the counter-clockwise convex polygon `polygon` inside the counter-clockwise
// convex polygon `window` (every edge of `window` in turn).
void clip_to_convex(std::vector<glm::dvec2>& polygon, const std::vector<glm::dvec2>& window,
                    std::vector<glm::dvec2>& scratch);

}  // namespace zraster::detail
