// Bresenham's line algorithm (Bresenham 1965, "Algorithm for computer control of a digital
// plotter", IBM Systems Journal 4(1)).
//
// What: the pixels of a segment between two integer points, one per major coordinate, each the
// nearest to the ideal line in the minor axis, using only integer additions and comparisons.
// Cost: O(max(|dx|, |dy|)), a few integer operations per pixel, no division, no rounding error.
// When: any time the endpoints are integers (wireframes, debug overlays, edge walking); it is
// exact, so it is also the reference the DDA is tested against. For real endpoints use the DDA.
//
// Symmetry: the textbook loop steps in the minor axis when the error term is > 0, which sends
// ties (ideal line exactly half-way between two pixels) towards the start point's side, so a->b
// and b->a differ. Here a tie goes to the larger minor COORDINATE (see lines.hpp): when walking
// towards larger minor coordinates that means stepping at error == 0, when walking towards
// smaller ones it means not stepping. The rule is then a property of the line, not of its
// direction.
#include <zraster/lines.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace zraster {
namespace {

// The walk's state at pixel i of a line of n + 1 pixels whose minor coordinate changes by m:
// k, the minor steps taken so far, and the error term (see walk_line). Closed form of the loop
// below, so that a walk can start anywhere along the line with the same pixels.
struct WalkState {
    std::int64_t k, error;
};
WalkState walk_state(std::int64_t i, std::int64_t n, std::int64_t m, bool step_on_tie) {
    // After pixel i, error = 2 (i m - k n) - n is <= 0 (< 0 when ties step) for the least such k.
    const std::int64_t num = 2 * i * m - n, den = 2 * n;
    const std::int64_t floor_div = num >= 0 ? num / den : -((-num + den - 1) / den);
    const std::int64_t k =
        step_on_tie ? floor_div + 1 : (num % den == 0 ? floor_div : floor_div + 1);
    return {k, num - k * den};
}

// Calls fn(x, y) for the pixels from a to b whose major coordinate (x for a line at most 45
// degrees from the x axis, else y) lies in [major_min, major_max], in order: the pixels the whole
// walk would give there, without walking the others.
template <class Fn>
void walk_line(glm::ivec2 a, glm::ivec2 b, std::int64_t major_min, std::int64_t major_max,
               Fn&& fn) {
    const std::int64_t dx = std::int64_t{b.x} - a.x;
    const std::int64_t dy = std::int64_t{b.y} - a.y;
    const bool x_major = std::llabs(dx) >= std::llabs(dy);
    const std::int64_t d_major = x_major ? dx : dy;
    const std::int64_t d_minor = x_major ? dy : dx;
    const std::int64_t n = std::llabs(d_major);  // pixel count - 1
    const std::int64_t m = std::llabs(d_minor);
    const int step_major = d_major >= 0 ? 1 : -1;
    const int step_minor = (d_minor > 0) - (d_minor < 0);
    const std::int64_t major_a = x_major ? a.x : a.y;

    // After advancing to pixel i with k minor steps taken so far,
    // error = 2 * (i * m - k * n) - n, i.e. 2n * (distance of the ideal line beyond the current
    // pixel, in the direction of travel) - n: positive when the next pixel is nearer, zero on a
    // tie. The minor step per pixel is m / n <= 1, so at most one step is ever needed.
    const bool step_on_tie = step_minor > 0;
    // The pixels i in [first, last] whose major coordinate major_a + step_major * i is inside.
    const std::int64_t first =
        std::max<std::int64_t>(0, step_major > 0 ? major_min - major_a : major_a - major_max);
    const std::int64_t last =
        std::min<std::int64_t>(n, step_major > 0 ? major_max - major_a : major_a - major_min);
    if (first > last) return;
    const WalkState start = n == 0 ? WalkState{0, 0} : walk_state(first, n, m, step_on_tie);
    int major = static_cast<int>(major_a + step_major * first);
    int minor = static_cast<int>((x_major ? a.y : a.x) + step_minor * start.k);
    std::int64_t error = start.error;
    for (std::int64_t i = first;; ++i) {
        if (x_major)
            fn(major, minor);
        else
            fn(minor, major);
        if (i == last) break;
        major += step_major;
        error += 2 * m;
        if (error > 0 || (error == 0 && step_on_tie)) {
            minor += step_minor;
            error -= 2 * n;
        }
    }
}

// Every pixel from a to b.
template <class Fn>
void walk_line(glm::ivec2 a, glm::ivec2 b, Fn&& fn) {
    walk_line(a, b, std::numeric_limits<std::int64_t>::min() / 4,
              std::numeric_limits<std::int64_t>::max() / 4, fn);
}

}  // namespace

