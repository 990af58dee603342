// Cohen-Sutherland line clipping against an axis-aligned rectangle (Sproull & Sutherland 1968, "A
// clipping divider"; described in Newman & Sproull 1973, "Principles of Interactive Computer
// Graphics").
//
// What: each endpoint gets a 4-bit outcode (which of the four half-planes it is outside of). Both
// codes 0: the segment is inside (trivial accept). A bit common to both: both endpoints are
// outside the same half-plane, so the whole segment is (trivial reject). Otherwise an outside
// endpoint is moved to where the line meets the boundary of one of its bits, and the test
// repeats.
// Cost: two outcodes (four comparisons each) for a trivial case; otherwise at most four
// subdivisions (one division each) in exact arithmetic.
// When: scenes where most segments are entirely inside or entirely outside the window (a
// zoomed-out wireframe, a zoomed-in map): those cost comparisons only. For many crossing segments
// Liang-Barsky does less work.
#include <zraster/line_clip.hpp>

namespace zraster {

std::uint32_t outcode(const glm::dvec2& p, const ClipRect& w) {
    std::uint32_t code = 0;
    if (p.x < w.x_min) code |= kOutLeft;
    if (p.x > w.x_max) code |= kOutRight;
    if (p.y < w.y_min) code |= kOutBottom;
    if (p.y > w.y_max) code |= kOutTop;
    return code;
}

ClippedLine2 clip_line_cohen_sutherland(glm::dvec2 a, glm::dvec2 b, const ClipRect& w,
                                        LineClipStats* stats) {
    LineClipStats s;
    s.segments = 1;
    // Intersections are always computed on the ORIGINAL segment, as a0 + t (b0 - a0) with t from
    // the boundary, the way Liang-Barsky does it: the point where the line meets a boundary does
    // not depend on which boundaries were clipped before (no accumulated error), and the three
    // clippers agree to the last bits.
    const glm::dvec2 a0 = a, d = b - a;
    std::uint32_t code_a = outcode(a, w), code_b = outcode(b, w);
    // Boundaries each endpoint has been moved onto. Near a corner, rounding may put the computed
    // coordinate a hair outside a boundary the endpoint was already moved onto; that coordinate is
    // then snapped back instead of clipping again, which bounds the loop at 8 subdivisions (each
    // endpoint, each boundary, once) even in floating point.
    std::uint32_t done_a = 0, done_b = 0;
    ClippedLine2 result;
    bool first_pass = true;
    for (;;) {
        ++s.iterations;
        if ((code_a | code_b) == 0) {
            if (first_pass) ++s.trivial_accepts;
            result = {true, a, b};
            break;
        }
        if ((code_a & code_b) != 0) {
            if (first_pass) ++s.trivial_rejects;
            break;
        }
        first_pass = false;
        const bool move_a = code_a != 0;
        glm::dvec2& p = move_a ? a : b;
        std::uint32_t& code = move_a ? code_a : code_b;
        std::uint32_t& done = move_a ? done_a : done_b;
        const std::uint32_t bit = code & (~code + 1u);  // lowest set bit
        // d.x (d.y) is nonzero here: p is outside this boundary and the other endpoint is not
        // outside it too (no common bit), so they lie on different sides.
        if (bit & (kOutLeft | kOutRight)) {
            const double x = bit == kOutLeft ? w.x_min : w.x_max;
            p = {x, a0.y + (x - a0.x) / d.x * d.y};
        } else {
            const double y = bit == kOutBottom ? w.y_min : w.y_max;
            p = {a0.x + (y - a0.y) / d.y * d.x, y};
        }
        ++s.subdivisions;
        done |= bit;
        code = outcode(p, w);
        // Snap back the rounding overshoots described above.
        if (code & done & kOutLeft) p.x = w.x_min;
        if (code & done & kOutRight) p.x = w.x_max;
        if (code & done & kOutBottom) p.y = w.y_min;
        if (code & done & kOutTop) p.y = w.y_max;
        code &= ~done;
    }
    if (stats) *stats += s;
    return result;
}

}  // namespace zraster
