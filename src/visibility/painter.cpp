// The painter's algorithm with the overlap tests of Newell, Newell & Sancha (1972), "A solution to
// the hidden surface problem" (Proc. ACM National Conference).
//
// What: polygons are sorted by their farthest depth and drawn back to front, later ones painting
// over earlier ones. Sorting alone is wrong whenever depth ranges overlap, so before the farthest
// polygon P is drawn it is compared with every Q whose depth range overlaps P's; P may go first
// if any of these tests, cheapest first, shows it cannot hide part of Q:
//   1. depth extents do not overlap,  2. x extents do not,  3. y extents do not,
//   4. P lies entirely behind Q's plane,  5. Q lies entirely in front of P's plane,
//   6. the projections do not overlap (exact convex-polygon test on the snapped vertices).
// If all fail and Q can go first instead (Q behind P's plane, or P in front of Q's plane), Q is
// moved ahead of P and marked. A marked Q that must move again closes a cycle (cyclic overlap):
// one polygon of the cycle is split by another's plane. If Q cannot go first either, P and Q
// interpenetrate and P is split by Q's plane. Pieces go back into the depth-sorted list.
//
// Cost: O(n log n) for the sort plus one comparison per pair of polygons whose depth ranges
// overlap (O(n^2) in the worst case, near-linear for scenes of small, depth-separated polygons);
// each split adds a polygon. Memory O(n + splits). Random, interpenetrating polygons make that
// worst case real (2,000 random triangles: 3e8 comparisons, a minute), so comparisons have a
// budget (PainterOptions::max_comparisons, RenderLimits::max_painter_comparisons).
//
// When to use: scenes of a few thousand polygons without a depth buffer (vector output such as
// PostScript/SVG/PDF, plotters), or for transparency, which needs a back-to-front order anyway.
// For a static scene seen from many viewpoints a BSP tree gives the order more cheaply per frame.
//
// Plane-side tests run in world space (double, positions as the renderer computes them) on the
// viewer-oriented planes of ScreenPolygon; overlap tests run on the snapped window coordinates,
// the exact coordinates coverage is decided on, so "the projections do not overlap" really means
// "no pixel center is covered by both".
#include <zraster/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>

#include "visibility/frame_context.hpp"

