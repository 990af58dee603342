// Warnock's area subdivision: J. E. Warnock (1969), "A hidden-surface algorithm for computer
// generated half-tone pictures", University of Utah, TR 4-15.
//
// What: divide and conquer on the screen. A region is decided at once when it is simple:
//   - no polygon meets it (background),
//   - exactly one polygon meets it (draw that polygon clipped to the region),
//   - one polygon surrounds it and is in front of every other polygon meeting it (fill with it);
//     "in front" compares the planes' depths at the region's four corner pixel centers, which
//     suffices because depth is linear in window x, y over a plane,
//   - it is a single pixel (take the nearest polygon covering the pixel center).
// Otherwise it is cut into four quadrants, each inheriting only the polygons that met the parent.
//
// Materials' alpha (canvas.hpp): only an opaque polygon can decide a region as the surrounder (a
// Mask one may have holes, a Blend one shows what is behind it), so regions where cut-out or
// blended polygons lie in front are subdivided down to pixels. At a pixel the polygons covering
// its center are sorted nearest first down to the first that hides what is behind it there (an
// opaque one, or a Mask one whose alpha passes the test at the pixel), then drawn farthest first:
// blended fragments composited in depth order over it, as the z-buffer's blend pass does.
//
// Classification (classify_polygon) is exact: integer edge functions on the snapped vertices with
// the rasterizer's top-left rule, evaluated at the corner pixel centers of the region, so
// "surrounding" means "covers every pixel center" and "disjoint" means "covers none".
//
// Cost: output-sensitive. Regions of constant visibility end high in the quadtree; every visible
// edge and every line where surfaces interpenetrate is followed down to single pixels, each
// examining the polygons that survived to it. Roughly O(p * n_local * log(resolution)) where p is
// the number of pixels on visible edges. No depth buffer is needed and hidden surfaces are never
// shaded, unlike the painter's algorithm. Random overlapping triangles make that p nearly every
// pixel, each with many polygons (20,000 random triangles at 1920x1080: 80 s), so
// classifications have a budget (RenderLimits::max_warnock_classifications).
//
// When to use: memory-starved settings (no per-pixel depth), images with large uniform regions,
// or as an anti-aliasing scheme (keep subdividing below a pixel). It is the ancestor of
// hierarchical z-buffers and tiled coverage (region culling against coarse tiles).
#include <zraster/error.hpp>

#include <algorithm>
#include <cmath>

#include "visibility/canvas.hpp"
#include "visibility/frame_context.hpp"

