// Occluder setup. Everything here errs on the side of covering less and lying further away:
//  - edge lines move inwards by (1 + |dx/dy|) * (2^-14 + subpixel_margin + |coordinates| * 2^-21)
//    pixels: (1 + |dx/dy|) turns a shift of the edge's end points into a shift along the row;
//    2^-21 per unit of coordinate is about twice the float error of the window coordinates and
//    of evaluating the edge per row; subpixel_margin covers a rasterizer that snaps vertices
//    (zraster's Renderer snaps to 1/256 pixel and uses 1/256). A pixel center the buffer covers
//    is then inside the triangle for any of them;
//  - depth planes are computed in double and evaluated in float; z_bias covers that rounding,
//    and z_max (the furthest vertex) caps the bound of thin triangles;
//  - triangles crossing the near plane are clipped to it in clip space (Sutherland & Hodgman
//    1974), and to a guard band 4096 pixels around the screen so that window coordinates stay
//    small enough for the float margins above; a triangle with a vertex at w <= 0 after that,
//    or with a NaN or infinite coordinate, is skipped (not drawing an occluder is always safe).
#include "occlusion/occluder_setup.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace zraster::detail {
namespace {

constexpr double kGuardPixels = occluder_setup::kGuardPixels;

bool finite(const glm::vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// Outcode bits: the screen planes (for trivial rejection) and the planes we clip against.
enum : unsigned {
    kLeft = 1,
    kRight = 2,
    kBottom = 4,
    kTop = 8,
    kFar = 16,
    kNear = 32,
    kGuardLeft = 64,
    kGuardRight = 128,
    kGuardBottom = 256,
    kGuardTop = 512,
};
constexpr unsigned kScreenPlanes = kLeft | kRight | kBottom | kTop | kFar | kNear;
constexpr unsigned kClipPlanes = kNear | kGuardLeft | kGuardRight | kGuardBottom | kGuardTop;

struct Guard {
    float x, y;  // guard band in NDC units: |x| <= x * w
};

unsigned outcode(const glm::vec4& v, Guard g) {
    unsigned code = 0;
    if (v.x < -v.w) code |= kLeft;
    if (v.x > v.w) code |= kRight;
    if (v.y < -v.w) code |= kBottom;
    if (v.y > v.w) code |= kTop;
    if (v.z > v.w) code |= kFar;
    if (v.z < -v.w) code |= kNear;
    if (v.x < -g.x * v.w) code |= kGuardLeft;
    if (v.x > g.x * v.w) code |= kGuardRight;
    if (v.y < -g.y * v.w) code |= kGuardBottom;
    if (v.y > g.y * v.w) code |= kGuardTop;
    return code;
}

float plane_distance(const glm::vec4& v, unsigned plane, Guard g) {
    switch (plane) {
        case kNear:
            return v.z + v.w;
        case kGuardLeft:
            return v.x + g.x * v.w;
        case kGuardRight:
            return g.x * v.w - v.x;
        case kGuardBottom:
            return v.y + g.y * v.w;
        default:
            return g.y * v.w - v.y;
    }
}

// Sutherland-Hodgman against the planes in `planes`; returns the vertex count.
int clip_polygon(std::array<glm::vec4, 9>& poly, int n, unsigned planes, Guard g) {
    std::array<glm::vec4, 9> out;
    for (unsigned plane = kNear; plane <= kGuardTop; plane <<= 1) {
        if (!(planes & plane)) continue;
        int m = 0;
        for (int i = 0; i < n; ++i) {
            const glm::vec4& p = poly[i];
            const glm::vec4& q = poly[(i + 1) % n];
            const float dp = plane_distance(p, plane, g), dq = plane_distance(q, plane, g);
            if (dp >= 0.0f) out[m++] = p;
            if ((dp >= 0.0f) != (dq >= 0.0f)) {
                const float t = dp / (dp - dq);
                out[m++] = p + (q - p) * t;
            }
        }
        n = m;
        std::copy(out.begin(), out.begin() + n, poly.begin());
        if (n < 3) return 0;
    }
    return n;
}

struct WindowVertex {
    double x, y, z;
};

// One projected triangle (already culled and oriented) to an OccluderTriangle. False when it
// covers no pixel center.
bool setup_projected(const std::array<WindowVertex, 3>& v, double area2, int width, int height,
                     float subpixel_margin, OccluderTriangle& t) {
    double max_abs = 0.0, xmin = v[0].x, xmax = v[0].x, ymin = v[0].y, ymax = v[0].y;
    double zmax = v[0].z;
    for (const WindowVertex& p : v) {
        max_abs = std::max({max_abs, std::abs(p.x), std::abs(p.y)});
        xmin = std::min(xmin, p.x);
        xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y);
        ymax = std::max(ymax, p.y);
        zmax = std::max(zmax, p.z);
    }
    const double margin = occluder_setup::kMarginBase + double(subpixel_margin) +
                          max_abs * occluder_setup::kMarginPerCoordinate;
    // Clamped in double before the conversion: a vertex may lie billions of pixels off screen.
    if (!std::isfinite(xmin + xmax + ymin + ymax + margin)) return false;
    const auto first = [](double v, int end) {
        return int(std::clamp(std::ceil(v), 0.0, double(end)));
    };
    const auto last = [](double v, int end) {
        return int(std::clamp(std::floor(v), -1.0, double(end - 1)));
    };
    t.x0 = first(xmin - 0.5, width);
    t.x1 = last(xmax - 0.5, width);
    t.y0 = first(ymin + margin - 0.5, height);
    t.y1 = last(ymax - margin - 0.5, height);
    if (t.x0 > t.x1 || t.y0 > t.y1) return false;

    // Edge lines: x at the center of row y0, and its step per row.
    int lefts = 0, rights = 0;
    const double row0 = t.y0 + 0.5;
    for (int k = 0; k < 3; ++k) {
        const WindowVertex& a = v[k];
        const WindowVertex& b = v[(k + 1) % 3];
        const double dy = b.y - a.y;
        if (std::abs(dy) < 0x1p-10) continue;  // horizontal: the row range bounds it
        const double step = (b.x - a.x) / dy;
        const double x = a.x + (row0 - a.y) * step;
        const double inset = (1.0 + std::abs(step)) * margin;
        // Two per side at most (their dy share a sign); a third would mean a broken triangle.
        if ((area2 * dy < 0.0 ? lefts : rights) == kEdgeSlots) return false;
        if (area2 * dy < 0.0) {  // the inside is to the right of this edge
            t.left_x[lefts] = static_cast<float>(x + inset);
            t.left_step[lefts++] = static_cast<float>(step);
        } else {
            t.right_x[rights] = static_cast<float>(x - inset);
            t.right_step[rights++] = static_cast<float>(step);
        }
    }
    if (lefts == 0 || rights == 0) return false;  // degenerate
    for (; lefts < kEdgeSlots; ++lefts) {
        t.left_x[lefts] = -kNoEdge;
        t.left_step[lefts] = 0.0f;
    }
    for (; rights < kEdgeSlots; ++rights) {
        t.right_x[rights] = kNoEdge;
        t.right_step[rights] = 0.0f;
    }

    // Depth plane z = z0 + gx (x - x0) + gy (y - y0) through vertex 0.
    const double e1x = v[1].x - v[0].x, e1y = v[1].y - v[0].y, e1z = v[1].z - v[0].z;
    const double e2x = v[2].x - v[0].x, e2y = v[2].y - v[0].y, e2z = v[2].z - v[0].z;
    const double gx = (e1z * e2y - e2z * e1y) / area2;
    const double gy = (e1x * e2z - e2x * e1z) / area2;
    const double bw = t.x1 - t.x0 + 2.0, bh = t.y1 - t.y0 + 2.0;
    t.z_origin = static_cast<float>(v[0].z);
    t.z_dx = static_cast<float>(gx);
    t.z_dy = static_cast<float>(gy);
    t.z_kx = static_cast<float>(t.x0 + 0.5 - v[0].x);
    t.z_ky = static_cast<float>(t.y0 + 0.5 - v[0].y);
    const double bias = 0x1p-20 * (1.0 + (std::abs(gx) + std::abs(gy)) * (max_abs + bw + bh));
    t.z_bias = static_cast<float>(std::min(bias, 4.0));
    t.z_max = static_cast<float>(zmax + 0x1p-20);
    if (!std::isfinite(t.z_dx) || !std::isfinite(t.z_dy) || !std::isfinite(t.z_kx) ||
        !std::isfinite(t.z_ky)) {
        // Extreme gradients (a sliver seen edge-on): the furthest vertex bounds every pixel.
        t.z_dx = t.z_dy = t.z_kx = t.z_ky = 0.0f;
        t.z_origin = t.z_max;
    }
    return true;
}

}  // namespace

