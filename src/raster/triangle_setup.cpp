// Triangle setup: divide, viewport, snap to fixed point, edge functions with the top-left fill
// rule, and the plane equations of depth and barycentrics. See include/zraster/raster.hpp.
#include <zraster/raster.hpp>

#include <algorithm>
#include <cmath>

namespace zraster {
namespace {

constexpr std::int64_t kHalfPixel = kSubpixelScale / 2;

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
    return q;
}

PlaneEquation make_plane(const std::array<double, 3>& X, const std::array<double, 3>& Y,
                         double inv_det, const std::array<double, 3>& f, double origin_x,
                         double origin_y) {
    const double df1 = f[1] - f[0], df2 = f[2] - f[0];
    const double a = (df1 * (Y[2] - Y[0]) - df2 * (Y[1] - Y[0])) * inv_det;
    const double b = (df2 * (X[1] - X[0]) - df1 * (X[2] - X[0])) * inv_det;
    const double c = f[0] + a * (origin_x - X[0]) + b * (origin_y - Y[0]);
    return {static_cast<float>(a), static_cast<float>(b), static_cast<float>(c)};
}

}  // namespace

std::array<std::int64_t, 2> snap_to_grid(const glm::dvec2& window) {
    return {static_cast<std::int64_t>(std::llrint(window.x * double(kSubpixelScale))),
            static_cast<std::int64_t>(std::llrint(window.y * double(kSubpixelScale)))};
}

bool to_screen(const glm::vec4& clip, const SetupSettings& settings, ScreenVertex& out) {
    const glm::dvec4 v(clip);
    if (!(v.w > 0.0)) return false;
    const double rw = 1.0 / v.w;
    const double wx = (v.x * rw + 1.0) * 0.5 * double(settings.viewport.width);
    const double wy = (1.0 - v.y * rw) * 0.5 * double(settings.viewport.height);
    // Beyond the guard band the fixed-point math could overflow (precision.hpp).
    const double limit = kGuardBand + double(kMaxViewport);
    if (!(std::abs(wx) <= limit && std::abs(wy) <= limit)) return false;
    const auto snapped = snap_to_grid({wx, wy});
    out.x = static_cast<std::int32_t>(snapped[0]);
    out.y = static_cast<std::int32_t>(snapped[1]);
    const double z = v.z * rw;
    out.z = static_cast<float>(settings.depth_range == ClipDepthRange::NegativeOneToOne
                                   ? 0.5 * z + 0.5
                                   : z);
    out.inv_w = static_cast<float>(rw);
    return true;
}

SetupResult setup_triangle(const std::array<glm::vec4, 3>& clip, const SetupSettings& settings,
                           TriangleSetup& t) {
    std::array<ScreenVertex, 3> v;
    for (std::size_t i = 0; i < 3; ++i)
        if (!to_screen(clip[i], settings, v[i])) return SetupResult::Degenerate;
    return setup_triangle(v, settings, t);
}