namespace zraster {
namespace {

// A polygon's edges with the inside on their positive side (setup_triangle's convention).
struct Edges {
    struct Edge {
        std::int64_t ax, ay, dx, dy;
        bool top_left;
    };
    std::vector<Edge> edges;
    std::int64_t x_min = 0, x_max = 0, y_min = 0, y_max = 0;
};

Edges make_edges(const ScreenPolygon& polygon) {
    Edges e;
    const auto& v = polygon.vertices;
    const std::size_t n = v.size();
    const bool reversed = visibility_detail::snapped_area2(v) < 0;
    e.x_min = e.x_max = v[0].snapped[0];
    e.y_min = e.y_max = v[0].snapped[1];
    for (std::size_t i = 0; i < n; ++i) {
        const auto& a = v[reversed ? (i + 1) % n : i].snapped;
        const auto& b = v[reversed ? i : (i + 1) % n].snapped;
        const std::int64_t dx = b[0] - a[0], dy = b[1] - a[1];
        // Top edge: horizontal with the inside below it; left edge: going up (y down).
        e.edges.push_back({a[0], a[1], dx, dy, dy < 0 || (dy == 0 && dx > 0)});
        e.x_min = std::min(e.x_min, v[i].snapped[0]);
        e.x_max = std::max(e.x_max, v[i].snapped[0]);
        e.y_min = std::min(e.y_min, v[i].snapped[1]);
        e.y_max = std::max(e.y_max, v[i].snapped[1]);
    }
    return e;
}

RegionRelation classify(const Edges& e, const PixelRegion& r) {
    // Corner pixel centers in fixed point.
    const std::int64_t half = kSubpixelScale / 2;
    const std::int64_t cx[2] = {r.x0 * kSubpixelScale + half, (r.x1 - 1) * kSubpixelScale + half};
    const std::int64_t cy[2] = {r.y0 * kSubpixelScale + half, (r.y1 - 1) * kSubpixelScale + half};
    if (e.x_max < cx[0] || e.x_min > cx[1] || e.y_max < cy[0] || e.y_min > cy[1])
        return RegionRelation::Disjoint;
    bool covers_all = true;
    for (const Edges::Edge& edge : e.edges) {
        int outside = 0;
        for (int j = 0; j < 4; ++j) {
            const std::int64_t x = cx[j & 1], y = cy[j >> 1];
            const std::int64_t f = edge.dx * (y - edge.ay) - edge.dy * (x - edge.ax);
            outside += f < 0;
            if (!(f > 0 || (f == 0 && edge.top_left))) covers_all = false;
        }
        // The whole center rectangle strictly outside one edge: disjoint (separating axis).
        if (outside == 4) return RegionRelation::Disjoint;
    }
    if (covers_all) return RegionRelation::Surrounding;
    if (e.x_min >= r.x0 * kSubpixelScale && e.x_max <= r.x1 * kSubpixelScale &&
        e.y_min >= r.y0 * kSubpixelScale && e.y_max <= r.y1 * kSubpixelScale)
        return RegionRelation::Contained;
    return RegionRelation::Intersecting;
}

using visibility_detail::depth_plane;
using visibility_detail::DepthPlane;

struct Task {
    PixelRegion region;
    std::size_t level;
    std::vector<std::uint32_t> active;  // polygons that met the parent region
};

}  // namespace

RegionRelation classify_polygon(const ScreenPolygon& polygon, const PixelRegion& region) {
    return classify(make_edges(polygon), region);
}

WarnockResult warnock_render(std::span<const ScreenPolygon> polygons, const RenderOptions& options,
                             const Camera& camera, const WarnockObserver* observer,
                             const Scene* shade_from) {
    auto observe = [observer](const PixelRegion& r, std::size_t level, WarnockRegionOutcome o) {
        if (observer != nullptr && observer->region) observer->region(r, level, o);
    };
    visibility_detail::Canvas canvas(options, camera, shade_from);
    const std::size_t n = polygons.size();
    std::vector<Edges> edges(n);
    std::vector<DepthPlane> planes(n);
    std::vector<std::vector<TriangleSetup>> fans(n);
    for (std::size_t i = 0; i < n; ++i) {
        edges[i] = make_edges(polygons[i]);
        planes[i] = depth_plane(polygons[i]);
        canvas.prepare(polygons[i], fans[i]);
    }

    WarnockResult result;
    WarnockStats& stats = result.stats;
    auto draw = [&](std::uint32_t i, const PixelRegion& r) {
        canvas.draw(polygons[i], fans[i], r.x0, r.y0, r.x1, r.y1);
    };
    // Nearer at (x, y): smaller depth, ties to the earlier polygon (the z-buffer's LESS test keeps
    // the first one drawn).
    auto nearer = [&](std::uint32_t i, std::uint32_t j, double x, double y) {
        const double zi = planes[i].at(x, y), zj = planes[j].at(x, y);
        return zi < zj || (zi == zj && i < j);
    };

    std::vector<Task> tasks;
    {
        Task root{{0, 0, options.width, options.height}, 0, {}};
        root.active.resize(n);
        for (std::uint32_t i = 0; i < n; ++i) root.active[i] = i;
        tasks.push_back(std::move(root));
    }
    std::vector<std::uint32_t> kept, covering;
    std::vector<RegionRelation> relation;
    const std::uint64_t budget =
        warnock_classification_budget(options.limits, n, options.width, options.height);
    std::uint64_t classified = 0, next_report = 0;
    // Pixels of the leaves done (the progress reported).
    std::uint64_t area_done = 0;
    const double area = double(options.width) * double(options.height);
    while (!tasks.empty()) {
        Task task = std::move(tasks.back());
        tasks.pop_back();
        const PixelRegion& r = task.region;
        if (stats.regions_per_level.size() <= task.level) {
            stats.regions_per_level.resize(task.level + 1, 0);
            stats.subdivisions_per_level.resize(task.level + 1, 0);
        }
        ++stats.regions_per_level[task.level];

        kept.clear();
        relation.clear();
        classified += task.active.size();
        if (classified > budget)
            throw LimitExceeded("", "max_warnock_classifications",
                                "Warnock's algorithm: more than " + std::to_string(budget) +
                                    " polygon-region classifications for " + std::to_string(n) +
                                    " polygons at " + std::to_string(options.width) + "x" +
                                    std::to_string(options.height) +
                                    " (the budget): too many polygons overlap in too many regions");
        if (options.progress != nullptr && classified >= next_report) {
            next_report = classified + (1 << 16);
            options.progress->report("Warnock's algorithm", double(area_done) / area);
        }
        const std::uint64_t region_area = std::uint64_t(r.x1 - r.x0) * std::uint64_t(r.y1 - r.y0);
        for (const std::uint32_t i : task.active) {
            const RegionRelation rel = classify(edges[i], r);
            ++stats.classifications[static_cast<std::size_t>(rel)];
            if (rel == RegionRelation::Disjoint) continue;
            kept.push_back(i);
            relation.push_back(rel);
        }
        if (kept.empty()) {
            ++stats.empty_leaves;
            observe(r, task.level, WarnockRegionOutcome::Empty);
            area_done += region_area;
            continue;
        }
        if (kept.size() == 1) {
            draw(kept[0], r);
            ++stats.single_leaves;
            observe(r, task.level, WarnockRegionOutcome::Single);
            area_done += region_area;
            continue;
        }

        // A surrounding polygon in front of all others. Only the surrounder nearest at the
        // region's center can be: one in front of it at all four corners would be in front of it
        // at the center too (depth is linear).
        const double x0 = r.x0 + 0.5, x1 = r.x1 - 0.5, y0 = r.y0 + 0.5, y1 = r.y1 - 0.5;
        const double xc = 0.5 * (x0 + x1), yc = 0.5 * (y0 + y1);
        std::int64_t front = -1;
        for (std::size_t k = 0; k < kept.size(); ++k)
            if (relation[k] == RegionRelation::Surrounding &&
                (front < 0 || nearer(kept[k], static_cast<std::uint32_t>(front), xc, yc)))
                front = kept[k];
        // (A cut-out or blended polygon does not hide the region behind it.)
        if (front >= 0 &&
            canvas.alpha_mode(polygons[static_cast<std::size_t>(front)]) != AlphaMode::Opaque)
            front = -1;
        if (front >= 0) {
            const auto s = static_cast<std::uint32_t>(front);
            bool in_front = true;
            for (const std::uint32_t j : kept) {
                if (j == s) continue;
                if (!(nearer(s, j, x0, y0) && nearer(s, j, x1, y0) && nearer(s, j, x0, y1) &&
                      nearer(s, j, x1, y1))) {
                    in_front = false;
                    break;
                }
            }
            if (in_front) {
                draw(s, r);
                ++stats.surrounded_leaves;
                observe(r, task.level, WarnockRegionOutcome::Surrounded);
                area_done += region_area;
                continue;
            }
        }

        if (r.x1 - r.x0 == 1 && r.y1 - r.y0 == 1) {
            // A pixel: the polygons surrounding it are those covering its center. Nearest first
            // down to the first that hides the rest there, then drawn farthest first.
            covering.clear();
            for (std::size_t k = 0; k < kept.size(); ++k)
                if (relation[k] == RegionRelation::Surrounding) covering.push_back(kept[k]);
            std::sort(covering.begin(), covering.end(),
                      [&](std::uint32_t i, std::uint32_t j) { return nearer(i, j, xc, yc); });
            std::size_t shown = 0;
            while (shown < covering.size() &&
                   !canvas.hides_at(polygons[covering[shown]], r.x0, r.y0))
                ++shown;
            if (shown < covering.size()) ++shown;
            for (std::size_t k = shown; k-- > 0;) draw(covering[k], r);
            ++stats.pixel_leaves;
            observe(r, task.level, WarnockRegionOutcome::Pixel);
            area_done += region_area;
            continue;
        }

        ++stats.subdivisions_per_level[task.level];
        observe(r, task.level, WarnockRegionOutcome::Subdivided);
        const int xm = r.x0 + (r.x1 - r.x0) / 2, ym = r.y0 + (r.y1 - r.y0) / 2;
        const PixelRegion quadrants[4] = {
            {r.x0, r.y0, xm, ym}, {xm, r.y0, r.x1, ym}, {r.x0, ym, xm, r.y1}, {xm, ym, r.x1, r.y1}};
        for (const PixelRegion& q : quadrants)
            if (q.x1 > q.x0 && q.y1 > q.y0) tasks.push_back({q, task.level + 1, kept});
    }
    result.targets = canvas.take();
    canvas.count_fragments(result.fragments);
    return result;
}

}  // namespace zraster
