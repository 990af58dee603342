// The cluster test of cluster_cull.cpp, a cluster per double lane: the same operations in the
// same order as cluster_is_culled() (no fused multiply-adds), so that every lane's verdict is the
// scalar one bit for bit; a test compares them on every instruction set. All conditions are
// evaluated in every lane and combined at the end (the scalar version returns early instead:
// the same verdict). Highway's foreach_target re-includes this file once per instruction set;
// the scalar reference and the dispatcher are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/cluster_kernel.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include "render/cluster_constants.hpp"
#include "render/cluster_cull.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void ClustersCulled(const ClusterView& v, const ClusterArrays& c, std::size_t first,
                    std::size_t count, std::uint8_t* culled) {
    if (!v.enabled) {
        for (std::size_t i = 0; i < count; ++i) culled[i] = 0;
        return;
    }
    const hn::ScalableTag<double> d;
    const std::size_t lanes = hn::Lanes(d);
    using V = hn::Vec<decltype(d)>;
    const auto set = [&](double x) { return hn::Set(d, x); };
    const V zero = hn::Zero(d), one = set(1.0);
    // (a . b) over three components as glm computes it: (ax bx + ay by) + az bz.
    const auto dot3 = [](V ax, V ay, V az, V bx, V by, V bz) {
        return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)), hn::Mul(az, bz));
    };
    // And over four: (ax bx + ay by) + (az bz + aw bw).
    const auto dot4 = [](V ax, V ay, V az, V aw, V bx, V by, V bz, V bw) {
        return hn::Add(hn::Add(hn::Mul(ax, bx), hn::Mul(ay, by)),
                       hn::Add(hn::Mul(az, bz), hn::Mul(aw, bw)));
    };
    std::size_t i = 0;
    for (; i + lanes <= count; i += lanes) {
        const std::size_t at = first + i;
        const auto load = [&](const std::vector<double>& field) {
            return hn::LoadU(d, field.data() + at);
        };
        const V cx = load(c.center[0]), cy = load(c.center[1]), cz = load(c.center[2]);
        V axis[3][3];
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j) axis[k][j] = load(c.axis[k][j]);
        const V hx = load(c.half[0]), hy = load(c.half[1]), hz = load(c.half[2]);
        const V mx = load(c.max_abs[0]), my = load(c.max_abs[1]), mz = load(c.max_abs[2]);
        const V cos_angle = load(c.cos_angle), sin_angle = load(c.sin_angle);
        const V min_area = load(c.min_double_area), max_edge = load(c.max_edge);
        auto ok = hn::Gt(min_area, zero);

        const V det = set(v.det);
        const V gx = hn::Add(hn::Mul(det, cx), set(v.adj_b.x));
        const V gy = hn::Add(hn::Mul(det, cy), set(v.adj_b.y));
        const V gz = hn::Add(hn::Mul(det, cz), set(v.adj_b.z));
        const V along =
            hn::Mul(set(v.culled_sign), dot3(axis[0][0], axis[0][1], axis[0][2], gx, gy, gz));
        ok = hn::And(ok, hn::Gt(along, zero));
        const V across =
            hn::Sqrt(hn::Max(zero, hn::Sub(dot3(gx, gy, gz, gx, gy, gz), hn::Mul(along, along))));
        const V spread = hn::Mul(set(v.abs_det), hn::Add(hx, hn::Mul(sin_angle, hn::Add(hy, hz))));
        const V margin =
            hn::Sub(hn::Sub(hn::Sub(hn::Mul(cos_angle, along), hn::Mul(sin_angle, across)), spread),
                    hn::Mul(set(kMarginSlack), hn::Add(hn::Add(along, across), spread)));
        ok = hn::And(ok, hn::Gt(margin, zero));

        const V two = set(2.0);
        const V edge_x = hn::Min(hn::Mul(two, hx), max_edge);
        const V edge_y = hn::Min(hn::Mul(two, hy), max_edge);
        const V edge_z = hn::Min(hn::Mul(two, hz), max_edge);
        struct Row {
            V value, reach, error, edge_change;
        };
        const auto row_bounds = [&](int r) {
            const glm::dvec4& row = v.row[r];
            const glm::dvec4& abs_row = v.abs_row[r];
            const V rx = set(row.x), ry = set(row.y), rz = set(row.z);
            V on_axes[3];
            for (int k = 0; k < 3; ++k)
                on_axes[k] = hn::Abs(dot3(rx, ry, rz, axis[k][0], axis[k][1], axis[k][2]));
            const V error =
                hn::Mul(set(kClipError), dot4(set(abs_row.x), set(abs_row.y), set(abs_row.z),
                                              set(abs_row.w), mx, my, mz, one));
            return Row{dot4(rx, ry, rz, set(row.w), cx, cy, cz, one),
                       hn::Add(dot3(on_axes[0], on_axes[1], on_axes[2], hx, hy, hz), error), error,
                       hn::Add(dot3(on_axes[0], on_axes[1], on_axes[2], edge_x, edge_y, edge_z),
                               hn::Mul(set(kSlack * v.row_length[r]), max_edge))};
        };
        const Row bx = row_bounds(0), by = row_bounds(1), bz = row_bounds(2), bw = row_bounds(3);
        const V w_lo = hn::Sub(bw.value, bw.reach), w_hi = hn::Add(bw.value, bw.reach);
        ok = hn::And(ok, hn::And(hn::Gt(w_lo, zero), hn::Lt(w_hi, set(1e30))));
        const V x_hi = hn::Add(hn::Abs(bx.value), bx.reach);
        const V y_hi = hn::Add(hn::Abs(by.value), by.reach);
        const V shrink = set(kShrink);
        ok = hn::And(ok, hn::Le(x_hi, hn::Mul(hn::Mul(set(v.guard_x), w_lo), shrink)));
        ok = hn::And(ok, hn::Le(y_hi, hn::Mul(hn::Mul(set(v.guard_y), w_lo), shrink)));
        const V z_lo = hn::Sub(bz.value, bz.reach);
        const V near_distance = v.zero_to_one ? z_lo : hn::Add(z_lo, w_lo);
        ok = hn::And(ok, hn::Gt(near_distance, zero));
        ok = hn::And(ok, hn::Gt(hn::Sub(w_lo, hn::Add(bz.value, bz.reach)), zero));

        const V half_width = set(v.half_width), half_height = set(v.half_height);
        const V inv_w = hn::Div(one, w_lo);
        const V ndc_x = hn::Mul(x_hi, inv_w), ndc_y = hn::Mul(y_hi, inv_w);
        const V double_error = hn::Mul(hn::Mul(set(0x1p-48), hn::Add(hn::Add(ndc_x, ndc_y), two)),
                                       set(v.half_width + v.half_height));
        const V delta_x =
            hn::Mul(hn::Mul(half_width, hn::Add(bx.error, hn::Mul(ndc_x, bw.error))), inv_w);
        const V delta_y =
            hn::Mul(hn::Mul(half_height, hn::Add(by.error, hn::Mul(ndc_y, bw.error))), inv_w);
        const V delta = hn::Add(hn::Add(hn::Max(delta_x, delta_y), set(1.0 / 512.0)), double_error);
        const V extent_x = hn::Mul(
            hn::Mul(half_width, hn::Add(hn::Mul(ndc_x, bw.edge_change), bx.edge_change)), inv_w);
        const V extent_y = hn::Mul(
            hn::Mul(half_height, hn::Add(hn::Mul(ndc_y, bw.edge_change), by.edge_change)), inv_w);
        const V area = hn::Div(hn::Mul(hn::Mul(set(v.area_scale), min_area), margin),
                               hn::Mul(hn::Mul(w_hi, w_hi), w_hi));
        const V area_error = hn::Add(hn::Mul(hn::Mul(set(4.0), delta), hn::Add(extent_x, extent_y)),
                                     hn::Mul(hn::Mul(set(8.0), delta), delta));
        ok = hn::And(ok, hn::Gt(area, hn::Mul(two, area_error)));
        // 0/1 per lane, stored as bytes.
        const hn::Rebind<std::int32_t, decltype(d)> di;
        const hn::Rebind<std::uint8_t, decltype(d)> d8;
        hn::StoreU(hn::DemoteTo(d8, hn::DemoteTo(di, hn::IfThenElseZero(ok, one))), d8, culled + i);
    }
    if (i < count) clusters_culled_scalar(v, c, first + i, count - i, culled + i);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(ClustersCulled);

void clusters_culled(const ClusterView& view, const ClusterArrays& clusters, std::size_t first,
                     std::size_t count, std::uint8_t* culled) {
    HWY_DYNAMIC_DISPATCH(ClustersCulled)(view, clusters, first, count, culled);
}

void clusters_culled_scalar(const ClusterView& view, const ClusterArrays& clusters,
                            std::size_t first, std::size_t count, std::uint8_t* culled) {
    for (std::size_t i = 0; i < count; ++i)
        culled[i] = cluster_is_culled(view, clusters[first + i]) ? 1 : 0;
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
