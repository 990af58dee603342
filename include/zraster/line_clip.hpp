// Line clipping: Cohen-Sutherland, Liang-Barsky and Cyrus-Beck in 2D, and Blinn & Newell's
// homogeneous Liang-Barsky against the view volume in clip space.
//
// Conventions shared by all of them:
//  - Windows are CLOSED: a point on the boundary is inside. A segment that only touches the
//    window (along an edge, or at a corner) is kept, possibly as a single point (a == b).
//  - Each clipper returns whether anything remains and, if so, the clipped endpoints, in the
//    original direction (the result's a is the end nearer the input's a).
//  - Each accepts an optional LineClipStats that it ADDS to, so a test or benchmark can sum over
//    many segments and check, e.g., that trivial cases were decided from outcodes alone.
//
// Which one: Cohen-Sutherland when most segments are trivially inside or outside (the outcode test
// decides them with comparisons only); Liang-Barsky for a rectangle when many segments cross it
// (at most four divisions, no iteration); Cyrus-Beck for any convex window; the homogeneous
// clipper for 3D lines before the perspective divide (wireframes, line primitives).
#pragma once
#include <zraster/camera.hpp>
#include <zraster/clip.hpp>
#include <zraster/export.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zraster {

// An axis-aligned window [x_min, x_max] x [y_min, y_max] (x_min <= x_max, y_min <= y_max).
struct ClipRect {
    double x_min = 0, y_min = 0, x_max = 0, y_max = 0;
};

// A convex window for Cyrus-Beck (and Sutherland-Hodgman, polygon_clip.hpp), prepared once:
// vertices counter-clockwise (y up; clockwise on a y-down screen), and the unit inward normal of
// edge i = (vertices[i], vertices[i + 1]). A point p is inside edge i when
// dot(inward_normals[i], p - vertices[i]) >= 0.
struct ConvexWindow {
    std::vector<glm::dvec2> vertices;
    std::vector<glm::dvec2> inward_normals;
};

// Builds a ConvexWindow from a convex polygon in either orientation (at least 3 vertices, no
// repeated consecutive vertices; collinear ones are allowed and merely redundant). Throws
// std::invalid_argument otherwise. Axis-aligned edges get exactly axis-aligned normals, so a
// rectangle window clips with exactly Liang-Barsky's arithmetic.
ZRASTER_API ConvexWindow make_convex_window(std::span<const glm::dvec2> polygon);
ZRASTER_API ConvexWindow make_convex_window(const ClipRect& rect);

struct LineClipStats {
    long long segments = 0;         // calls
    long long trivial_accepts = 0;  // decided inside from the outcodes alone
    long long trivial_rejects = 0;  // decided outside from the outcodes alone
    // Work done on the non-trivial segments. Cohen-Sutherland: endpoint moves onto a boundary
    // (one division each). Liang-Barsky, Cyrus-Beck, homogeneous: boundary parameters computed
    // (one division each).
    long long subdivisions = 0;
    long long iterations = 0;  // Cohen-Sutherland: passes of the outcode loop

    LineClipStats& operator+=(const LineClipStats& o) {
        segments += o.segments;
        trivial_accepts += o.trivial_accepts;
        trivial_rejects += o.trivial_rejects;
        subdivisions += o.subdivisions;
        iterations += o.iterations;
        return *this;
    }
};

struct ClippedLine2 {
    bool visible = false;
    glm::dvec2 a{0.0}, b{0.0};
};

// Cohen-Sutherland 4-bit outcode of p: which of the window's half-planes p is outside of.
enum OutcodeBit : std::uint32_t {
    kOutLeft = 1u << 0,    // x < x_min
    kOutRight = 1u << 1,   // x > x_max
    kOutBottom = 1u << 2,  // y < y_min
    kOutTop = 1u << 3,     // y > y_max
};
ZRASTER_API std::uint32_t outcode(const glm::dvec2& p, const ClipRect& window);

// Cohen-Sutherland: trivial accept (both outcodes 0) and reject (a common bit), otherwise move an
// outside endpoint onto the boundary of one of its bits and repeat. Clipped endpoints are inside
// the closed window exactly (the boundary coordinate is set, not computed).
ZRASTER_API ClippedLine2 clip_line_cohen_sutherland(glm::dvec2 a, glm::dvec2 b,
                                                    const ClipRect& window,
                                                    LineClipStats* stats = nullptr);

// Liang-Barsky: the parametric interval [t0, t1] of a + t (b - a) inside each slab, intersected,
// after the same outcode pre-test. Clipped endpoints are inside the closed window exactly.
ZRASTER_API ClippedLine2 clip_line_liang_barsky(glm::dvec2 a, glm::dvec2 b, const ClipRect& window,
                                                LineClipStats* stats = nullptr);

// Cyrus-Beck against any convex window. For a rectangle window (make_convex_window(rect)) it
// computes the same parameters as Liang-Barsky bit for bit; its endpoints may differ in the last
// bits because it does not snap them onto the boundary.
ZRASTER_API ClippedLine2 clip_line_cyrus_beck(glm::dvec2 a, glm::dvec2 b,
                                              const ConvexWindow& window,
                                              LineClipStats* stats = nullptr);

// 3D: the segment between clip-space points a and b (before the perspective divide) against the
// view volume -w <= x <= w, -w <= y <= w and -w <= z <= w (NegativeOneToOne) or 0 <= z <= w
// (ZeroToOne). t0 <= t1 are the parameters of the kept part along a + t (b - a), for
// interpolating any vertex attribute.
struct ClippedLine4 {
    bool visible = false;
    glm::dvec4 a{0.0}, b{0.0};
    double t0 = 0, t1 = 0;
};

// 6-bit outcode of a clip-space point: the ClipPlaneBit bits of clip.hpp (kClipDepthMin ..
// kClipTop) of the planes it is outside of, against the view volume itself (no guard band).
ZRASTER_API std::uint32_t outcode(const glm::dvec4& p, ClipDepthRange range);

// Blinn & Newell's homogeneous Liang-Barsky: outcodes for the trivial cases, then the parameter
// interval from the boundary coordinates (w + x, w - x, ...), which are linear in t.
ZRASTER_API ClippedLine4 clip_line_homogeneous(
    const glm::dvec4& a, const glm::dvec4& b,
    ClipDepthRange range = ClipDepthRange::NegativeOneToOne, LineClipStats* stats = nullptr);

}  // namespace zraster
