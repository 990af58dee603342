// The A-buffer: L. Carpenter (1984), "The A-buffer, an antialiased hidden surface method",
// SIGGRAPH '84 (Computer Graphics 18(3)).
//
// What: every polygon of project_scene (slivers between pixel centers kept) leaves, in every
// pixel where it covers at least one subsample, a fragment (depth, subsample mask, polygon: what
// shading needs). Its alpha (fragment_alphas.hpp: the material's, textures' alpha sampled where
// the fragment is shaded) is taken when the pixel is resolved; fragments of alpha 0 (cut out, or
// fully transparent) are dropped there. Fragments are kept in per-pixel linked lists in one pool
// (Carpenter's fragment lists); resolving a pixel sorts its list by depth and composites, for each
// subsample, the fragments covering it front to back (an opaque one ends the sample), over the
// background, then averages the samples. A fragment is shaded (surface_shader.hpp: render()'s
// shading, at the pixel center when it covers every sample, else at the centroid of its samples)
// the first time it contributes to a sample, so fragments hidden everywhere are never shaded.
//
// Differences from the paper, deliberately: masks are exact point samples on a regular n x n grid
// (1, 2, 4 or 8 per side) decided with the rasterizer's integer edge functions and top-left rule
// rather than area-sampled bit patterns, so polygons sharing an edge partition the samples; each
// fragment has one depth, the polygon's depth plane at the pixel center (Carpenter's zmin/zmax
// blending of interpenetrating fragments is not done: where two surfaces cross inside a pixel, the
// whole pixel takes the order at its center; render_multisampled resolves such pixels per sample).
// Ordering ties are broken by the fragments' content (opacity, mask, shaded color) before ids, so
// neither submission order nor instance numbering decides.
//
// Cost: masks O(touched pixels x (edges + samples)) per polygon; resolve O(f log f + f x samples)
// per pixel with f fragments, plus one shading per contributing fragment. Memory: 24 bytes per
// fragment (allocated 64 Ki at a time) plus 4 per pixel, bounded by ABufferOptions::max_fragments
// (LimitExceeded beyond it, checked before each fragment is added; an allocation the system
// refuses below it is an InputError naming the budget).
//
// When to use: transparent surfaces submitted in any order (order-independent transparency), and
// antialiased edges with one shading per fragment instead of per subsample (compare with
// render_supersampled, src/visibility/supersample.cpp).
#include <zraster/abuffer.hpp>
#include <zraster/error.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <tuple>

#include "render/thread_arena.hpp"
#include "visibility/fragment_alphas.hpp"
#include "visibility/frame_context.hpp"
#include "visibility/surface_shader.hpp"

