// Occluder triangle setup, many triangles at once (one per lane), in float: clip-space corners
// to the OccluderTriangle fields (see occlusion_kernel.hpp) of the triangles inside the guard
// band and in front of the near plane. The error margins are those of occluder_setup.cpp, which
// explains them; in float the depth plane's own error is measured at the vertices (the plane
// and the true interpolant are both affine, so inside the triangle they differ by at most the
// larger residual) and added to the bias. Lanes that need clipping (or hold NaN/Inf) go through
// setup_occluder, in submission order.
// The steps, for each vector of triangles: reading it from the index list (GatherWholeVector
// or GatherLaneByLane, LoadCorner, FindInteriorEdges: occluder_gather-inl.h), ToWindow,
// FootprintOf (culling, bounding box, margins), SetupEdges, SetupDepthPlane, then EmitKept or
// EmitInOrder into the batch.
// Highway's foreach_target re-includes this file once per instruction set; the scalar twin and
// the dispatcher are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "occlusion/occluder_setup_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "occlusion/occluder_gather-inl.h"
#include "occlusion/occluder_setup.hpp"
#include "occlusion/occlusion_kernel.hpp"
#include "occlusion/occlusion_lanes-inl.h"
#include "simd/compress_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace k = occluder_setup;

// The viewport's values, broadcast once per call.
struct SetupView {
    hn::Vec<DF> width, height, max_x, max_y;  // max_x, max_y: the last pixel column and row
    hn::Vec<DF> guard_x, guard_y;             // the guard band in NDC units: |x| <= guard_x * w
    hn::Vec<DF> margin_base, float_margin_base;
};

HWY_INLINE SetupView SetupViewOf(const OccluderSource& src) {
    const DF df;
    SetupView view;
    view.width = hn::Set(df, static_cast<float>(src.width));
    view.height = hn::Set(df, static_cast<float>(src.height));
    view.max_x = hn::Set(df, static_cast<float>(src.width - 1));
    view.max_y = hn::Set(df, static_cast<float>(src.height - 1));
    view.guard_x = hn::Set(df, 1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.width));
    view.guard_y = hn::Set(df, 1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.height));
    view.margin_base = hn::Set(df, k::kMarginBase + src.subpixel_margin);
    view.float_margin_base = hn::Set(df, k::kMarginBase);
    return view;
}

// A vector of triangles in window coordinates (x right and y down in pixels, z in [0, 1]).
struct WindowLanes {
    hn::Vec<DF> x[3], y[3], z[3];
    hn::Mask<DF> fast;  // no clipping needed (see ToWindow)
};

HWY_INLINE WindowLanes ToWindow(const ClipCorner* corners, const SetupView& view) {
    const DF df;
    const auto zero = hn::Zero(df), half = hn::Set(df, 0.5f), one = hn::Set(df, 1.0f);
    WindowLanes t;
    t.fast = hn::Eq(zero, zero);
    for (int v = 0; v < 3; ++v) {
        const auto [x, y, z, w] = corners[v];
        // In front of the near plane, before the far plane, inside the guard band (false for
        // NaN): no clipping needed.
        t.fast = hn::And(t.fast, hn::And(hn::Gt(w, zero), hn::Lt(w, hn::Set(df, k::kMaxW))));
        t.fast = hn::And(t.fast, hn::And(hn::Ge(z, hn::Neg(w)), hn::Le(z, w)));
        t.fast = hn::And(t.fast, hn::Le(hn::Abs(x), hn::Mul(view.guard_x, w)));
        t.fast = hn::And(t.fast, hn::Le(hn::Abs(y), hn::Mul(view.guard_y, w)));
        const auto inv_w = hn::Div(one, w);
        t.x[v] = hn::Mul(hn::Add(hn::Mul(hn::Mul(x, inv_w), half), half), view.width);
        t.y[v] = hn::Mul(hn::Sub(half, hn::Mul(hn::Mul(y, inv_w), half)), view.height);
        t.z[v] = hn::Add(hn::Mul(hn::Mul(z, inv_w), half), half);
    }
    return t;
}

