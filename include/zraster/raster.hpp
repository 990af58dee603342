// Triangle setup and coverage: fixed-point vertices, exact integer edge functions (Pineda 1988,
// "A parallel algorithm for polygon rasterization"), the top-left fill rule, and plane equations
// for depth and perspective-correct barycentrics (Heckbert & Moreton 1991).
//
// Window coordinates: x to the right, y DOWN (row 0 is the top row of the image), pixel (px, py)
// has its center at (px + 0.5, py + 0.5). A pixel is covered when its center is strictly inside
// the triangle, or exactly on a top or left edge (Direct3D's rule, also what GL implementations
// use): see precision.hpp for the exactness argument and the limits.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/compiler.hpp>
#include <zraster/export.hpp>
#include <zraster/precision.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>

namespace zraster {

struct Viewport {
    int width = 0;
    int height = 0;
};

enum class CullMode { None, Back, Front };
enum class FrontFace { CounterClockwise, Clockwise };  // as seen on screen with y up (OpenGL)
enum class Interpolation {
    PerspectiveCorrect,  // attributes interpolated through 1/w: right
    ScreenLinear,        // attributes linear in screen space: wrong under perspective (affine)
};

// v(px, py) = c + a * (px - origin_x) + b * (py - origin_y), evaluated in float in exactly this
// order so that a SIMD kernel can reproduce the scalar result bit for bit.
struct PlaneEquation {
    float a = 0, b = 0, c = 0;
    float at(int dx, int dy) const {
        return (c + a * static_cast<float>(dx)) + b * static_cast<float>(dy);
    }
};

// A vertex after the divide and viewport transform: snapped window position in
// 1/kSubpixelScale pixels (y down; |x|, |y| < 2^29 inside the guard band) for coverage, the
// unsnapped position in pixels for the plane equations (depth and barycentrics then follow the
// true geometry instead of the snapped one: on triangles a few pixels wide the difference in
// depth reaches 1e-3 of the depth range), window depth, 1/w.
struct ScreenVertex {
    std::int32_t x = 0, y = 0;
    float z = 0.0f;
    float inv_w = 1.0f;
    float window_x = 0.0f, window_y = 0.0f;
};

struct TriangleSetup {
    // Snapped window positions in 1/kSubpixelScale pixels (y down), in input order.
    std::array<std::int32_t, 3> x{}, y{};
    // Edge functions over pixel indices, E_k(px, py) = a[k] * px + b[k] * py + c[k], positive
    // inside; c[k] already includes the fill-rule bias (-1 on edges that are not top or left),
    // so a pixel is covered iff all three are >= 0.
    std::array<std::int64_t, 3> edge_a{}, edge_b{}, edge_c{};
    // Inclusive pixel bounding box, clipped to the viewport; the plane equations' origin.
    int min_x = 0, min_y = 0, max_x = -1, max_y = -1;
    bool front_facing = true;
    // Window depth (clamped to [0, 1] by the user), and the perspective-correct barycentric
    // numerators: q = sum(lambda_i / w_i), p1 = lambda_1 / w_1, p2 = lambda_2 / w_2 (scaled by a
    // common factor), so beta_1 = p1 / q, beta_2 = p2 / q. l1, l2 are the screen-linear
    // barycentrics lambda_1, lambda_2. All relative to input vertex order.
    PlaneEquation depth, q, p1, p2, l1, l2;
};

enum class SetupResult {
    Visible,     // covers at least the bounding box of one pixel center
    Degenerate,  // zero area after snapping
    Culled,      // back- (or front-) facing per the cull mode
    NoCoverage,  // its bounding box contains no pixel center inside the viewport
};

struct SetupSettings {
    Viewport viewport;
    ClipDepthRange depth_range = ClipDepthRange::NegativeOneToOne;
    CullMode cull = CullMode::Back;
    FrontFace front_face = FrontFace::CounterClockwise;
    // Compute the perspective-correct barycentric planes q, p1, p2 (depth-only work needs only
    // the depth plane).
    bool barycentric_planes = true;
    // Compute the screen-linear barycentric planes l1, l2 too (only ScreenLinear needs them).
    bool screen_linear_planes = true;
};

// Snaps a window-space position (pixels, y down) to the fixed-point grid: nearest 1/256 pixel,
// ties to even (what to_screen does after the viewport transform).
ZRASTER_API std::array<std::int64_t, 2> snap_to_grid(const glm::dvec2& window);

// Divide by w, viewport transform and snap: window x = (ndc_x + 1) / 2 * width,
// y = (1 - ndc_y) / 2 * height (flipped so row 0 is the top), rounded to the nearest 1/256 pixel
// (ties to even). Computed in double from the float clip position, once per vertex: a vertex
// shared by several triangles snaps to the same point in all of them. Returns false when w <= 0
// or the point is beyond the guard band (such vertices must be clipped first).
inline bool to_screen(const glm::vec4& clip, const SetupSettings& settings, ScreenVertex& out);

// Sets up a triangle from snapped vertices: orients the edges, applies the fill rule and the
// cull mode, bounds its pixel centers, and computes the plane equations. `planes` = false skips
// the plane equations (enough for coverage-only work and early rejection).
ZRASTER_API SetupResult setup_triangle(const std::array<ScreenVertex, 3>& v,
                                       const SetupSettings& settings, TriangleSetup& out,
                                       bool planes = true);

// Front-end test of a triangle of snapped vertices: degenerate, culled, or the inclusive pixel
// box of the pixel centers it may cover (empty box: NoCoverage). Exactly the decisions
// setup_triangle makes, without the edge functions and planes.
struct TriangleBounds {
    int min_x, min_y, max_x, max_y;
    bool front_facing;
};
ZRASTER_API SetupResult classify_triangle(const std::array<ScreenVertex, 3>& v,
                                          const SetupSettings& settings, TriangleBounds& out);
// The same on three vertices in place (inline: the front end calls it once per triangle).
inline SetupResult classify_triangle(const ScreenVertex& v0, const ScreenVertex& v1,
                                     const ScreenVertex& v2, const SetupSettings& settings,
                                     TriangleBounds& out);

// Convenience: to_screen on each vertex (all must be inside the guard band with w > 0, what
// the clipper guarantees; otherwise Degenerate), then setup_triangle.
ZRASTER_API SetupResult setup_triangle(const std::array<glm::vec4, 3>& clip,
                                       const SetupSettings& settings, TriangleSetup& out);

// Barycentric weights of the input vertices at pixel (px, py) of a set-up triangle.
ZRASTER_API glm::vec3 barycentrics(const TriangleSetup& t, int px, int py,
                                   Interpolation interpolation);

// Window depth at pixel (px, py), clamped to [0, 1].
ZRASTER_API float depth_at(const TriangleSetup& t, int px, int py);

// Calls fn(px, py) for every covered pixel of t inside [x0, x1) x [y0, y1), row by row, left to
// right. This is the reference (scalar) coverage loop: every faster kernel must agree with it.
template <class Fn>
void for_each_covered_pixel(const TriangleSetup& t, int x0, int y0, int x1, int y1, Fn&& fn) {
    const int bx0 = x0 > t.min_x ? x0 : t.min_x;
    const int by0 = y0 > t.min_y ? y0 : t.min_y;
    const int bx1 = x1 - 1 < t.max_x ? x1 - 1 : t.max_x;
    const int by1 = y1 - 1 < t.max_y ? y1 - 1 : t.max_y;
    for (int py = by0; py <= by1; ++py) {
        std::int64_t e0 = t.edge_a[0] * bx0 + t.edge_b[0] * py + t.edge_c[0];
        std::int64_t e1 = t.edge_a[1] * bx0 + t.edge_b[1] * py + t.edge_c[1];
        std::int64_t e2 = t.edge_a[2] * bx0 + t.edge_b[2] * py + t.edge_c[2];
        for (int px = bx0; px <= bx1; ++px) {
            if ((e0 | e1 | e2) >= 0) fn(px, py);
            e0 += t.edge_a[0];
            e1 += t.edge_a[1];
            e2 += t.edge_a[2];
        }
    }
}

// (Always inlined: as a call, its results come back through memory, and triangle setup stalls
// on them.)
ZRASTER_FORCE_INLINE SetupResult classify_triangle(const ScreenVertex& v0, const ScreenVertex& v1,
                                                   const ScreenVertex& v2,
                                                   const SetupSettings& settings,
                                                   TriangleBounds& out) {
    // Twice the signed area in y-down window space; negative means counter-clockwise as seen with
    // y up, i.e. OpenGL's default front face.
    const std::int64_t x0 = v0.x, y0 = v0.y;
    const std::int64_t area = (std::int64_t{v1.x} - x0) * (std::int64_t{v2.y} - y0) -
                              (std::int64_t{v2.x} - x0) * (std::int64_t{v1.y} - y0);
    if (area == 0) return SetupResult::Degenerate;
    out.front_facing = (settings.front_face == FrontFace::CounterClockwise) == (area < 0);
    if ((settings.cull == CullMode::Back && !out.front_facing) ||
        (settings.cull == CullMode::Front && out.front_facing))
        return SetupResult::Culled;
    // Bounding box of covered pixel centers: px * S + S/2 within [min, max]. S is a power of
    // two, so floor division is an arithmetic shift (C++20 defines >> on negatives so).
    static_assert(kSubpixelScale == 1 << kSubpixelBits);
    constexpr std::int64_t half = kSubpixelScale / 2;
    // Selects on values: std::min of the vertices' fields (references) compiled to a branch per
    // comparison, which the shapes of triangles make unpredictable.
    const auto lo3 = [](std::int64_t a, std::int64_t b, std::int64_t c) {
        const std::int64_t ab = a < b ? a : b;
        return ab < c ? ab : c;
    };
    const auto hi3 = [](std::int64_t a, std::int64_t b, std::int64_t c) {
        const std::int64_t ab = a < b ? b : a;
        return ab < c ? c : ab;
    };
    const std::int64_t lo_x = lo3(x0, v1.x, v2.x), hi_x = hi3(x0, v1.x, v2.x);
    const std::int64_t lo_y = lo3(y0, v1.y, v2.y), hi_y = hi3(y0, v1.y, v2.y);
    const std::int64_t px0 = std::max<std::int64_t>(0, -((half - lo_x) >> kSubpixelBits));  // ceil
    const std::int64_t py0 = std::max<std::int64_t>(0, -((half - lo_y) >> kSubpixelBits));
    const std::int64_t px1 =
        std::min<std::int64_t>(settings.viewport.width - 1, (hi_x - half) >> kSubpixelBits);
    const std::int64_t py1 =
        std::min<std::int64_t>(settings.viewport.height - 1, (hi_y - half) >> kSubpixelBits);
    if (px0 > px1 || py0 > py1) return SetupResult::NoCoverage;
    out.min_x = static_cast<int>(px0);
    out.min_y = static_cast<int>(py0);
    out.max_x = static_cast<int>(px1);
    out.max_y = static_cast<int>(py1);
    return SetupResult::Visible;
}

inline bool to_screen(const glm::vec4& clip, const SetupSettings& settings, ScreenVertex& out) {
    const double w = clip.w;
    if (!(w > 0.0)) return false;
    const double rw = 1.0 / w;
    const double wx = (double(clip.x) * rw + 1.0) * 0.5 * double(settings.viewport.width);
    const double wy = (1.0 - double(clip.y) * rw) * 0.5 * double(settings.viewport.height);
    // Beyond the guard band the fixed-point math could overflow (precision.hpp).
    constexpr double limit = kGuardBand + double(kMaxViewport);
    if (!(wx >= -limit && wx <= limit && wy >= -limit && wy <= limit)) return false;
    // Nearest 1/256 pixel, ties to even (cvtsd2si), as snap_to_grid.
    out.x = static_cast<std::int32_t>(round_to_long(wx * double(kSubpixelScale)));
    out.y = static_cast<std::int32_t>(round_to_long(wy * double(kSubpixelScale)));
    const double z = double(clip.z) * rw;
    out.z = static_cast<float>(
        settings.depth_range == ClipDepthRange::NegativeOneToOne ? 0.5 * z + 0.5 : z);
    out.inv_w = static_cast<float>(rw);
    out.window_x = static_cast<float>(wx);
    out.window_y = static_cast<float>(wy);
    return true;
}

}  // namespace zraster