namespace zraster {
namespace {

using visibility_detail::set_window_xy;
using visibility_detail::snapped_area2;

struct Item {
    ScreenPolygon polygon;
    double z_min = 0, z_max = 0;
    std::int64_t x_min = 0, x_max = 0, y_min = 0, y_max = 0;
    int orientation = 1;  // sign of snapped_area2: which side of each edge is inside
    bool marked = false;  // moved ahead of another polygon once
};

Item make_item(ScreenPolygon polygon) {
    Item item;
    const auto& v = polygon.vertices;
    item.z_min = item.z_max = v[0].window.z;
    item.x_min = item.x_max = v[0].snapped[0];
    item.y_min = item.y_max = v[0].snapped[1];
    for (const PolygonVertex& p : v) {
        item.z_min = std::min(item.z_min, p.window.z);
        item.z_max = std::max(item.z_max, p.window.z);
        item.x_min = std::min(item.x_min, p.snapped[0]);
        item.x_max = std::max(item.x_max, p.snapped[0]);
        item.y_min = std::min(item.y_min, p.snapped[1]);
        item.y_max = std::max(item.y_max, p.snapped[1]);
    }
    item.orientation = snapped_area2(v) < 0 ? -1 : 1;
    item.polygon = std::move(polygon);
    return item;
}

// Every vertex of `polygon` on the non-positive side of `plane` (behind it, seen from the viewer).
bool all_behind(const ScreenPolygon& polygon, const glm::dvec4& plane, double eps) {
    for (const PolygonVertex& v : polygon.vertices)
        if (visibility_detail::plane_distance(plane, v.world) > eps) return false;
    return true;
}

bool all_in_front(const ScreenPolygon& polygon, const glm::dvec4& plane, double eps) {
    for (const PolygonVertex& v : polygon.vertices)
        if (visibility_detail::plane_distance(plane, v.world) < -eps) return false;
    return true;
}

// True when some edge of `a` has every vertex of `b` on its outer side or on it.
bool has_separating_edge(const Item& a, const Item& b) {
    const auto& va = a.polygon.vertices;
    const std::size_t n = va.size();
    for (std::size_t i = 0; i < n; ++i) {
        const auto& p = va[i].snapped;
        const auto& q = va[(i + 1) % n].snapped;
        const std::int64_t dx = q[0] - p[0], dy = q[1] - p[1];
        bool separates = true;
        for (const PolygonVertex& v : b.polygon.vertices) {
            const std::int64_t e = dx * (v.snapped[1] - p[1]) - dy * (v.snapped[0] - p[0]);
            if (e * a.orientation > 0) {
                separates = false;
                break;
            }
        }
        if (separates) return true;
    }
    return false;
}

// Exact overlap of the interiors of two convex polygons (separating axis theorem: two convex
// polygons are disjoint iff a line through an edge of one of them separates them). Touching
// polygons do not overlap: the top-left rule gives a pixel center on a shared line to one side.
bool projections_overlap(const Item& a, const Item& b) {
    return !has_separating_edge(a, b) && !has_separating_edge(b, a);
}

// Splits `polygon` by `plane`; false when it does not straddle the plane (beyond eps). New
// vertices are interpolated from the front vertex towards the back one, so polygons sharing an
// edge get bit-identical new vertices on it.
bool split_polygon(const ScreenPolygon& polygon, const glm::dvec4& plane, double eps,
                   const Viewport& viewport, ScreenPolygon& front, ScreenPolygon& back) {
    front = polygon;
    back = polygon;
    return visibility_detail::split_by_plane(
        polygon.vertices, plane, eps, front.vertices, back.vertices,
        [&](const PolygonVertex& f, const PolygonVertex& b, double t, PolygonVertex& c) {
            c.world = f.world + t * (b.world - f.world);
            const glm::dvec4 cf(f.clip), cb(b.clip);
            c.clip = glm::vec4(cf + t * (cb - cf));
            const glm::dvec3 wf(f.weights), wb(b.weights);
            c.weights = glm::vec3(wf + t * (wb - wf));
            // A convex combination of two vertices inside the guard band is inside it too.
            if (!set_window_xy(c, viewport)) return false;
            // Window depth is affine in z/w: the w-weighted mean of the endpoints' depths.
            const double w_f = (1.0 - t) * cf.w, w_b = t * cb.w;
            c.window.z = (w_f * f.window.z + w_b * b.window.z) / (w_f + w_b);
            return true;
        });
}

bool usable(const ScreenPolygon& p) {
    return p.vertices.size() >= 3 && snapped_area2(p.vertices) != 0;
}

class Painter {
  public:
    Painter(std::vector<ScreenPolygon> polygons, const Viewport& viewport,
            const PainterOptions& options)
        : viewport_(viewport) {
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
        for (const ScreenPolygon& p : polygons)
            for (const PolygonVertex& v : p.vertices) {
                lo = glm::min(lo, v.world);
                hi = glm::max(hi, v.world);
            }
        const double extent = polygons.empty() ? 0.0 : glm::length(hi - lo);
        eps_ = options.plane_epsilon * (std::isfinite(extent) ? extent : 0.0);
        max_splits_ = options.max_splits ? options.max_splits : 16 * polygons.size() + 1024;
        input_polygons_ = polygons.size();
        max_comparisons_ = options.max_comparisons
                               ? options.max_comparisons
                               : painter_comparison_budget(RenderLimits{}, polygons.size());
        progress_ = options.progress;
        observer_ = options.observer;
        items_.reserve(polygons.size());
        for (ScreenPolygon& p : polygons) add(std::move(p));
    }

    PainterResult run() {
        PainterResult result;
        while (!stack_.empty() || !sorted_.empty()) {
            const std::uint32_t p = stack_.empty() ? sorted_.begin()->second : stack_.back();
            if (settle(p)) {
                output(p, result.order);
            }
            if (progress_ != nullptr && stats_.comparisons >= next_report_) {
                next_report_ = stats_.comparisons + kReportEvery;
                // Polygons drawn of those known (split pieces join as they are made), or the
                // comparison budget used where that is further: a first polygon overlapping
                // a million others draws nothing for a long time, and the run ends at the
                // budget at the latest.
                const double drawn = double(result.order.size()) / double(items_.size());
                const double budget = max_comparisons_ > 0
                                          ? double(stats_.comparisons) / double(max_comparisons_)
                                          : 0.0;
                reported_ = std::max({reported_, drawn, std::min(budget, 1.0)});
                progress_->report("painter's algorithm", reported_);
            }
        }
        result.stats = stats_;
        return result;
    }