int setup_occluder(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, int width,
                   int height, const OccluderOptions& options, OccluderTriangle* out) {
    if (!finite(a) || !finite(b) || !finite(c)) return 0;
    const Guard guard{static_cast<float>(1.0 + 2.0 * kGuardPixels / width),
                      static_cast<float>(1.0 + 2.0 * kGuardPixels / height)};
    const unsigned ca = outcode(a, guard), cb = outcode(b, guard), cc = outcode(c, guard);
    if (ca & cb & cc & kScreenPlanes) return 0;
    std::array<glm::vec4, 9> poly{a, b, c};
    int n = 3;
    const unsigned crossing = (ca | cb | cc) & kClipPlanes;
    if (crossing) n = clip_polygon(poly, n, crossing, guard);
    if (n < 3) return 0;

    std::array<WindowVertex, 9> window;
    for (int i = 0; i < n; ++i) {
        const glm::vec4& p = poly[i];
        if (!(p.w > 0.0f)) return 0;
        const double inv_w = 1.0 / p.w;
        window[i] = {(p.x * inv_w * 0.5 + 0.5) * width, (0.5 - p.y * inv_w * 0.5) * height,
                     p.z * inv_w * 0.5 + 0.5};
    }
    int count = 0;
    for (int i = 1; i + 1 < n; ++i) {
        std::array<WindowVertex, 3> tri{window[0], window[i], window[i + 1]};
        // Twice the signed area with y down: negative for counter-clockwise in NDC (y up).
        double area2 = (tri[1].x - tri[0].x) * (tri[2].y - tri[0].y) -
                       (tri[1].y - tri[0].y) * (tri[2].x - tri[0].x);
        if (!(area2 != 0.0) || !std::isfinite(area2)) continue;
        const bool counter_clockwise = area2 < 0.0;
        const bool front = counter_clockwise != options.front_face_clockwise;
        if ((options.cull == OccluderCull::Back && !front) ||
            (options.cull == OccluderCull::Front && front))
            continue;
        if (setup_projected(tri, area2, width, height, options.subpixel_margin, out[count]))
            ++count;
    }
    return count;
}

// Orientation of the projected triangle (sign of the (x, y, w) determinant, which is the sign of
// its screen area when all w > 0); 0 when a w is not positive or a value is not finite.
int orientation(const OccluderSource& s, const std::uint32_t* t) {
    glm::vec3 p[3];
    for (int k = 0; k < 3; ++k) {
        const float* v = s.clip + 4 * std::size_t{t[k]};
        if (!(v[3] > 0.0f)) return 0;
        p[k] = glm::vec3(v[0], v[1], v[3]);
    }
    const float det = glm::dot(p[0], glm::cross(p[1], p[2]));
    return det > 0.0f ? 1 : (det < 0.0f ? -1 : 0);
}

}  // namespace zraster::detail
