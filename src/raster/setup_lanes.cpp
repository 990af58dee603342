// See setup_lanes.hpp. Highway's foreach_target re-includes this file once per instruction set;
// the scalar reference and the dispatcher are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/setup_lanes.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <array>
#include <cstdlib>

#include "raster/setup_lanes.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// setup_triangle's operations, in its order, on lanes of doubles (integers included: see the
// header).
void SetupLanesImpl(const VertexLanes& in, int count, const SetupSettings& settings,
                    SetupLanes& out, const JobWindow* window) {
    const hn::CappedTag<double, kSetupLanes> dd;
    const hn::Rebind<std::int32_t, decltype(dd)> di;
    const hn::Rebind<float, decltype(dd)> df;
    const hn::RebindToSigned<decltype(dd)> dl;
    const int lanes = static_cast<int>(hn::Lanes(dd));
    const auto zero = hn::Zero(dd), one = hn::Set(dd, 1.0), half_pixel = hn::Set(dd, 0.5);
    const auto half = hn::Set(dd, double(kSubpixelScale / 2));
    const auto scale = hn::Set(dd, double(kSubpixelScale));
    const auto inv_scale = hn::Set(dd, 1.0 / double(kSubpixelScale));
    const auto inv_scale2 = hn::Set(dd, (1.0 / double(kSubpixelScale)) / double(kSubpixelScale));
    const auto limit = hn::Set(dd, double(kSetupLanesCoordinateLimit));
    const auto last_x = hn::Set(dd, double(settings.viewport.width - 1));
    const auto last_y = hn::Set(dd, double(settings.viewport.height - 1));
    const bool ccw = settings.front_face == FrontFace::CounterClockwise;
    // Integers held exactly in doubles, below 2^51 in magnitude (see the header), as int64:
    // added to 1.5 * 2^52 their bits are that number's plus the integer. (Without AVX-512
    // there is no double -> int64 conversion: Highway's emulation took a fifth of the setup.)
    const auto magic = hn::Set(dd, 6755399441055744.0);  // 1.5 * 2^52
    const auto magic_bits = hn::BitCast(dl, magic);
    const auto exact_int64 = [&](hn::Vec<decltype(dd)> v) HWY_ATTR {
        return hn::Sub(hn::BitCast(dl, hn::Add(v, magic)), magic_bits);
    };
    for (int lane = 0; lane < count; lane += lanes) {
        const auto load_i = [&](const std::int32_t* p) {
            return hn::PromoteTo(dd, hn::LoadU(di, p + lane));
        };
        const auto load_f = [&](const float* p) {
            return hn::PromoteTo(dd, hn::LoadU(df, p + lane));
        };
        const auto x0 = load_i(in.x[0]), x1 = load_i(in.x[1]), x2 = load_i(in.x[2]);
        const auto y0 = load_i(in.y[0]), y1 = load_i(in.y[1]), y2 = load_i(in.y[2]);
        const auto within = [&](hn::Vec<decltype(dd)> v) { return hn::Lt(hn::Abs(v), limit); };
        const auto small = hn::And(hn::And(hn::And(within(x0), within(x1)), within(x2)),
                                   hn::And(hn::And(within(y0), within(y1)), within(y2)));

        // classify_triangle: area, facing, culling, the box of covered pixel centers.
        const auto area = hn::Sub(hn::Mul(hn::Sub(x1, x0), hn::Sub(y2, y0)),
                                  hn::Mul(hn::Sub(x2, x0), hn::Sub(y1, y0)));
        const auto negative = hn::Lt(area, zero);
        const auto front = ccw ? negative : hn::Not(negative);
        auto rejected = hn::Eq(area, zero);
        if (settings.cull == CullMode::Back) rejected = hn::Or(rejected, hn::Not(front));
        if (settings.cull == CullMode::Front) rejected = hn::Or(rejected, front);
        const auto lo_x = hn::Min(hn::Min(x0, x1), x2), hi_x = hn::Max(hn::Max(x0, x1), x2);
        const auto lo_y = hn::Min(hn::Min(y0, y1), y2), hi_y = hn::Max(hn::Max(y0, y1), y2);
        // Floor division by the power-of-two scale: exact in double.
        const auto px0 = hn::Max(zero, hn::Neg(hn::Floor(hn::Mul(hn::Sub(half, lo_x), inv_scale))));
        const auto py0 = hn::Max(zero, hn::Neg(hn::Floor(hn::Mul(hn::Sub(half, lo_y), inv_scale))));
        const auto px1 = hn::Min(last_x, hn::Floor(hn::Mul(hn::Sub(hi_x, half), inv_scale)));
        const auto py1 = hn::Min(last_y, hn::Floor(hn::Mul(hn::Sub(hi_y, half), inv_scale)));
        rejected = hn::Or(rejected, hn::Or(hn::Gt(px0, px1), hn::Gt(py0, py1)));
        const auto scalar = hn::Or(rejected, hn::Not(small));
        hn::StoreU(hn::DemoteTo(di, px0), di, out.min_x + lane);
        hn::StoreU(hn::DemoteTo(di, py0), di, out.min_y + lane);
        hn::StoreU(hn::DemoteTo(di, px1), di, out.max_x + lane);
        hn::StoreU(hn::DemoteTo(di, py1), di, out.max_y + lane);
        hn::StoreU(hn::DemoteTo(di, hn::IfThenElseZero(front, one)), di, out.front_facing + lane);
        hn::StoreU(hn::DemoteTo(di, hn::IfThenElseZero(scalar, one)), di, out.scalar + lane);

        // Single jobs in the window (see the header): the box clipped to it, in double too.
        auto single = hn::FirstN(dd, 0);
        auto job_x = zero, job_y = zero;
        if (window != nullptr) {
            const auto wx0 = hn::Set(dd, double(window->x0)), wy0 = hn::Set(dd, double(window->y0));
            job_x = hn::Max(px0, wx0);
            job_y = hn::Max(py0, wy0);
            const auto end_x = hn::Min(px1, hn::Set(dd, double(window->x1 - 1)));
            const auto end_y = hn::Min(py1, hn::Set(dd, double(window->y1 - 1)));
            const auto extent = hn::Set(dd, double(kSingleJobExtent));
            single = hn::AndNot(
                scalar, hn::And(hn::And(hn::Lt(hn::Sub(hi_x, lo_x), extent),
                                        hn::Lt(hn::Sub(hi_y, lo_y), extent)),
                                hn::And(hn::Lt(hn::Sub(end_x, job_x),
                                               hn::Set(dd, double(window->max_columns))),
                                        hn::And(hn::Le(job_x, end_x), hn::Le(job_y, end_y)))));
            const auto store_job = [&](hn::Vec<decltype(dd)> v, std::int32_t* to) {
                hn::StoreU(hn::DemoteTo(di, hn::IfThenElseZero(single, v)), di, to + lane);
            };
            store_job(one, out.single_job);
            store_job(hn::Sub(job_x, wx0), out.job_x0);
            store_job(hn::Sub(job_y, wy0), out.job_y0);
            store_job(hn::Add(hn::Sub(end_x, job_x), one), out.job_width);
            store_job(hn::Add(hn::Sub(end_y, job_y), one), out.job_height);
            store_job(hn::Sub(job_x, px0), out.job_plane_dx);
            store_job(hn::Sub(job_y, py0), out.job_plane_dy);
        }

        // The edges, oriented by the sign of the area, with the fill rule's bias.
        const auto sign = hn::IfThenElse(negative, hn::Set(dd, -1.0), one);
        // (Inline: GCC kept it a call, its vectors passed through memory.)
        const auto edge = [&](int k, hn::Vec<decltype(dd)> ax, hn::Vec<decltype(dd)> ay,
                              hn::Vec<decltype(dd)> bx, hn::Vec<decltype(dd)> by) HWY_ATTR
            __attribute__((always_inline)) {
            const auto dx = hn::Mul(sign, hn::Sub(bx, ax)), dy = hn::Mul(sign, hn::Sub(by, ay));
            const auto top_left =
                hn::Or(hn::Lt(dy, zero), hn::And(hn::Eq(dy, zero), hn::Gt(dx, zero)));
            const auto c =
                hn::Sub(hn::Sub(hn::Mul(dx, hn::Sub(half, ay)), hn::Mul(dy, hn::Sub(half, ax))),
                        hn::IfThenZeroElse(top_left, one));
            const auto a = hn::Mul(hn::Neg(dy), scale), b = hn::Mul(dx, scale);
            hn::StoreU(exact_int64(a), dl, out.edge_a[k] + lane);
            hn::StoreU(exact_int64(b), dl, out.edge_b[k] + lane);
            hn::StoreU(exact_int64(c), dl, out.edge_c[k] + lane);
            if (window == nullptr) return;
            // A single job's values fit 32 bits (see kSingleJobExtent).
            const auto store_job = [&](hn::Vec<decltype(dd)> v, std::int32_t* to) {
                hn::StoreU(hn::DemoteTo(di, hn::IfThenElseZero(single, v)), di, to + lane);
            };
            store_job(hn::Add(hn::Add(hn::Mul(a, job_x), hn::Mul(b, job_y)), c), out.job_e[k]);
            store_job(a, out.job_step_x[k]);
            store_job(b, out.job_step_y[k]);
        };
        edge(0, x1, y1, x2, y2);
        edge(1, x2, y2, x0, y0);
        edge(2, x0, y0, x1, y1);

        // The plane equations over the unsnapped positions, or the snapped ones where the
        // unsnapped triangle's orientation differs.
        const auto fx0 = load_f(in.window_x[0]), fy0 = load_f(in.window_y[0]);
        auto ex1 = hn::Sub(load_f(in.window_x[1]), fx0), ey1 = hn::Sub(load_f(in.window_y[1]), fy0);
        auto ex2 = hn::Sub(load_f(in.window_x[2]), fx0), ey2 = hn::Sub(load_f(in.window_y[2]), fy0);
        auto det = hn::Sub(hn::Mul(ex1, ey2), hn::Mul(ex2, ey1));
        auto ox = hn::Sub(hn::Add(px0, half_pixel), fx0);
        auto oy = hn::Sub(hn::Add(py0, half_pixel), fy0);
        const auto unsnapped = hn::Gt(hn::Mul(det, area), zero);
        ex1 = hn::IfThenElse(unsnapped, ex1, hn::Mul(hn::Sub(x1, x0), inv_scale));
        ey1 = hn::IfThenElse(unsnapped, ey1, hn::Mul(hn::Sub(y1, y0), inv_scale));
        ex2 = hn::IfThenElse(unsnapped, ex2, hn::Mul(hn::Sub(x2, x0), inv_scale));
        ey2 = hn::IfThenElse(unsnapped, ey2, hn::Mul(hn::Sub(y2, y0), inv_scale));
        det = hn::IfThenElse(unsnapped, det, hn::Mul(area, inv_scale2));
        ox = hn::IfThenElse(unsnapped, ox,
                            hn::Sub(hn::Add(px0, half_pixel), hn::Mul(x0, inv_scale)));
        oy = hn::IfThenElse(unsnapped, oy,
                            hn::Sub(hn::Add(py0, half_pixel), hn::Mul(y0, inv_scale)));
        const auto inv_det = hn::Div(one, det);
        const auto l1_dx = hn::Mul(ey2, inv_det), l1_dy = hn::Mul(hn::Neg(ex2), inv_det);
        const auto l2_dx = hn::Mul(hn::Neg(ey1), inv_det), l2_dy = hn::Mul(ex1, inv_det);
        const auto plane = [&](int p, hn::Vec<decltype(dd)> f0, hn::Vec<decltype(dd)> df1,
                               hn::Vec<decltype(dd)> df2) {
            const auto a = hn::Add(hn::Mul(df1, l1_dx), hn::Mul(df2, l2_dx));
            const auto b = hn::Add(hn::Mul(df1, l1_dy), hn::Mul(df2, l2_dy));
            const auto c = hn::Add(hn::Add(f0, hn::Mul(a, ox)), hn::Mul(b, oy));
            hn::StoreU(hn::DemoteTo(df, a), df, out.plane_a[p] + lane);
            hn::StoreU(hn::DemoteTo(df, b), df, out.plane_b[p] + lane);
            hn::StoreU(hn::DemoteTo(df, c), df, out.plane_c[p] + lane);
        };
        const auto z0 = load_f(in.z[0]);
        plane(SetupLanes::kDepth, z0, hn::Sub(load_f(in.z[1]), z0), hn::Sub(load_f(in.z[2]), z0));
        if (!settings.barycentric_planes) continue;
        const auto w0 = load_f(in.inv_w[0]), w1 = load_f(in.inv_w[1]), w2 = load_f(in.inv_w[2]);
        const auto w_scale = hn::Div(one, hn::Max(hn::Max(w0, w1), w2));
        const auto q0 = hn::Mul(w0, w_scale), q1 = hn::Mul(w1, w_scale), q2 = hn::Mul(w2, w_scale);
        plane(SetupLanes::kQ, q0, hn::Sub(q1, q0), hn::Sub(q2, q0));
        plane(SetupLanes::kP1, zero, q1, zero);
        plane(SetupLanes::kP2, zero, zero, q2);
        if (!settings.screen_linear_planes) continue;
        plane(SetupLanes::kL1, zero, one, zero);
        plane(SetupLanes::kL2, zero, zero, one);
    }
}