namespace zraster {
namespace {

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
    return q;
}

// Calls fn(px, py, mask) for every pixel of the viewport where the polygon covers a sample.
template <class Fn>
void for_each_mask(const ScreenPolygon& polygon, const Viewport& viewport, int n, Fn&& fn) {
    const auto& v = polygon.vertices;
    const std::size_t count = v.size();
    if (count < 3) return;
    const bool reversed = visibility_detail::snapped_area2(v) < 0;
    // Sample offsets inside a pixel, in 1/kSubpixelScale pixels: (2i + 1) / (2n) pixel.
    std::int64_t offset[8];
    for (int i = 0; i < n; ++i) offset[i] = (2 * i + 1) * (kSubpixelScale / 2) / n;

    struct Edge {
        std::int64_t ax, ay, dx, dy, bias;  // f(X, Y) = dx (Y - ay) - dy (X - ax) >= bias
        std::int64_t col[8], row[8];        // sample offset terms
        std::int64_t col_min, col_max, row_min, row_max;
    };
    Edge edges[64];
    std::vector<Edge> many;
    Edge* e = edges;
    if (count > 64) {
        many.resize(count);
        e = many.data();
    }
    std::size_t edge_count = 0;
    std::int64_t x_min = v[0].snapped[0], x_max = x_min, y_min = v[0].snapped[1], y_max = y_min;
    for (std::size_t i = 0; i < count; ++i) {
        const auto& a = v[reversed ? (i + 1) % count : i].snapped;
        const auto& b = v[reversed ? i : (i + 1) % count].snapped;
        x_min = std::min(x_min, v[i].snapped[0]);
        x_max = std::max(x_max, v[i].snapped[0]);
        y_min = std::min(y_min, v[i].snapped[1]);
        y_max = std::max(y_max, v[i].snapped[1]);
        const std::int64_t dx = b[0] - a[0], dy = b[1] - a[1];
        if (dx == 0 && dy == 0) continue;  // repeated vertex: no edge
        Edge& edge = e[edge_count++];
        // Top edge: horizontal with the inside below it; left edge: going up (y down). Samples
        // exactly on other edges are outside (f >= 1).
        const bool top_left = dy < 0 || (dy == 0 && dx > 0);
        edge = {a[0], a[1], dx, dy, top_left ? 0 : 1, {}, {}, 0, 0, 0, 0};
        for (int k = 0; k < n; ++k) {
            edge.col[k] = -dy * offset[k];
            edge.row[k] = dx * offset[k];
        }
        edge.col_min = std::min(edge.col[0], edge.col[n - 1]);
        edge.col_max = std::max(edge.col[0], edge.col[n - 1]);
        edge.row_min = std::min(edge.row[0], edge.row[n - 1]);
        edge.row_max = std::max(edge.row[0], edge.row[n - 1]);
    }
    if (edge_count < 3) return;
    const int px0 = int(std::max<std::int64_t>(0, floor_div(x_min, kSubpixelScale)));
    const int py0 = int(std::max<std::int64_t>(0, floor_div(y_min, kSubpixelScale)));
    const int px1 =
        int(std::min<std::int64_t>(viewport.width - 1, floor_div(x_max, kSubpixelScale)));
    const int py1 =
        int(std::min<std::int64_t>(viewport.height - 1, floor_div(y_max, kSubpixelScale)));
    const int samples = n * n;
    const std::uint64_t full =
        samples == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << samples) - 1;
    for (int py = py0; py <= py1; ++py) {
        const std::int64_t y = std::int64_t(py) * kSubpixelScale;
        for (int px = px0; px <= px1; ++px) {
            const std::int64_t x = std::int64_t(px) * kSubpixelScale;
            std::uint64_t mask = full;
            for (std::size_t k = 0; k < edge_count && mask; ++k) {
                const Edge& edge = e[k];
                // Within the guard band (precision.hpp) each product stays below 2^58.
                const std::int64_t base = edge.dx * (y - edge.ay) - edge.dy * (x - edge.ax);
                if (base + edge.col_min + edge.row_min >= edge.bias) continue;  // all inside
                if (base + edge.col_max + edge.row_max < edge.bias) {
                    mask = 0;  // all outside
                    break;
                }
                std::uint64_t inside = 0;
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i)
                        if (base + edge.row[j] + edge.col[i] >= edge.bias)
                            inside |= std::uint64_t{1} << (j * n + i);
                mask &= inside;
            }
            if (mask) fn(px, py, mask);
        }
    }
}

using visibility_detail::depth_plane;
using visibility_detail::DepthPlane;

constexpr std::uint32_t kEnd = std::numeric_limits<std::uint32_t>::max();

struct Fragment {
    double depth;  // larger is farther
    std::uint64_t mask;
    std::uint32_t polygon;
    std::uint32_t next;  // next fragment of the same pixel, kEnd at the end
};

// The fragments of a frame, in blocks of kBlock: memory grows by one block at a time, never to
// twice what is stored as a doubling vector's does, and never past the budget's blocks.
class FragmentPool {
  public:
    std::size_t size() const { return size_; }
    const Fragment& operator[](std::uint32_t i) const { return blocks_[i >> kShift][i & kMask]; }