// Where a vector of triangles lands: facing, the pixels whose centers it may cover, margins.
struct FootprintLanes {
    hn::Vec<DF> area2;                 // twice the signed area
    hn::Mask<DF> counter_clockwise;    // on screen (y down): area2 < 0
    hn::Mask<DF> keep;                 // fast, not culled, covering a pixel center
    hn::Vec<DF> max_abs, z_max;        // the largest |x| or |y| of the corners, the largest z
    hn::Vec<DF> margin, float_margin;  // the edge margins (see occluder_setup.cpp)
    hn::Vec<DF> x0, x1, y0, y1, row0;  // pixel bounding box (inclusive); row0 = y0 + 0.5
};

HWY_INLINE FootprintLanes FootprintOf(const WindowLanes& t, const OccluderSource& src,
                                      const SetupView& view) {
    const DF df;
    const auto zero = hn::Zero(df), half = hn::Set(df, 0.5f);
    const auto margin_per = hn::Set(df, k::kMarginPerCoordinate);
    FootprintLanes box;
    box.area2 = hn::Sub(hn::Mul(hn::Sub(t.x[1], t.x[0]), hn::Sub(t.y[2], t.y[0])),
                        hn::Mul(hn::Sub(t.y[1], t.y[0]), hn::Sub(t.x[2], t.x[0])));
    box.counter_clockwise = hn::Lt(box.area2, zero);
    const auto front =
        src.front_face_clockwise ? hn::Not(box.counter_clockwise) : box.counter_clockwise;
    box.keep = hn::And(t.fast, hn::Ne(box.area2, zero));
    if (src.cull_back) box.keep = hn::And(box.keep, front);
    if (src.cull_front) box.keep = hn::AndNot(front, box.keep);

    box.max_abs = GreaterOf(hn::Abs(t.x[0]), hn::Abs(t.y[0]));
    auto xmin = t.x[0], xmax = t.x[0], ymin = t.y[0], ymax = t.y[0];
    box.z_max = t.z[0];
    for (int v = 1; v < 3; ++v) {
        box.max_abs = GreaterOf(box.max_abs, hn::Abs(t.x[v]));
        box.max_abs = GreaterOf(box.max_abs, hn::Abs(t.y[v]));
        xmin = LessOf(xmin, t.x[v]);
        xmax = GreaterOf(xmax, t.x[v]);
        ymin = LessOf(ymin, t.y[v]);
        ymax = GreaterOf(ymax, t.y[v]);
        box.z_max = GreaterOf(box.z_max, t.z[v]);
    }
    box.float_margin = hn::Add(view.float_margin_base, hn::Mul(box.max_abs, margin_per));
    box.margin = hn::Add(view.margin_base, hn::Mul(box.max_abs, margin_per));
    box.x0 = GreaterOf(hn::Ceil(hn::Sub(xmin, half)), zero);
    box.x1 = LessOf(hn::Floor(hn::Sub(xmax, half)), view.max_x);
    box.y0 = GreaterOf(hn::Ceil(hn::Sub(hn::Add(ymin, box.margin), half)), zero);
    box.y1 = LessOf(hn::Floor(hn::Sub(hn::Sub(ymax, box.margin), half)), view.max_y);
    box.keep = hn::And(box.keep, hn::And(hn::Le(box.x0, box.x1), hn::Le(box.y0, box.y1)));
    box.row0 = hn::Add(box.y0, half);
    return box;
}