const char* SetupLanesTarget() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(SetupLanesImpl);
HWY_EXPORT(SetupLanesTarget);

void setup_lanes(const VertexLanes& in, int count, const SetupSettings& settings, SetupLanes& out,
                 const JobWindow* window) {
    HWY_DYNAMIC_DISPATCH(SetupLanesImpl)(in, count, settings, out, window);
}

const char* setup_lanes_target() {
    return HWY_DYNAMIC_DISPATCH(SetupLanesTarget)();
}

namespace {

std::array<ScreenVertex, 3> lane_vertices(const VertexLanes& in, int lane) {
    return {in.vertex(0, lane), in.vertex(1, lane), in.vertex(2, lane)};
}

// The single job of lane `lane` (set up in `t`) in `window`, as the header describes it.
void single_job_scalar(const VertexLanes& in, int lane, const TriangleSetup& t,
                       const JobWindow& window, SetupLanes& out) {
    const auto [lo_x, hi_x] = std::minmax({in.x[0][lane], in.x[1][lane], in.x[2][lane]});
    const auto [lo_y, hi_y] = std::minmax({in.y[0][lane], in.y[1][lane], in.y[2][lane]});
    const int x0 = std::max(t.min_x, window.x0), y0 = std::max(t.min_y, window.y0);
    const int x1 = std::min(t.max_x, window.x1 - 1), y1 = std::min(t.max_y, window.y1 - 1);
    const bool single = std::int64_t{hi_x} - lo_x < kSingleJobExtent &&
                        std::int64_t{hi_y} - lo_y < kSingleJobExtent &&
                        x1 - x0 < window.max_columns && x0 <= x1 && y0 <= y1;
    const auto job = [&](std::int64_t v) { return single ? static_cast<std::int32_t>(v) : 0; };
    out.single_job[lane] = single;
    out.job_x0[lane] = job(x0 - window.x0);
    out.job_y0[lane] = job(y0 - window.y0);
    out.job_width[lane] = job(x1 - x0 + 1);
    out.job_height[lane] = job(y1 - y0 + 1);
    out.job_plane_dx[lane] = job(x0 - t.min_x);
    out.job_plane_dy[lane] = job(y0 - t.min_y);
    for (std::size_t k = 0; k < 3; ++k) {
        out.job_e[k][lane] = job(t.edge_a[k] * x0 + t.edge_b[k] * y0 + t.edge_c[k]);
        out.job_step_x[k][lane] = job(t.edge_a[k]);
        out.job_step_y[k][lane] = job(t.edge_b[k]);
    }
}

}  // namespace