    // Stores f and returns its index. A block the system refuses ends the run with a message
    // naming the budget (the command's "out of memory" would name nothing).
    std::uint32_t add(const Fragment& f, const std::string& file, std::size_t limit) {
        if ((size_ & kMask) == 0) {
            try {
                blocks_.emplace_back(std::make_unique_for_overwrite<Fragment[]>(kBlock));
            } catch (const std::bad_alloc&) {
                throw InputError(
                    file, "A-buffer: out of memory after " + std::to_string(size_) +
                              " fragments (" + std::to_string(size_ * sizeof(Fragment) >> 20) +
                              " MiB at " + std::to_string(sizeof(Fragment)) +
                              " bytes each; the budget max_abuffer_fragments is " +
                              std::to_string(limit) +
                              "): render fewer pixels or polygons, or lower the budget to what "
                              "this machine can hold");
            }
        }
        blocks_.back()[size_ & kMask] = f;
        return static_cast<std::uint32_t>(size_++);
    }

  private:
    static constexpr unsigned kShift = 16;  // 64 Ki fragments (1.5 MiB) a block
    static constexpr std::size_t kBlock = std::size_t{1} << kShift;
    static constexpr std::size_t kMask = kBlock - 1;
    std::vector<std::unique_ptr<Fragment[]>> blocks_;
    std::size_t size_ = 0;
};

}  // namespace

std::vector<PixelCoverage> polygon_coverage(const ScreenPolygon& polygon, const Viewport& viewport,
                                            int samples_per_side) {
    visibility_detail::check_samples_per_side(samples_per_side, "A-buffer");
    std::vector<PixelCoverage> out;
    for_each_mask(polygon, viewport, samples_per_side, [&](int px, int py, std::uint64_t mask) {
        out.push_back({px, py, mask});
    });
    return out;
}