void bresenham_line(glm::ivec2 a, glm::ivec2 b, std::vector<glm::ivec2>& out) {
    walk_line(a, b, [&](int x, int y) { out.emplace_back(x, y); });
}

std::vector<glm::ivec2> bresenham_line(glm::ivec2 a, glm::ivec2 b) {
    std::vector<glm::ivec2> out;
    bresenham_line(a, b, out);
    return out;
}

namespace {

// bresenham_line_depth's pixels whose major coordinate is in [major_min, major_max].
void line_depth(glm::ivec2 a, float depth_a, glm::ivec2 b, float depth_b, std::int64_t major_min,
                std::int64_t major_max, std::vector<LinePixel>& out) {
    // Interpolate from the lexicographically smaller endpoint, whatever the drawing direction,
    // so both directions produce bit-identical depths.
    const bool a_first = a.x < b.x || (a.x == b.x && a.y <= b.y);
    const glm::ivec2 lo = a_first ? a : b;
    const glm::ivec2 hi = a_first ? b : a;
    const double z_lo = a_first ? depth_a : depth_b;
    const double z_hi = a_first ? depth_b : depth_a;
    const bool x_major = std::abs(std::int64_t{hi.x} - lo.x) >= std::abs(std::int64_t{hi.y} - lo.y);
    const double major_lo = x_major ? lo.x : lo.y;
    const double span = (x_major ? hi.x : hi.y) - major_lo;
    if (span == 0.0) {
        // A single pixel: the smaller depth, a choice that does not depend on the order.
        const float z = depth_a < depth_b ? depth_a : depth_b;
        out.push_back({a.x, a.y, z});
        return;
    }
    walk_line(a, b, major_min, major_max, [&](int x, int y) {
        const double t = ((x_major ? x : y) - major_lo) / span;
        out.push_back({x, y, static_cast<float>(z_lo + (z_hi - z_lo) * t)});
    });
}

}  // namespace

void bresenham_line_depth(glm::ivec2 a, float depth_a, glm::ivec2 b, float depth_b,
                          std::vector<LinePixel>& out) {
    line_depth(a, depth_a, b, depth_b, std::numeric_limits<std::int64_t>::min() / 4,
               std::numeric_limits<std::int64_t>::max() / 4, out);
}

void bresenham_line_depth_in(glm::ivec2 a, float depth_a, glm::ivec2 b, float depth_b, int width,
                             int height, std::vector<LinePixel>& out) {
    if (width < 1 || height < 1) return;
    const bool x_major = std::llabs(std::int64_t{b.x} - a.x) >= std::llabs(std::int64_t{b.y} - a.y);
    const std::size_t from = out.size();
    line_depth(a, depth_a, b, depth_b, 0, (x_major ? width : height) - 1, out);
    // The minor coordinate is not clipped by the walk: drop what lies outside here.
    const auto outside = [&](const LinePixel& p) {
        return p.x < 0 || p.y < 0 || p.x >= width || p.y >= height;
    };
    out.erase(std::remove_if(out.begin() + std::ptrdiff_t(from), out.end(), outside), out.end());
}

std::vector<LinePixel> bresenham_line_depth(glm::ivec2 a, float depth_a, glm::ivec2 b,
                                            float depth_b) {
    std::vector<LinePixel> out;
    bresenham_line_depth(a, depth_a, b, depth_b, out);
    return out;
}

}  // namespace zraster
