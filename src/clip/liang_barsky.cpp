// Liang-Barsky line clipping against an axis-aligned rectangle (Liang & Barsky 1984, "A new
// concept and method for line clipping", ACM Transactions on Graphics 3(1)).
//
// What: the segment is a + t d, t in [0, 1]. Each of the four boundaries gives an inequality
// p_k t <= q_k; where p_k < 0 the line enters the half-plane at t = q_k / p_k, where p_k > 0 it
// leaves it there, where p_k = 0 it is parallel and either entirely inside (q_k >= 0) or not.
// The kept part is [max of entries and 0, min of exits and 1], if not empty.
// Cost: the outcode pre-test (as in Cohen-Sutherland) decides trivial cases with comparisons
// only; a crossing segment costs at most four divisions and two multiply-adds, with no iteration.
// When: a rectangular window with many crossing segments. For convex windows use Cyrus-Beck (of
// which this is the specialization to axis-aligned normals); in 3D before the divide, the
// homogeneous version (line_clip_3d.cpp).
#include <zraster/line_clip.hpp>

#include <algorithm>

namespace zraster {
namespace {

double clamp_to(double v, double lo, double hi) {
    return std::min(std::max(v, lo), hi);
}

}  // namespace

ClippedLine2 clip_line_liang_barsky(glm::dvec2 a, glm::dvec2 b, const ClipRect& w,
                                    LineClipStats* stats) {
    LineClipStats s;
    s.segments = 1;
    ClippedLine2 result;
    const std::uint32_t code_a = outcode(a, w), code_b = outcode(b, w);
    if ((code_a | code_b) == 0) {
        ++s.trivial_accepts;
        result = {true, a, b};
    } else if ((code_a & code_b) != 0) {
        ++s.trivial_rejects;
    } else {
        const glm::dvec2 d = b - a;
        const double p[4] = {-d.x, d.x, -d.y, d.y};
        const double q[4] = {a.x - w.x_min, w.x_max - a.x, a.y - w.y_min, w.y_max - a.y};
        double t0 = 0.0, t1 = 1.0;
        int enter = -1, leave = -1;  // the boundary that set t0 / t1, for snapping
        bool visible = true;
        for (int k = 0; k < 4 && visible; ++k) {
            if (p[k] == 0.0) {
                visible = q[k] >= 0.0;  // parallel: inside this slab entirely, or not at all
                continue;
            }
            const double t = q[k] / p[k];
            ++s.subdivisions;
            if (p[k] < 0.0) {
                if (t > t0) t0 = t, enter = k;
            } else {
                if (t < t1) t1 = t, leave = k;
            }
            visible = t0 <= t1;
        }
        if (visible) {
            // The boundary coordinate is set exactly and the other one clamped into the window:
            // the true intersection is in the closed window, and this keeps the computed one there
            // too (it can be a rounding error outside near a corner).
            const double bound[4] = {w.x_min, w.x_max, w.y_min, w.y_max};
            auto point = [&](glm::dvec2 r, int k) {
                if (k >= 0 && k < 2) r.x = bound[k];
                if (k >= 2) r.y = bound[k];
                return glm::dvec2(clamp_to(r.x, w.x_min, w.x_max), clamp_to(r.y, w.y_min, w.y_max));
            };
            // An end that was not moved keeps its input value (a + 1 * d need not round to b).
            result = {true, point(enter < 0 ? a : a + t0 * d, enter),
                      point(leave < 0 ? b : a + t1 * d, leave)};
        }
    }
    if (stats) *stats += s;
    return result;
}

}  // namespace zraster
