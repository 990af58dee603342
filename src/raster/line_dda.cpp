// The digital differential analyzer (DDA) for lines: the incremental line algorithm that
// predates Bresenham's (see Newman & Sproull 1973, "Principles of Interactive Computer Graphics",
// and Bresenham 1965 for the integer version it was replaced by).
//
// What: one pixel per major coordinate; the minor coordinate of the ideal line is carried in a
// double and advanced by the slope at each step, then rounded half up to pick the pixel.
// Cost: O(max(|dx|, |dy|)): one floating-point add and one floor per pixel, one division per line.
// When: endpoints that are not integers (clipped or projected vertices) without snapping them
// first; for integer endpoints Bresenham is exact and as fast. The accumulated sum drifts by about
// one rounding error per step, which matters only when the ideal line passes exactly half-way
// between two pixels (a tie): there the DDA may pick either pixel. See lines.hpp for the rule.
#include <zraster/lines.hpp>

#include <cassert>
#include <cmath>
#include <cstdint>

namespace zraster {
namespace {

// floor(v + 0.5): round half up, the tie rule of lines.hpp.
int round_half_up(double v) {
    return static_cast<int>(std::floor(v + 0.5));
}

}  // namespace

void dda_line(glm::dvec2 a, glm::dvec2 b, std::vector<glm::ivec2>& out) {
    assert(std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(b.x) && std::isfinite(b.y));
    const glm::dvec2 d = b - a;
    const bool x_major = std::abs(d.x) >= std::abs(d.y);
    const double d_major = x_major ? d.x : d.y;
    if (d_major == 0.0) {  // then d_minor is 0 too: a single point
        out.emplace_back(round_half_up(a.x), round_half_up(a.y));
        return;
    }
    const double a_major = x_major ? a.x : a.y;
    const double a_minor = x_major ? a.y : a.x;
    const int first = round_half_up(a_major);
    const int last = round_half_up(x_major ? b.x : b.y);
    const int step = last >= first ? 1 : -1;
    const double slope = (x_major ? d.y : d.x) / d_major;  // |slope| <= 1: 8-connected pixels
    // The ideal line's minor coordinate at the first pixel's major coordinate (not at a itself,
    // which may lie up to half a pixel away when a is not an integer point).
    double minor = a_minor + (first - a_major) * slope;
    const double increment = step * slope;
    for (int major = first;; major += step) {
        const int m = round_half_up(minor);
        if (x_major)
            out.emplace_back(major, m);
        else
            out.emplace_back(m, major);
        if (major == last) break;
        minor += increment;
    }
}

std::vector<glm::ivec2> dda_line(glm::dvec2 a, glm::dvec2 b) {
    std::vector<glm::ivec2> out;
    dda_line(a, b, out);
    return out;
}

}  // namespace zraster