  private:
    enum class Verdict { PFirst, QFirst, Interpenetrate };

    std::uint32_t add(ScreenPolygon polygon) {
        const auto index = static_cast<std::uint32_t>(items_.size());
        items_.push_back(make_item(std::move(polygon)));
        sorted_.emplace(-items_.back().z_max, index);
        return index;
    }

    Verdict compare(std::uint32_t p_index, std::uint32_t q_index) {
        const Item& p = items_[p_index];
        const Item& q = items_[q_index];
        if (++stats_.comparisons > max_comparisons_) refuse();
        auto resolved = [&](int test) {
            ++stats_.resolved_by[static_cast<std::size_t>(test)];
            return Verdict::PFirst;
        };
        if (p.z_min >= q.z_max) return resolved(0);
        if (p.x_max <= q.x_min || q.x_max <= p.x_min) return resolved(1);
        if (p.y_max <= q.y_min || q.y_max <= p.y_min) return resolved(2);
        if (all_behind(p.polygon, q.polygon.plane, eps_)) return resolved(3);
        if (all_in_front(q.polygon, p.polygon.plane, eps_)) return resolved(4);
        if (!projections_overlap(p, q)) return resolved(5);
        // P may hide part of Q. Can Q go first?
        if (all_behind(q.polygon, p.polygon.plane, eps_) ||
            all_in_front(p.polygon, q.polygon.plane, eps_))
            return Verdict::QFirst;
        return Verdict::Interpenetrate;
    }

    // Compares P with every polygon that may overlap it in depth; true when P can be drawn now.
    // Otherwise the lists were changed (a move or a split) and the caller starts over.
    bool settle(std::uint32_t p) {
        const double p_z_min = items_[p].z_min;
        // The moved polygons on the stack are not in depth order: all of them are compared.
        for (std::size_t s = 0; s + 1 < stack_.size(); ++s)
            if (!act(p, stack_[s], compare(p, stack_[s]))) return false;
        for (auto it = sorted_.begin(); it != sorted_.end(); ++it) {
            const std::uint32_t q = it->second;
            if (q == p) continue;
            const Verdict verdict = compare(p, q);
            // The rest of the list is no deeper than Q: none of it reaches P's depth range.
            if (items_[q].z_max <= p_z_min) break;
            if (!act(p, q, verdict)) return false;
        }
        return true;
    }

    // Applies a verdict; false when the lists changed.
    bool act(std::uint32_t p, std::uint32_t q, Verdict verdict) {
        switch (verdict) {
            case Verdict::PFirst:
                return true;
            case Verdict::QFirst:
                if (!items_[q].marked) {
                    sorted_.erase({-items_[q].z_max, q});
                    items_[q].marked = true;
                    stack_.push_back(q);
                    ++stats_.swaps;
                    if (observer_ && observer_->swapped)
                        observer_->swapped(items_[q].polygon, items_[p].polygon);
                    return false;
                }
                return !resolve_cycle(p, q);
            case Verdict::Interpenetrate:
                // Failing tests 4 and "P in front of Q's plane" means P has vertices on both
                // sides of Q's plane: the split always exists.
                if (stats_.splits < max_splits_ && split(p, items_[q].polygon.plane)) {
                    ++stats_.splits;
                    return false;
                }
                ++stats_.unresolved;
                return true;
        }
        return true;
    }