SetupResult setup_triangle(const std::array<ScreenVertex, 3>& v, const SetupSettings& settings,
                           TriangleSetup& t, bool planes) {
    for (std::size_t i = 0; i < 3; ++i) {
        t.x[i] = v[i].x;
        t.y[i] = v[i].y;
    }
    // Twice the signed area in y-down window space; negative means counter-clockwise as seen with
    // y up, i.e. OpenGL's default front face.
    const std::int64_t x0 = t.x[0], y0 = t.y[0];
    const std::int64_t area = (t.x[1] - x0) * (t.y[2] - y0) - (t.x[2] - x0) * (t.y[1] - y0);
    if (area == 0) return SetupResult::Degenerate;
    const bool ccw = area < 0;
    t.front_facing = (settings.front_face == FrontFace::CounterClockwise) == ccw;
    if ((settings.cull == CullMode::Back && !t.front_facing) ||
        (settings.cull == CullMode::Front && t.front_facing))
        return SetupResult::Culled;

    // Bounding box of covered pixel centers: px * S + S/2 within [min, max].
    const std::int64_t lo_x = std::min({t.x[0], t.x[1], t.x[2]});
    const std::int64_t hi_x = std::max({t.x[0], t.x[1], t.x[2]});
    const std::int64_t lo_y = std::min({t.y[0], t.y[1], t.y[2]});
    const std::int64_t hi_y = std::max({t.y[0], t.y[1], t.y[2]});
    const std::int64_t px0 =
        std::max<std::int64_t>(0, -floor_div(kHalfPixel - lo_x, kSubpixelScale));  // ceil
    const std::int64_t py0 =
        std::max<std::int64_t>(0, -floor_div(kHalfPixel - lo_y, kSubpixelScale));
    const std::int64_t px1 = std::min<std::int64_t>(settings.viewport.width - 1,
                                                    floor_div(hi_x - kHalfPixel, kSubpixelScale));
    const std::int64_t py1 = std::min<std::int64_t>(settings.viewport.height - 1,
                                                    floor_div(hi_y - kHalfPixel, kSubpixelScale));
    if (px0 > px1 || py0 > py1) return SetupResult::NoCoverage;
    t.min_x = static_cast<int>(px0);
    t.min_y = static_cast<int>(py0);
    t.max_x = static_cast<int>(px1);
    t.max_y = static_cast<int>(py1);

    // Edge k is opposite vertex k, oriented so the inside is positive.
    for (int k = 0; k < 3; ++k) {
        int ia = (k + 1) % 3, ib = (k + 2) % 3;
        if (area < 0) std::swap(ia, ib);
        const std::int64_t ax = t.x[static_cast<std::size_t>(ia)];
        const std::int64_t ay = t.y[static_cast<std::size_t>(ia)];
        const std::int64_t dx = t.x[static_cast<std::size_t>(ib)] - ax;
        const std::int64_t dy = t.y[static_cast<std::size_t>(ib)] - ay;
        // Top edge: horizontal with the triangle below it; left edge: going up (y down).
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        const auto ks = static_cast<std::size_t>(k);
        t.edge_a[ks] = -dy * kSubpixelScale;
        t.edge_b[ks] = dx * kSubpixelScale;
        t.edge_c[ks] = dx * (kHalfPixel - ay) - dy * (kHalfPixel - ax) - (top_left ? 0 : 1);
    }
    if (!planes) return SetupResult::Visible;

    // Plane equations in pixel units relative to the center of pixel (min_x, min_y).
    std::array<double, 3> X{}, Y{}, depth{}, q{};
    for (std::size_t i = 0; i < 3; ++i) {
        X[i] = double(t.x[i]) * (1.0 / double(kSubpixelScale));
        Y[i] = double(t.y[i]) * (1.0 / double(kSubpixelScale));
        depth[i] = v[i].z;
    }
    const double inv_det = double(kSubpixelScale * kSubpixelScale) / double(area);
    const double ox = t.min_x + 0.5, oy = t.min_y + 0.5;
    // Scale 1/w so the largest is 1: the ratios are what matter, and this keeps them in range.
    const double scale = 1.0 / std::max({double(v[0].inv_w), double(v[1].inv_w), double(v[2].inv_w)});
    for (std::size_t i = 0; i < 3; ++i) q[i] = double(v[i].inv_w) * scale;
    t.depth = make_plane(X, Y, inv_det, depth, ox, oy);
    t.q = make_plane(X, Y, inv_det, q, ox, oy);
    t.p1 = make_plane(X, Y, inv_det, {0.0, q[1], 0.0}, ox, oy);
    t.p2 = make_plane(X, Y, inv_det, {0.0, 0.0, q[2]}, ox, oy);
    if (settings.screen_linear_planes) {
        t.l1 = make_plane(X, Y, inv_det, {0.0, 1.0, 0.0}, ox, oy);
        t.l2 = make_plane(X, Y, inv_det, {0.0, 0.0, 1.0}, ox, oy);
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