// The edge fields of a vector of triangles (f[kLeftX..kRightStep + 1]).
HWY_INLINE void SetupEdges(const WindowLanes& t, const FootprintLanes& box,
                           hn::Vec<DI> interior_bits, hn::Vec<DF>* f) {
    const DF df;
    const DI di;
    const auto zero = hn::Zero(df), one = hn::Set(df, 1.0f);
    const auto no_edge = hn::Set(df, kNoEdge), minus_no_edge = hn::Set(df, -kNoEdge);
    hn::Vec<DF> left_x[3], left_step[3], right_x[3], right_step[3];
    hn::Mask<DF> left[3], right[3];
    for (int e = 0; e < 3; ++e) {
        const hn::Vec<DF>&ax = t.x[e], &ay = t.y[e], &bx = t.x[(e + 1) % 3], &by = t.y[(e + 1) % 3];
        const auto dy = hn::Sub(by, ay);
        const auto slanted = hn::Ge(hn::Abs(dy), hn::Set(df, k::kHorizontal));
        const auto step = hn::Div(hn::Sub(bx, ax), hn::IfThenElse(slanted, dy, one));
        const auto x = hn::Add(ax, hn::Mul(hn::Sub(box.row0, ay), step));
        // Interior edges move outwards by the float error instead (see interior_edges).
        const auto is_interior =
            hn::RebindMask(df, hn::Ne(hn::And(interior_bits, hn::Set(di, 1 << e)), hn::Zero(di)));
        const auto inset =
            hn::Mul(hn::Add(one, hn::Abs(step)),
                    hn::IfThenElse(is_interior, hn::Neg(box.float_margin), box.margin));
        // The inside is to the right of the edge when area2 * dy < 0.
        const auto left_side = hn::Xor(box.counter_clockwise, hn::Lt(dy, zero));
        const auto is_left = hn::And(slanted, left_side);
        const auto is_right = hn::AndNot(left_side, slanted);
        left[e] = is_left;
        right[e] = is_right;
        left_x[e] = hn::IfThenElse(is_left, hn::Add(x, inset), minus_no_edge);
        left_step[e] = hn::IfThenElseZero(is_left, step);
        right_x[e] = hn::IfThenElse(is_right, hn::Sub(x, inset), no_edge);
        right_step[e] = hn::IfThenElseZero(is_right, step);
    }
    // At most two edges per side (their dy share a sign): two slots each (see kEdgeSlots).
    // Slot 0 takes the first edge of the side, slot 1 the second (or the last edge again).
    const auto pack = [&](const hn::Vec<DF>* v, const hn::Mask<DF>* is, int slot) {
        return slot == 0 ? hn::IfThenElse(is[0], v[0], hn::IfThenElse(is[1], v[1], v[2]))
                         : hn::IfThenElse(hn::And(is[0], is[1]), v[1], v[2]);
    };
    for (int slot = 0; slot < kEdgeSlots; ++slot) {
        f[k::kLeftX + slot] = pack(left_x, left, slot);
        f[k::kLeftStep + slot] = pack(left_step, left, slot);
        f[k::kRightX + slot] = pack(right_x, right, slot);
        f[k::kRightStep + slot] = pack(right_step, right, slot);
    }
}

// The depth fields of a vector of triangles (f[kZOrigin..kZMax]).
HWY_INLINE void SetupDepthPlane(const WindowLanes& t, const FootprintLanes& box, hn::Vec<DF>* f) {
    const DF df;
    const auto half = hn::Set(df, 0.5f), one = hn::Set(df, 1.0f);
    const auto slack = hn::Set(df, k::kDepthSlack);
    const auto e1x = hn::Sub(t.x[1], t.x[0]), e1y = hn::Sub(t.y[1], t.y[0]);
    const auto e1z = hn::Sub(t.z[1], t.z[0]);
    const auto e2x = hn::Sub(t.x[2], t.x[0]), e2y = hn::Sub(t.y[2], t.y[0]);
    const auto e2z = hn::Sub(t.z[2], t.z[0]);
    const auto gx = hn::Div(hn::Sub(hn::Mul(e1z, e2y), hn::Mul(e2z, e1y)), box.area2);
    const auto gy = hn::Div(hn::Sub(hn::Mul(e1x, e2z), hn::Mul(e2x, e1z)), box.area2);
    const auto err1 = hn::Abs(hn::Sub(hn::Add(hn::Mul(gx, e1x), hn::Mul(gy, e1y)), e1z));
    const auto err2 = hn::Abs(hn::Sub(hn::Add(hn::Mul(gx, e2x), hn::Mul(gy, e2y)), e2z));
    const auto residual = GreaterOf(err1, err2);
    const auto extent =
        hn::Add(hn::Add(box.max_abs, hn::Sub(box.x1, box.x0)), hn::Sub(box.y1, box.y0));
    auto spread = hn::Mul(hn::Add(hn::Abs(gx), hn::Abs(gy)), hn::Add(extent, hn::Set(df, 4.0f)));
    spread = hn::Add(hn::Add(one, spread), hn::Add(hn::Abs(e1z), hn::Abs(e2z)));
    // Pixels up to a margin outside the triangle (interior edges) see the plane extended.
    const auto reach = hn::Mul(hn::Add(hn::Abs(gx), hn::Abs(gy)), hn::Add(box.margin, box.margin));
    const auto bias = hn::Add(hn::Add(hn::Add(residual, residual), hn::Mul(slack, spread)), reach);
    const auto sane = hn::And(hn::Lt(hn::Abs(gx), hn::Set(df, k::kHugeGradient)),
                              hn::Lt(hn::Abs(gy), hn::Set(df, k::kHugeGradient)));
    const auto z_max = hn::Add(box.z_max, slack);
    f[k::kZOrigin] = hn::IfThenElse(sane, t.z[0], z_max);
    f[k::kZDx] = hn::IfThenElseZero(sane, gx);
    f[k::kZDy] = hn::IfThenElseZero(sane, gy);
    f[k::kZKx] = hn::IfThenElseZero(sane, hn::Sub(hn::Add(box.x0, half), t.x[0]));
    f[k::kZKy] = hn::IfThenElseZero(sane, hn::Sub(box.row0, t.y[0]));
    f[k::kZBias] = hn::IfThenElseZero(sane, bias);
    f[k::kZMax] = z_max;
}

