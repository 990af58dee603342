// Clipping in homogeneous clip space with the Sutherland-Hodgman algorithm
// (Sutherland & Hodgman 1974, "Reentrant polygon clipping"; Blinn & Newell 1978, "Clipping using
// homogeneous coordinates").
//
// Clipping happens before the perspective divide, where the view volume is convex and linear:
// a vertex is inside plane p when dot(p, v) >= 0. That handles triangles crossing w = 0 or lying
// partly behind the eye exactly: no division by a vanishing w ever happens on a kept vertex.
//
// Cost: O(vertices x planes) per polygon; only triangles that cross a plane pay it, the others
// are accepted or rejected from their vertex outcodes.
// When to use: every triangle before rasterization (what the pipeline does), and any polygon that
// must be cut by planes in 3D before the divide; for polygons in 2D against a convex window see
// polygon_clip.hpp, for line segments line_clip.hpp.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/export.hpp>

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace zraster {

// Bits of a clip-space outcode: which planes a vertex is outside of.
enum ClipPlaneBit : std::uint32_t {
    kClipDepthMin = 1u << 0,  // z >= -w (OpenGL) or z >= 0 (zero-to-one)
    kClipDepthMax = 1u << 1,  // z <= w
    kClipLeft = 1u << 2,      // guard band planes
    kClipRight = 1u << 3,
    kClipBottom = 1u << 4,
    kClipTop = 1u << 5,
    kClipUser0 = 1u << 6,  // user planes 0..kMaxUserClipPlanes-1
};
inline constexpr int kMaxUserClipPlanes = 6;

// A vertex of a clipped polygon: its clip-space position and its barycentric weights relative to
// the original triangle, so any vertex attribute can be recovered as sum(weights[i] * attr[i])
// without carrying attributes through the clipper.
struct ClipVertex {
    glm::vec4 position;
    glm::vec3 weights;
};

// A triangle clipped by up to 2 + 4 + kMaxUserClipPlanes planes has at most 3 + that many
// vertices.
inline constexpr int kMaxClippedVertices = 3 + 2 + 4 + kMaxUserClipPlanes;

struct ClippedPolygon {
    std::array<ClipVertex, kMaxClippedVertices> vertices;
    int count = 0;
};

struct ClipSettings {
    ClipDepthRange depth_range = ClipDepthRange::NegativeOneToOne;
    // Guard band half-extent in NDC units (kGuardBand / (viewport half size)); vertices within
    // |x| <= guard_x * w and |y| <= guard_y * w need no x/y clipping.
    float guard_x = 1.0f;
    float guard_y = 1.0f;
    int user_plane_count = 0;
};

// Signed distance-like value of v to frustum plane `bit_index` (0..5 in ClipPlaneBit order):
// inside when >= 0. One definition shared by the outcodes and the clipper.
inline float frustum_plane_distance(int bit_index, const glm::vec4& v, const ClipSettings& s) {
    switch (bit_index) {
        case 0:
            return s.depth_range == ClipDepthRange::ZeroToOne ? v.z : v.z + v.w;
        case 1:
            return v.w - v.z;
        case 2:
            return v.x + s.guard_x * v.w;
        case 3:
            return s.guard_x * v.w - v.x;
        case 4:
            return v.y + s.guard_y * v.w;
        default:
            return s.guard_y * v.w - v.y;
    }
}

// Outcode for the six frustum/guard-band planes only (the hot path of the vertex stage).
inline std::uint32_t frustum_outcode(const glm::vec4& v, const ClipSettings& s) {
    // Unrolled frustum_plane_distance, the same expressions.
    const float depth_min = s.depth_range == ClipDepthRange::ZeroToOne ? v.z : v.z + v.w;
    const float gx = s.guard_x * v.w, gy = s.guard_y * v.w;
    return (depth_min >= 0.0f ? 0u : kClipDepthMin) | (v.w - v.z >= 0.0f ? 0u : kClipDepthMax) |
           (v.x + gx >= 0.0f ? 0u : kClipLeft) | (gx - v.x >= 0.0f ? 0u : kClipRight) |
           (v.y + gy >= 0.0f ? 0u : kClipBottom) | (gy - v.y >= 0.0f ? 0u : kClipTop);
}

// Outcode of one vertex. user_distances holds the vertex's signed distance to each user plane
// (inside when >= 0).
ZRASTER_API std::uint32_t clip_outcode(const glm::vec4& v, const ClipSettings& settings,
                                       std::span<const float> user_distances);

// Clips triangle (v[0], v[1], v[2]) against every plane named in `planes` (a mask of
// ClipPlaneBit). user_distances[k][i] is vertex i's distance to user plane k.
// Result: a convex polygon (count may be 0). Intersections on an edge are always computed from
// the inside vertex towards the outside one, so two triangles sharing an edge produce
// bit-identical new vertices on it (no cracks after clipping).
ZRASTER_API void clip_triangle(const std::array<glm::vec4, 3>& v, std::uint32_t planes,
                               const ClipSettings& settings,
                               std::span<const std::array<float, 3>> user_distances,
                               ClippedPolygon& out);

// Sutherland-Hodgman against one homogeneous plane (keep dot(plane, v) >= 0); the building block,
// also usable on its own. Writes the clipped polygon to out and returns its vertex count. The
// output holds each inside vertex plus one new vertex per crossing edge: at most n + 1 vertices
// for a convex input of n vertices, but up to floor(3n / 2) for a concave one (n/2 inside
// vertices each between two crossings, e.g. a comb whose teeth cross the plane), so `out` must
// hold max_clip_output(n) = n + n / 2 + 1 vertices unless the input is known to be convex
// (the count may exceed out.size() otherwise: a precondition, checked by assert only).
ZRASTER_API int clip_polygon_against_plane(std::span<const ClipVertex> in, const glm::vec4& plane,
                                           std::span<ClipVertex> out);

// Output capacity that clip_polygon_against_plane needs for any input of n vertices.
constexpr std::size_t max_clip_output(std::size_t n) {
    return n + n / 2 + 1;
}

}  // namespace zraster