    // Q, already moved once, must move ahead of P again: the polygons from Q up to P on the stack
    // form a cycle. Some polygon of a cycle crosses the plane of another (otherwise a BSP tree
    // without splits would order them, and there would be no cycle); split the first such one,
    // preferring Q by P's plane and P by Q's plane. All marks are then cleared: the old moves
    // were decided against a polygon that no longer exists.
    bool resolve_cycle(std::uint32_t p, std::uint32_t q) {
        if (stats_.splits >= max_splits_) {
            ++stats_.unresolved;
            return false;
        }
        std::vector<std::uint32_t> cycle;
        const auto q_at = std::find(stack_.begin(), stack_.end(), q);
        cycle.assign(q_at, stack_.end());
        std::vector<std::pair<std::uint32_t, std::uint32_t>> tries = {{q, p}, {p, q}};
        for (const std::uint32_t a : cycle)
            for (const std::uint32_t b : cycle)
                if (a != b) tries.emplace_back(a, b);
        for (const auto& [victim, by] : tries) {
            ScreenPolygon front, back;
            if (!split_polygon(items_[victim].polygon, items_[by].polygon.plane, eps_, viewport_,
                               front, back))
                continue;
            if (observer_ && observer_->split)
                observer_->split(items_[victim].polygon, items_[by].polygon.plane);
            // Unmark and return every moved polygon to the depth-sorted list.
            for (const std::uint32_t s : stack_) {
                items_[s].marked = false;
                if (s != victim) sorted_.emplace(-items_[s].z_max, s);
            }
            stack_.clear();
            sorted_.erase({-items_[victim].z_max, victim});
            if (usable(front)) add(std::move(front));
            if (usable(back)) add(std::move(back));
            ++stats_.splits;
            ++stats_.cycle_splits;
            return true;
        }
        ++stats_.unresolved;  // no straddling pair: rounding; draw in the current order
        return false;
    }

    // Replaces P (the polygon about to be drawn) by its pieces on either side of `plane`.
    bool split(std::uint32_t p, const glm::dvec4& plane) {
        ScreenPolygon front, back;
        if (!split_polygon(items_[p].polygon, plane, eps_, viewport_, front, back)) return false;
        if (observer_ && observer_->split) observer_->split(items_[p].polygon, plane);
        remove(p);
        if (usable(front)) add(std::move(front));
        if (usable(back)) add(std::move(back));
        return true;
    }

    void remove(std::uint32_t p) {
        if (!stack_.empty() && stack_.back() == p)
            stack_.pop_back();
        else
            sorted_.erase({-items_[p].z_max, p});
    }

    [[noreturn]] void refuse() const {
        throw LimitExceeded(
            "", "max_painter_comparisons",
            "painter's algorithm: more than " + std::to_string(max_comparisons_) +
                " polygon comparisons for " + std::to_string(input_polygons_) +
                " polygons (the budget; " + std::to_string(stats_.splits) +
                " splits so far): the input has too many intersecting or cyclically overlapping "
                "polygons for a depth sort");
    }

    void output(std::uint32_t p, std::vector<ScreenPolygon>& order) {
        remove(p);
        order.push_back(std::move(items_[p].polygon));
    }

    static constexpr std::uint64_t kReportEvery = 1 << 16;  // comparisons between reports

    Viewport viewport_;
    double eps_ = 0;
    std::size_t max_splits_ = 0;
    std::size_t input_polygons_ = 0;
    std::uint64_t max_comparisons_ = 0;
    ProgressReporter* progress_ = nullptr;
    const PainterObserver* observer_ = nullptr;
    std::uint64_t next_report_ = 0;
    double reported_ = 0.0;
    std::vector<Item> items_;
    // Unmarked polygons, farthest (largest z_max) first; ties in submission order.
    std::set<std::pair<double, std::uint32_t>> sorted_;
    // Moved polygons, the last one moved on top: drawn before everything below them.
    std::vector<std::uint32_t> stack_;
    PainterStats stats_;
};

}  // namespace

PainterResult painter_sort(std::vector<ScreenPolygon> polygons, const Viewport& viewport,
                           const PainterOptions& options) {
    return Painter(std::move(polygons), viewport, options).run();
}

std::vector<ScreenPolygon> sort_by_farthest_depth(std::vector<ScreenPolygon> polygons) {
    std::vector<std::pair<double, std::size_t>> keys(polygons.size());
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        double z = -std::numeric_limits<double>::infinity();
        for (const PolygonVertex& v : polygons[i].vertices) z = std::max(z, v.window.z);
        keys[i] = {-z, i};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<ScreenPolygon> out;
    out.reserve(polygons.size());
    for (const auto& key : keys) out.push_back(std::move(polygons[key.second]));
    return out;
}

}  // namespace zraster