// A set-up vector of triangles: the float fields and the pixel bounding box (x0, x1, y0, y1;
// integral and inside the guard band in kept lanes, the others are dropped).
struct SetUpLanes {
    hn::Vec<DF> field[k::kFloatFields];
    hn::Vec<DI> box[4];
};

// No lane to clip (the usual case): the `take` lanes go out in order, straight into the batch
// from triangle n on, one register compress and store per field. Returns the new count.
HWY_INLINE std::size_t EmitKept(const SetUpLanes& s, hn::Mask<DF> take, OccluderBatch& out,
                                std::size_t n) {
    const DF df;
    const DI di;
    std::int32_t* const out_box[4] = {out.x0, out.x1, out.y0, out.y1};
    const auto take_i = hn::RebindMask(di, take);
    for (int field = 0; field < k::kFloatFields; ++field)
        hn::StoreU(CompressLanes(df, s.field[field], take), df, out.field[field] + n);
    for (int b = 0; b < 4; ++b) hn::StoreU(CompressLanes(di, s.box[b], take_i), di, out_box[b] + n);
    return n + hn::CountTrue(df, take);
}

// Some lane needs clipping: lane by lane, in submission order, the lanes to clip through
// setup_occluder (triangles i0..) and the kept others as set up. Returns the new count.
HWY_INLINE std::size_t EmitInOrder(const OccluderSource& src, std::size_t i0, std::size_t m,
                                   const IndexLanes& lanes, const SetUpLanes& s, hn::Mask<DF> keep,
                                   hn::Mask<DF> fast, OccluderBatch& out, std::size_t n) {
    const DF df;
    const DI di;
    const auto one = hn::Set(df, 1.0f);
    alignas(64) float fields[k::kFloatFields][kMaxLanes];
    alignas(64) std::int32_t box[4][kMaxLanes];
    alignas(64) float keep_lanes[kMaxLanes], fast_lanes[kMaxLanes];
    for (int field = 0; field < k::kFloatFields; ++field)
        hn::Store(s.field[field], df, fields[field]);
    for (int b = 0; b < 4; ++b) hn::Store(s.box[b], di, box[b]);
    hn::Store(hn::IfThenElseZero(keep, one), df, keep_lanes);
    hn::Store(hn::IfThenElseZero(fast, one), df, fast_lanes);
    std::int32_t* const out_box[4] = {out.x0, out.x1, out.y0, out.y1};
    for (std::size_t l = 0; l < m; ++l) {
        if (!((lanes.valid >> l) & 1u)) continue;
        if (fast_lanes[l] == 0.0f) {
            n = append_clipped_occluder(src, i0 + l, out, n);
            continue;
        }
        if (keep_lanes[l] == 0.0f) continue;
        for (int b = 0; b < 4; ++b) out_box[b][n] = box[b][l];
        for (int field = 0; field < k::kFloatFields; ++field)
            out.field[field][n] = fields[field][l];
        ++n;
    }
    return n;
}