void setup_lanes_scalar(const VertexLanes& in, int count, const SetupSettings& settings,
                        SetupLanes& out, const JobWindow* window) {
    for (int lane = 0; lane < count; ++lane) {
        TriangleSetup t;
        const bool small = [&] {
            for (int k = 0; k < 3; ++k)
                if (std::abs(std::int64_t{in.x[k][lane]}) >= kSetupLanesCoordinateLimit ||
                    std::abs(std::int64_t{in.y[k][lane]}) >= kSetupLanesCoordinateLimit)
                    return false;
            return true;
        }();
        out.scalar[lane] =
            !small || setup_triangle(lane_vertices(in, lane), settings, t) != SetupResult::Visible;
        if (window != nullptr) {
            if (out.scalar[lane]) {
                t = TriangleSetup{};
                t.max_x = t.max_y = -1;  // no pixels: not a single job
            }
            single_job_scalar(in, lane, t, *window, out);
        }
        if (out.scalar[lane]) continue;
        out.min_x[lane] = t.min_x;
        out.min_y[lane] = t.min_y;
        out.max_x[lane] = t.max_x;
        out.max_y[lane] = t.max_y;
        out.front_facing[lane] = t.front_facing;
        for (int k = 0; k < 3; ++k) {
            out.edge_a[k][lane] = t.edge_a[std::size_t(k)];
            out.edge_b[k][lane] = t.edge_b[std::size_t(k)];
            out.edge_c[k][lane] = t.edge_c[std::size_t(k)];
        }
        const PlaneEquation* planes[SetupLanes::kPlanes] = {&t.depth, &t.q,  &t.p1,
                                                            &t.p2,    &t.l1, &t.l2};
        for (int p = 0; p < SetupLanes::kPlanes; ++p) {
            out.plane_a[p][lane] = planes[p]->a;
            out.plane_b[p][lane] = planes[p]->b;
            out.plane_c[p][lane] = planes[p]->c;
        }
    }
}

SetupResult setup_lane_scalar(const VertexLanes& in, int lane, const SetupSettings& settings,
                              TriangleSetup& t) {
    return setup_triangle(lane_vertices(in, lane), settings, t);
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