namespace {

RenderResult abuffer_frame(const Scene& scene, const RenderOptions& options,
                           const ABufferOptions& abuffer, ABufferStats* stats) {
    using visibility_detail::SurfaceShader;
    const auto start = std::chrono::steady_clock::now();
    visibility_detail::check_samples_per_side(abuffer.samples_per_side, "A-buffer");
    // Slivers between pixel centers may still cover subsamples: keep them.
    const std::vector<ScreenPolygon> polygons = project_scene(scene, options, true);
    const visibility_detail::FrameContext frame =
        visibility_detail::make_frame_context(scene, options);
    const Camera& camera = frame.camera;
    const int width = options.width, height = options.height;
    const Viewport viewport{width, height};
    const int n = abuffer.samples_per_side;
    const int samples = n * n;
    detail::ThreadArena threads(options.threads > 0 ? options.threads
                                                    : tbb::info::default_concurrency());
    tbb::task_arena& arena = threads.arena();

    // Per polygon: depth plane and what shading needs; alpha (fragment_alphas.hpp) per fragment.
    const SurfaceShader shader(frame);
    std::vector<DepthPlane> planes(polygons.size());
    std::vector<SurfaceShader::Prepared> prepared(polygons.size());
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, polygons.size(), [&](std::size_t i) {
            planes[i] = depth_plane(polygons[i]);
            shader.prepare(polygons[i], prepared[i]);
        });
    });
    const visibility_detail::FragmentAlphas alphas(shader, polygons, n);

    // Build the fragment lists. Fragment indices are 32-bit (kEnd marks the end of a list).
    const std::size_t limit = std::min<std::size_t>(abuffer.max_fragments, std::size_t{kEnd} - 1);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<std::uint32_t> head(pixels, kEnd);
    FragmentPool pool;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        const DepthPlane& plane = planes[i];
        for_each_mask(polygons[i], viewport, n, [&](int px, int py, std::uint64_t mask) {
            if (pool.size() >= limit)
                throw LimitExceeded(scene.name, "max_abuffer_fragments",
                                    "A-buffer: more than " + std::to_string(limit) +
                                        " fragments (polygon-pixel pairs of " +
                                        std::to_string(sizeof(Fragment)) +
                                        " bytes, the limit): render fewer pixels or polygons, or "
                                        "raise the limit");
            const std::size_t p = std::size_t(py) * std::size_t(width) + std::size_t(px);
            const double depth = plane.at(px + 0.5, py + 0.5);
            head[p] = pool.add({depth, mask, std::uint32_t(i), head[p]}, scene.name, limit);
        });
    }

    ABufferStats local;
    local.fragments = pool.size();
    for (std::size_t p = 0; p < pixels; ++p) {
        std::uint64_t length = 0;
        for (std::uint32_t f = head[p]; f != kEnd; f = pool[f].next) ++length;
        local.max_list_length = std::max(local.max_list_length, length);
        local.pixels_with_fragments += length != 0;
    }

    // Targets.
    RenderResult result;
    result.targets = visibility_detail::blank_targets(options);
    RenderTargets& t = result.targets;
    const glm::dvec3 background =
        glm::clamp(glm::dvec3(options.background), glm::dvec3(0.0), glm::dvec3(1.0));
    const std::uint64_t full =
        samples == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << samples) - 1;

    // A fragment of the pixel being resolved, shaded on first use (hidden ones never are).
    struct Entry {
        const Fragment* fragment;
        float alpha;  // in [0, 1]: 1 for an opaque fragment and a Mask one that passed
        bool shaded;
        visibility_detail::Shaded shading;
    };
    auto shade = [&](Entry& e, int px, int py) {
        if (e.shaded) return;
        const Fragment& f = *e.fragment;
        // A full fragment is shaded at the pixel center, as render() shades the pixel; a partial
        // one at the centroid of the samples it covers (always inside the convex polygon).
        const glm::dvec2 at = visibility_detail::mask_centroid(f.mask, n, px, py);
        e.shading = shader.shade(prepared[f.polygon], px, py, f.mask == full, at.x, at.y,
                                 options.normal_target);
        e.shading.color = glm::clamp(e.shading.color, glm::vec3(0.0f), glm::vec3(1.0f));
        e.shaded = true;
    };
    // Nearest first; equal depths by content (alpha, mask, then the shaded color), ids last.
    auto before = [&](const Entry& a, const Entry& b) {
        const Fragment& f = *a.fragment;
        const Fragment& g = *b.fragment;
        return std::make_tuple(f.depth, a.alpha, f.mask) <
               std::make_tuple(g.depth, b.alpha, g.mask);
    };
    auto ids = [&](const Entry& e) {
        const ScreenPolygon& p = polygons[e.fragment->polygon];
        return std::make_tuple(e.shading.color.x, e.shading.color.y, e.shading.color.z, p.instance,
                               p.primitive);
    };
    std::atomic<std::uint64_t> shaded_total{0}, discarded_total{0}, blended_total{0},
        blended_pixels_total{0};
    // A pixel without fragments: the background, composited as below with no fragment (the same
    // sums, so the same bytes), once instead of per sample of every empty pixel.
    std::uint8_t empty_color[3] = {};
    {
        glm::dvec3 sum(0.0);
        for (int s = 0; s < samples; ++s) sum += glm::dvec3(0.0) + 1.0 * background;
        sum /= double(samples);
        for (int c = 0; c < 3; ++c) empty_color[c] = visibility_detail::to_unorm8(float(sum[c]));
    }
    auto resolve_rows = [&](const tbb::blocked_range<int>& rows) {
        std::vector<Entry> list;
        std::uint64_t shaded = 0, discarded = 0, blended = 0, blended_pixels = 0;
        for (int py = rows.begin(); py < rows.end(); ++py) {
            for (int px = 0; px < width; ++px) {
                const std::size_t p = std::size_t(py) * std::size_t(width) + std::size_t(px);
                if (head[p] == kEnd) {
                    if (options.color_target)
                        for (int c = 0; c < 3; ++c)
                            t.color[p * 4 + std::size_t(c)] = empty_color[c];
                    continue;
                }
                list.clear();
                // Fragments whose alpha is 0 (cut out by the alpha test, or fully transparent)
                // are dropped: they show nothing and hide nothing.
                for (std::uint32_t f = head[p]; f != kEnd; f = pool[f].next) {
                    const float alpha =
                        alphas.at(prepared[pool[f].polygon], pool[f].polygon, pool[f].mask, px, py);
                    if (alpha > 0.0f) {
                        list.push_back({&pool[f], alpha, false, {}});
                    } else if (shader.alpha_mode(polygons[pool[f].polygon].instance) ==
                               AlphaMode::Mask) {
                        ++discarded;
                    }
                }
                std::sort(list.begin(), list.end(), before);
                // Ties: order by the shaded color, so submission order never decides.
                for (std::size_t i = 0; i < list.size();) {
                    std::size_t j = i + 1;
                    while (j < list.size() && !before(list[i], list[j])) ++j;
                    if (j - i > 1) {
                        for (std::size_t k = i; k < j; ++k) shade(list[k], px, py);
                        std::sort(list.begin() + std::ptrdiff_t(i),
                                  list.begin() + std::ptrdiff_t(j),
                                  [&](const Entry& a, const Entry& b) { return ids(a) < ids(b); });
                    }
                    i = j;
                }
                if (options.color_target) {
                    glm::dvec3 sum(0.0);
                    for (int s = 0; s < samples; ++s) {
                        const std::uint64_t bit = std::uint64_t{1} << s;
                        glm::dvec3 color(0.0);
                        double transmittance = 1.0;
                        for (Entry& e : list) {
                            if (!(e.fragment->mask & bit)) continue;
                            shade(e, px, py);
                            const double alpha = e.alpha;
                            color += transmittance * alpha * glm::dvec3(e.shading.color);
                            if (alpha >= 1.0) {
                                transmittance = 0.0;
                                break;
                            }
                            transmittance *= 1.0 - alpha;
                        }
                        sum += color + transmittance * background;
                    }
                    sum /= double(samples);
                    for (int c = 0; c < 3; ++c)
                        t.color[p * 4 + std::size_t(c)] =
                            visibility_detail::to_unorm8(float(sum[c]));
                }
                // Depth, ids and normal: the nearest fragment that is not blended (blended ones
                // write none of them, as in render()).
                auto nearest_it = std::find_if(list.begin(), list.end(), [&](const Entry& e) {
                    return !alphas.blended(e.fragment->polygon);
                });
                if (nearest_it != list.end()) {
                    Entry& nearest = *nearest_it;
                    const ScreenPolygon& polygon = polygons[nearest.fragment->polygon];
                    const double z = nearest.fragment->depth;
                    t.depth[p] = float(camera.reversed_z ? 1.0 - z : z);
                    if (options.normal_target) {
                        shade(nearest, px, py);
                        t.normal[p] = nearest.shading.normal;
                    }
                    if (options.id_targets) {
                        t.instance_id[p] = polygon.instance;
                        t.primitive_id[p] = polygon.primitive;
                    }
                }
                for (const Entry& e : list) shaded += e.shaded;
                // Blended fragments in front of the nearest opaque one (as render() counts the
                // ones that pass its depth test).
                std::uint64_t in_front = 0;
                for (auto e = list.begin(); e != nearest_it; ++e) in_front += e->alpha > 0.0f;
                blended += in_front;
                blended_pixels += in_front > 0;
            }
        }
        shaded_total += shaded;
        discarded_total += discarded;
        blended_total += blended;
        blended_pixels_total += blended_pixels;
    };
    arena.execute([&] { tbb::parallel_for(tbb::blocked_range<int>(0, height, 8), resolve_rows); });

    if (stats) *stats = local;
    result.stats.triangles_rasterized = polygons.size();
    result.stats.fragments_shaded = shaded_total.load();
    result.stats.fragments_alpha_discarded = discarded_total.load();
    result.stats.fragments_blended = blended_total.load();
    result.stats.pixels_blended = blended_pixels_total.load();
    visibility_detail::finish_stats(result.stats, camera, scene, start);
    return result;
}

}  // namespace

RenderResult render_abuffer(const Scene& scene, const RenderOptions& options,
                            const ABufferOptions& abuffer, ABufferStats* stats) {
    try {
        return abuffer_frame(scene, options, abuffer, stats);
    } catch (const std::bad_alloc&) {
        // Past the pool (which names its own count), the polygons' shading data and the
        // per-pixel lists are what can fail: name the budgets that bound them.
        throw InputError(scene.name,
                         "A-buffer: out of memory for " + std::to_string(options.width) + "x" +
                             std::to_string(options.height) +
                             " pixels and their polygons: render fewer pixels or polygons, or "
                             "lower the budgets max_projected_polygons and max_abuffer_fragments "
                             "to what this machine can hold");
    }
}

}  // namespace zraster