std::size_t SetupOccluders(const OccluderSource& src, std::size_t first, std::size_t count,
                           OccluderBatch& out) {
    if (src.vertex_count == 0) return 0;
    const DF df;
    const std::size_t lanes = hn::Lanes(df);
    const SetupView view = SetupViewOf(src);
    IndexLanes triangles;
    std::size_t n = 0;
    for (std::size_t base = 0; base < count; base += lanes) {
        const std::size_t m = std::min(lanes, count - base);
        const std::size_t i0 = first + base;
        if (m == lanes && i0 > 0 && i0 + lanes < src.triangle_count &&
            src.vertex_count <= 0xffffffffu)
            GatherWholeVector(src, i0, triangles);
        else
            GatherLaneByLane(src, i0, m, triangles);
        ClipCorner corners[3];
        for (int v = 0; v < 3; ++v) corners[v] = LoadCorner(df, src.clip, triangles.read[v]);
        FindInteriorEdges(src, i0, m, triangles);
        const WindowLanes t = ToWindow(corners, view);
        const FootprintLanes box = FootprintOf(t, src, view);
        SetUpLanes s;
        SetupEdges(t, box, hn::Load(DI(), triangles.interior), s.field);
        SetupDepthPlane(t, box, s.field);
        s.box[0] = TruncInRange(box.x0);
        s.box[1] = TruncInRange(box.x1);
        s.box[2] = TruncInRange(box.y0);
        s.box[3] = TruncInRange(box.y1);
        alignas(8) std::uint8_t valid_bytes[8] = {};
        std::memcpy(valid_bytes, &triangles.valid, sizeof(triangles.valid));  // as StoreMaskBits
        const auto valid = hn::LoadMaskBits(df, valid_bytes);
        if (hn::AllFalse(df, hn::AndNot(t.fast, valid)))
            n = EmitKept(s, hn::And(box.keep, valid), out, n);
        else
            n = EmitInOrder(src, i0, m, triangles, s, box.keep, t.fast, out, n);
    }
    return n;
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(SetupOccluders);

std::size_t setup_occluders(const OccluderSource& source, std::size_t first, std::size_t count,
                            OccluderBatch& out) {
    return HWY_DYNAMIC_DISPATCH(SetupOccluders)(source, first, count, out);
}

std::size_t append_clipped_occluder(const OccluderSource& source, std::size_t triangle,
                                    OccluderBatch& out, std::size_t n) {
    OccluderOptions options;
    options.cull = source.cull_back    ? OccluderCull::Back
                   : source.cull_front ? OccluderCull::Front
                                       : OccluderCull::None;
    options.front_face_clockwise = source.front_face_clockwise;
    options.subpixel_margin = source.subpixel_margin;
    const std::uint32_t* t = source.indices + 3 * triangle;
    const auto vertex = [&](std::uint32_t i) {
        const float* p = source.clip + 4 * std::size_t{i};
        return glm::vec4(p[0], p[1], p[2], p[3]);
    };
    OccluderTriangle pieces[kMaxOccluderPieces];
    const int made = setup_occluder(vertex(t[0]), vertex(t[1]), vertex(t[2]), source.width,
                                    source.height, options, pieces);
    for (int p = 0; p < made; ++p) out.set(n++, pieces[p]);
    return n;
}

namespace {

// The scalar twins of the SIMD steps, one triangle at a time.
namespace k = occluder_setup;

struct SetupViewScalar {
    float width, height, max_x, max_y, guard_x, guard_y;
    explicit SetupViewScalar(const OccluderSource& src)
        : width(static_cast<float>(src.width)),
          height(static_cast<float>(src.height)),
          max_x(static_cast<float>(src.width - 1)),
          max_y(static_cast<float>(src.height - 1)),
          guard_x(1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.width)),
          guard_y(1.0f + 2.0f * k::kGuardPixels / static_cast<float>(src.height)) {}
};

struct WindowTriangle {
    float x[3], y[3], z[3];
    bool fast;
};

WindowTriangle to_window(const OccluderSource& src, const std::uint32_t* t,
                         const SetupViewScalar& view) {
    WindowTriangle out;
    out.fast = true;
    for (int v = 0; v < 3; ++v) {
        const float* p = src.clip + 4 * std::size_t{t[v]};
        const float x = p[0], y = p[1], z = p[2], w = p[3];
        out.fast = out.fast && (w > 0.0f && w < k::kMaxW);
        out.fast = out.fast && (z >= -w && z <= w);
        out.fast = out.fast && std::fabs(x) <= view.guard_x * w;
        out.fast = out.fast && std::fabs(y) <= view.guard_y * w;
        const float inv_w = 1.0f / w;
        out.x[v] = ((x * inv_w) * 0.5f + 0.5f) * view.width;
        out.y[v] = (0.5f - (y * inv_w) * 0.5f) * view.height;
        out.z[v] = (z * inv_w) * 0.5f + 0.5f;
    }
    return out;
}

float min_f(float a, float b) {
    return a < b ? a : b;
}
float max_f(float a, float b) {
    return a > b ? a : b;
}

struct Footprint {
    float area2;
    bool counter_clockwise, keep;
    float max_abs, z_max, margin, float_margin;
    float x0, x1, y0, y1, row0;
};

Footprint footprint_of(const WindowTriangle& t, const OccluderSource& src,
                       const SetupViewScalar& view) {
    Footprint box;
    box.area2 = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
    box.counter_clockwise = box.area2 < 0.0f;
    const bool front = src.front_face_clockwise ? !box.counter_clockwise : box.counter_clockwise;
    box.keep = box.area2 != 0.0f;
    if (src.cull_back) box.keep = box.keep && front;
    if (src.cull_front) box.keep = box.keep && !front;
    box.max_abs = max_f(std::fabs(t.x[0]), std::fabs(t.y[0]));
    float xmin = t.x[0], xmax = t.x[0], ymin = t.y[0], ymax = t.y[0];
    box.z_max = t.z[0];
    for (int v = 1; v < 3; ++v) {
        box.max_abs = max_f(box.max_abs, std::fabs(t.x[v]));
        box.max_abs = max_f(box.max_abs, std::fabs(t.y[v]));
        xmin = min_f(xmin, t.x[v]);
        xmax = max_f(xmax, t.x[v]);
        ymin = min_f(ymin, t.y[v]);
        ymax = max_f(ymax, t.y[v]);
        box.z_max = max_f(box.z_max, t.z[v]);
    }
    box.float_margin = k::kMarginBase + box.max_abs * k::kMarginPerCoordinate;
    box.margin = (k::kMarginBase + src.subpixel_margin) + box.max_abs * k::kMarginPerCoordinate;
    box.x0 = max_f(std::ceil(xmin - 0.5f), 0.0f);
    box.x1 = min_f(std::floor(xmax - 0.5f), view.max_x);
    box.y0 = max_f(std::ceil((ymin + box.margin) - 0.5f), 0.0f);
    box.y1 = min_f(std::floor((ymax - box.margin) - 0.5f), view.max_y);
    box.keep = box.keep && box.x0 <= box.x1 && box.y0 <= box.y1;
    box.row0 = box.y0 + 0.5f;
    return box;
}

void setup_edges(const WindowTriangle& t, const Footprint& box, std::uint32_t interior,
                 OccluderTriangle& o) {
    float left_x[3], left_step[3], right_x[3], right_step[3];
    bool left[3], right[3];
    for (int e = 0; e < 3; ++e) {
        const float ax = t.x[e], ay = t.y[e], bx = t.x[(e + 1) % 3], by = t.y[(e + 1) % 3];
        const float dy = by - ay;
        const bool slanted = std::fabs(dy) >= k::kHorizontal;
        const float step = (bx - ax) / (slanted ? dy : 1.0f);
        const float x = ax + (box.row0 - ay) * step;
        const bool is_interior = (interior >> e) & 1u;
        const float inset =
            (1.0f + std::fabs(step)) * (is_interior ? -box.float_margin : box.margin);
        const bool left_side = box.counter_clockwise != (dy < 0.0f);
        const bool is_left = slanted && left_side, is_right = slanted && !left_side;
        left[e] = is_left;
        right[e] = is_right;
        left_x[e] = is_left ? x + inset : -kNoEdge;
        left_step[e] = is_left ? step : 0.0f;
        right_x[e] = is_right ? x - inset : kNoEdge;
        right_step[e] = is_right ? step : 0.0f;
    }
    const auto pack = [](const float* v, const bool* is, int slot) {
        return slot == 0 ? (is[0] ? v[0] : (is[1] ? v[1] : v[2])) : (is[0] && is[1] ? v[1] : v[2]);
    };
    for (int slot = 0; slot < kEdgeSlots; ++slot) {
        o.left_x[slot] = pack(left_x, left, slot);
        o.left_step[slot] = pack(left_step, left, slot);
        o.right_x[slot] = pack(right_x, right, slot);
        o.right_step[slot] = pack(right_step, right, slot);
    }
}

void setup_depth_plane(const WindowTriangle& t, const Footprint& box, OccluderTriangle& o) {
    const float e1x = t.x[1] - t.x[0], e1y = t.y[1] - t.y[0], e1z = t.z[1] - t.z[0];
    const float e2x = t.x[2] - t.x[0], e2y = t.y[2] - t.y[0], e2z = t.z[2] - t.z[0];
    const float gx = (e1z * e2y - e2z * e1y) / box.area2;
    const float gy = (e1x * e2z - e2x * e1z) / box.area2;
    const float err1 = std::fabs((gx * e1x + gy * e1y) - e1z);
    const float err2 = std::fabs((gx * e2x + gy * e2y) - e2z);
    const float residual = max_f(err1, err2);
    const float extent = (box.max_abs + (box.x1 - box.x0)) + (box.y1 - box.y0);
    float spread = (std::fabs(gx) + std::fabs(gy)) * (extent + 4.0f);
    spread = (1.0f + spread) + (std::fabs(e1z) + std::fabs(e2z));
    const float reach = (std::fabs(gx) + std::fabs(gy)) * (box.margin + box.margin);
    const float bias = ((residual + residual) + k::kDepthSlack * spread) + reach;
    const bool sane = std::fabs(gx) < k::kHugeGradient && std::fabs(gy) < k::kHugeGradient;
    const float z_max = box.z_max + k::kDepthSlack;
    o.z_origin = sane ? t.z[0] : z_max;
    o.z_dx = sane ? gx : 0.0f;
    o.z_dy = sane ? gy : 0.0f;
    o.z_kx = sane ? (box.x0 + 0.5f) - t.x[0] : 0.0f;
    o.z_ky = sane ? box.row0 - t.y[0] : 0.0f;
    o.z_bias = sane ? bias : 0.0f;
    o.z_max = z_max;
}

}  // namespace

// Triangle by triangle, the operations of SetupOccluders in the same order.
std::size_t setup_occluders_scalar(const OccluderSource& src, std::size_t first, std::size_t count,
                                   OccluderBatch& batch) {
    const SetupViewScalar view(src);
    std::size_t n = 0;
    for (std::size_t i = first; i < first + count; ++i) {
        const std::uint32_t* t = src.indices + 3 * i;
        if (t[0] >= src.vertex_count || t[1] >= src.vertex_count || t[2] >= src.vertex_count)
            continue;
        const std::uint32_t interior = interior_edges(src, i);
        const WindowTriangle w = to_window(src, t, view);
        if (!w.fast) {
            n = append_clipped_occluder(src, i, batch, n);
            continue;
        }
        const Footprint box = footprint_of(w, src, view);
        if (!box.keep) continue;
        OccluderTriangle o;
        setup_edges(w, box, interior, o);
        setup_depth_plane(w, box, o);
        o.x0 = static_cast<int>(box.x0);
        o.x1 = static_cast<int>(box.x1);
        o.y0 = static_cast<int>(box.y0);
        o.y1 = static_cast<int>(box.y1);
        batch.set(n++, o);
    }
    return n;
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
