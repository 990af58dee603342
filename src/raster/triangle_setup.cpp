// Triangle setup: divide, viewport, snap to fixed point, edge functions with the top-left fill
// rule, and the plane equations of depth and barycentrics. See include/zraster/raster.hpp.
#include <zraster/raster.hpp>

#include <algorithm>
#include <cmath>

namespace zraster {
namespace {

constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;

}  // namespace

std::array<std::int64_t, 2> snap_to_grid(const glm::dvec2& window) {
    return {static_cast<std::int64_t>(std::llrint(window.x * double(kSubpixelScale))),
            static_cast<std::int64_t>(std::llrint(window.y * double(kSubpixelScale)))};
}

SetupResult setup_triangle(const std::array<glm::vec4, 3>& clip, const SetupSettings& settings,
                           TriangleSetup& t) {
    std::array<ScreenVertex, 3> v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!to_screen(clip[i], settings, v[i])) return SetupResult::Degenerate;
    return setup_triangle(v, settings, t);
}

SetupResult classify_triangle(const std::array<ScreenVertex, 3>& v, const SetupSettings& settings,
                              TriangleBounds& out) {
    return classify_triangle(v[0], v[1], v[2], settings, out);
}

SetupResult setup_triangle(const std::array<ScreenVertex, 3>& v, const SetupSettings& settings,
                           TriangleSetup& t, bool planes) {
    TriangleBounds bounds;
    const SetupResult result = classify_triangle(v[0], v[1], v[2], settings, bounds);
    if (result != SetupResult::Visible) return result;
    t.min_x = bounds.min_x;
    t.min_y = bounds.min_y;
    t.max_x = bounds.max_x;
    t.max_y = bounds.max_y;
    t.front_facing = bounds.front_facing;
    for (std::size_t i = 0; i < 3; ++i) {
        t.x[i] = v[i].x;
        t.y[i] = v[i].y;
    }
    const std::int64_t x0 = t.x[0], y0 = t.y[0];
    const std::int64_t area = (t.x[1] - x0) * (t.y[2] - y0) - (t.x[2] - x0) * (t.y[1] - y0);

    // Edge k is opposite vertex k, from vertex `from` to vertex `to` (or the reverse when the
    // area is negative), oriented so the inside is positive. Reversing an edge negates its
    // function exactly, and any point of the line gives the same constant, so `from` serves as
    // the origin either way. (Written out per edge: with indices computed in a loop the
    // compiler indexed the vertices through memory.)
    const std::int64_t sign = area < 0 ? -1 : 1;
    const auto edge = [&](std::size_t k, std::size_t from, std::size_t to) {
        const std::int64_t ax = t.x[from], ay = t.y[from];
        const std::int64_t dx = sign * (t.x[to] - ax), dy = sign * (t.y[to] - ay);
        // Top edge: horizontal with the triangle below it; left edge: going up (y down).
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        t.edge_a[k] = -dy * kSubpixelScale;
        t.edge_b[k] = dx * kSubpixelScale;
        t.edge_c[k] = dx * (kHalfPixel - ay) - dy * (kHalfPixel - ax) - (top_left ? 0 : 1);
    };
    edge(0, 1, 2);
    edge(1, 2, 0);
    edge(2, 0, 1);
    if (!planes) return SetupResult::Visible;

    // Plane equations in pixel units relative to the center of pixel (min_x, min_y), from the
    // gradients of the screen-linear barycentrics lambda_1 and lambda_2 (in double), over the
    // unsnapped positions. A sliver whose unsnapped area vanishes falls back to the snapped one.
    const double fx0 = v[0].window_x, fy0 = v[0].window_y;
    double ex1 = double(v[1].window_x) - fx0, ey1 = double(v[1].window_y) - fy0;
    double ex2 = double(v[2].window_x) - fx0, ey2 = double(v[2].window_y) - fy0;
    double det = ex1 * ey2 - ex2 * ey1;
    double ox = (t.min_x + 0.5) - fx0, oy = (t.min_y + 0.5) - fy0;
    // The unsnapped triangle must have the same orientation as the snapped one.
    if (!(det * double(area) > 0.0)) {
        constexpr double kInvScale = 1.0 / double(kSubpixelScale);
        ex1 = double(t.x[1] - x0) * kInvScale;
        ey1 = double(t.y[1] - y0) * kInvScale;
        ex2 = double(t.x[2] - x0) * kInvScale;
        ey2 = double(t.y[2] - y0) * kInvScale;
        det = double(area) * (kInvScale * kInvScale);
        ox = (t.min_x + 0.5) - double(x0) * kInvScale;
        oy = (t.min_y + 0.5) - double(y0) * kInvScale;
    }
    const double inv_det = 1.0 / det;
    const double l1_dx = ey2 * inv_det, l1_dy = -ex2 * inv_det;
    const double l2_dx = -ey1 * inv_det, l2_dy = ex1 * inv_det;
    const auto plane = [&](double f0, double df1, double df2) {
        const double a = df1 * l1_dx + df2 * l2_dx;
        const double b = df1 * l1_dy + df2 * l2_dy;
        return PlaneEquation{static_cast<float>(a), static_cast<float>(b),
                             static_cast<float>(f0 + a * ox + b * oy)};
    };
    const double z0 = v[0].z;
    t.depth = plane(z0, double(v[1].z) - z0, double(v[2].z) - z0);
    if (!settings.barycentric_planes) return SetupResult::Visible;
    // Scale 1/w so the largest is 1: the ratios are what matter, and this keeps them in range.
    const double scale =
        1.0 / std::max({double(v[0].inv_w), double(v[1].inv_w), double(v[2].inv_w)});
    const double q0 = double(v[0].inv_w) * scale, q1 = double(v[1].inv_w) * scale,
                 q2 = double(v[2].inv_w) * scale;
    t.q = plane(q0, q1 - q0, q2 - q0);
    t.p1 = plane(0.0, q1, 0.0);
    t.p2 = plane(0.0, 0.0, q2);
    if (settings.screen_linear_planes) {
        t.l1 = plane(0.0, 1.0, 0.0);
        t.l2 = plane(0.0, 0.0, 1.0);
    }
    return SetupResult::Visible;
}

glm::vec3 barycentrics(const TriangleSetup& t, int px, int py, Interpolation interpolation) {
    const int dx = px - t.min_x, dy = py - t.min_y;
    float b1, b2;
    if (interpolation == Interpolation::PerspectiveCorrect) {
        const float q = t.q.at(dx, dy);
        b1 = t.p1.at(dx, dy) / q;
        b2 = t.p2.at(dx, dy) / q;
    } else {
        b1 = t.l1.at(dx, dy);
        b2 = t.l2.at(dx, dy);
    }
    return {1.0f - b1 - b2, b1, b2};
}

float depth_at(const TriangleSetup& t, int px, int py) {
    // min/max in this order (as the SIMD kernels do) and + 0 to turn -0 into +0, so the stored
    // bits never depend on the sign of a zero.
    const float z = t.depth.at(px - t.min_x, py - t.min_y);
    return std::min(std::max(z, 0.0f), 1.0f) + 0.0f;
}

}  // namespace zraster
