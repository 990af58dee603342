// Multisampling (MSAA) of the z-buffer path: coverage and depth per subsample, shading per pixel
// (the antialiasing of graphics hardware since the late 1990s; Akeley 1993, "RealityEngine
// graphics", SIGGRAPH '93).
//
// What: every polygon of project_scene (slivers between pixel centers kept) is rasterized into
// an n x n grid of samples per pixel (the A-buffer's exact masks, src/visibility/abuffer.cpp),
// each sample holding a depth (the polygon's window-depth plane at the sample) and the polygon
// that is nearest there (z-buffer, LESS: equal depths keep the first drawn). Shading is deferred
// and done once per pixel and visible polygon: at the pixel center when the polygon holds every
// sample of the pixel (then the color is render()'s, bit for bit), else at the centroid of its
// samples there. The pixel is the mean of its samples' colors (background where none).
//
// Materials' alpha (fragment_alphas.hpp: one alpha per polygon and pixel, at the pixel center
// when the polygon covers every sample, else at the centroid of its samples, as hardware MSAA
// tests alpha once per pixel without alpha-to-coverage). Mask: a fragment whose alpha fails the
// test leaves every sample it covers in the pixel alone (writes no depth); the rest are opaque.
// Blend: the fragments write no depth; they are kept in per-pixel lists (the A-buffer's), shaded
// once per pixel like opaque ones, sorted farther first by their depth at the pixel center (ties
// by content, then ids: never by submission order), and composited per sample over the sample's
// opaque color where the fragment covers the sample and lies in front of its opaque depth there.
//
// Cost: O(touched pixels x samples x polygon edges) for coverage and depth, one shading per
// (pixel, visible polygon); memory 8 bytes per sample (float depth, polygon index), so 16 x
// that of a depth buffer at 4 x 4, plus about 300 bytes per polygon for shading, plus 24 bytes
// per blended fragment.
//
// When to use: antialiased edges and intersection lines (depth is per sample, so two surfaces
// crossing inside a pixel are resolved per sample, which the A-buffer's one depth per fragment
// does not do) at the shading cost of an aliased frame. It does not antialias texture or
// specular detail inside polygons: supersampling (supersample.cpp) does, at n^2 the shading.
#include <zraster/abuffer.hpp>
#include <zraster/error.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>

#include "raster/bounding_box_pixels.hpp"
#include "render/thread_arena.hpp"
#include "visibility/fragment_alphas.hpp"
#include "visibility/frame_context.hpp"
#include "visibility/surface_shader.hpp"

namespace zraster {

RenderResult render_multisampled(const Scene& scene, const RenderOptions& options,
                                 int samples_per_side) {
    using visibility_detail::SurfaceShader;
    const auto start = std::chrono::steady_clock::now();
    const int n = samples_per_side;
    visibility_detail::check_samples_per_side(n, "multisampling");
    // The sample buffers are 8 bytes per sample: bound them as render() bounds its pixels.
    const std::uint64_t total = std::uint64_t(std::max(options.width, 0)) *
                                std::uint64_t(std::max(options.height, 0)) * std::uint64_t(n * n);
    if (total > options.limits.max_pixels)
        throw InputError("", "multisampled frame of " + std::to_string(total) +
                                 " samples exceeds the limit of " +
                                 std::to_string(options.limits.max_pixels) +
                                 " (RenderLimits::max_pixels, --max-pixels)");
    // Its sample buffers with the frame's memory (make_frame_context counts pixels only):
    // coverage and depth, 8 bytes a sample, and the resolved targets' share.
    check_frame_memory(scene.name, scene.vertex_count(), scene.triangle_count(), total,
                       options.limits, 8 + (kFrameBytesPerSample + n * n - 1) / (n * n));
    const std::vector<ScreenPolygon> polygons = project_scene(scene, options, true);
    // Every polygon's coverage and depth are computed per sample, hidden or not (there is no
    // hierarchical z here): that work is bounded before any is done.
    std::uint64_t covered = 0;
    for (const ScreenPolygon& polygon : polygons) {
        constexpr std::int64_t kLow = std::numeric_limits<std::int64_t>::lowest();
        constexpr std::int64_t kHigh = std::numeric_limits<std::int64_t>::max();
        std::int64_t min_x = kHigh, min_y = kHigh, max_x = kLow, max_y = kLow;
        for (const PolygonVertex& v : polygon.vertices) {
            min_x = std::min(min_x, v.snapped[0]);
            min_y = std::min(min_y, v.snapped[1]);
            max_x = std::max(max_x, v.snapped[0]);
            max_y = std::max(max_y, v.snapped[1]);
        }
        covered +=
            detail::bounding_box_pixels(min_x, min_y, max_x, max_y, options.width, options.height) *
            std::uint64_t(n * n);
    }
    detail::check_covered_samples(covered, options.limits.max_covered_samples,
                                  "multisampling (--msaa) rasterizes every triangle whole");
    const visibility_detail::FrameContext frame =
        visibility_detail::make_frame_context(scene, options);
    const int width = options.width, height = options.height;
    const int samples = n * n;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    detail::ThreadArena threads(options.threads > 0 ? options.threads
                                                    : tbb::info::default_concurrency());
    tbb::task_arena& arena = threads.arena();

    // What shading and alpha need of each polygon.
    const SurfaceShader shader(frame);
    std::vector<SurfaceShader::Prepared> prepared(polygons.size());
    std::vector<visibility_detail::DepthPlane> planes(polygons.size());
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, polygons.size(), [&](std::size_t i) {
            shader.prepare(polygons[i], prepared[i]);
            planes[i] = visibility_detail::depth_plane(polygons[i]);
        });
    });
    const visibility_detail::FragmentAlphas alphas(shader, polygons, n);

    // Coverage and depth per sample, polygons in submission order; blended fragments listed per
    // pixel instead.
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<float> depth(pixels * std::size_t(samples), std::numeric_limits<float>::infinity());
    std::vector<std::uint32_t> owner(pixels * std::size_t(samples), kNone);
    std::vector<double> offset(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) offset[std::size_t(i)] = (i + 0.5) / n;
    auto sample_depth = [&](std::uint32_t index, int px, int py, int s) {
        return float(
            planes[index].at(px + offset[std::size_t(s % n)], py + offset[std::size_t(s / n)]));
    };
    struct BlendedFragment {
        std::uint64_t mask;
        std::uint32_t polygon;
        float alpha;
        std::uint32_t next;  // of the same pixel, kNone at the end
    };
    std::vector<BlendedFragment> blended;
    std::vector<std::uint32_t> blend_head(alphas.any() ? pixels : 0, kNone);
    std::uint64_t discarded = 0;
    for (std::size_t index = 0; index < polygons.size(); ++index) {
        const auto polygon = std::uint32_t(index);
        const AlphaMode mode = alphas.mode(polygon);
        for (const PixelCoverage& c : polygon_coverage(polygons[index], {width, height}, n)) {
            const std::size_t pixel = std::size_t(c.y) * std::size_t(width) + std::size_t(c.x);
            if (mode != AlphaMode::Opaque) {
                const float alpha = alphas.at(prepared[index], polygon, c.mask, c.x, c.y);
                if (alpha == 0.0f) {
                    discarded += mode == AlphaMode::Mask;
                    continue;
                }
                if (mode == AlphaMode::Blend) {
                    blended.push_back({c.mask, polygon, alpha, blend_head[pixel]});
                    blend_head[pixel] = std::uint32_t(blended.size() - 1);
                    continue;
                }
            }
            const std::size_t base = pixel * std::size_t(samples);
            for (int s = 0; s < samples; ++s) {
                if (!(c.mask >> s & 1)) continue;
                const float z = sample_depth(polygon, c.x, c.y, s);
                if (z < depth[base + std::size_t(s)]) {
                    depth[base + std::size_t(s)] = z;
                    owner[base + std::size_t(s)] = polygon;
                }
            }
        }
    }

    // Deferred shading and resolve, parallel over rows.
    RenderResult result;
    result.targets = visibility_detail::blank_targets(options);
    RenderTargets& t = result.targets;
    const glm::dvec3 background =
        glm::clamp(glm::dvec3(options.background), glm::dvec3(0.0), glm::dvec3(1.0));
    const int center_sample = (n / 2) * n + n / 2;  // for depth, ids, normal
    const std::uint64_t full =
        samples == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << samples) - 1;
    auto clamped = [](const glm::vec3& c) {
        return glm::clamp(glm::dvec3(c), glm::dvec3(0.0), glm::dvec3(1.0));
    };
    // A blended fragment of the pixel being resolved: its depth at the pixel center orders it.
    struct Layer {
        const BlendedFragment* fragment;
        double depth;
        glm::dvec3 color;
    };
    std::atomic<std::uint64_t> pixels_blended{0};
    auto resolve_rows = [&](const tbb::blocked_range<int>& rows) {
        std::vector<Layer> layers;
        std::uint64_t blended_here = 0;
        for (int py = rows.begin(); py < rows.end(); ++py)
            for (int px = 0; px < width; ++px) {
                const std::size_t p = std::size_t(py) * std::size_t(width) + std::size_t(px);
                const std::uint32_t* own = &owner[p * std::size_t(samples)];
                const bool blend = !blend_head.empty() && blend_head[p] != kNone;
                // The samples' opaque colors (only where fragments blend over them).
                glm::dvec3 sample_color[64];
                glm::dvec3 sum(0.0);
                std::uint64_t done = 0;  // samples already accounted for
                glm::vec3 center_normal(0.0f);
                for (int s = 0; s < samples; ++s) {
                    if (done >> s & 1) continue;
                    if (own[s] == kNone) {
                        sum += background;
                        if (blend) sample_color[s] = background;
                        continue;
                    }
                    // Every sample of this polygon in the pixel: shaded once.
                    const std::uint32_t index = own[s];
                    int count = 0;
                    double x = 0.0, y = 0.0;
                    bool has_center = false;
                    for (int k = s; k < samples; ++k)
                        if (own[k] == index) {
                            done |= std::uint64_t{1} << k;
                            x += offset[std::size_t(k % n)];
                            y += offset[std::size_t(k / n)];
                            has_center |= k == center_sample;
                            ++count;
                        }
                    const bool whole = count == samples;
                    const visibility_detail::Shaded shaded =
                        shader.shade(prepared[index], px, py, whole, px + x / count, py + y / count,
                                     options.normal_target && has_center);
                    const glm::dvec3 color = clamped(shaded.color);
                    sum += double(count) * color;
                    if (blend)
                        for (int k = s; k < samples; ++k)
                            if (own[k] == index) sample_color[k] = color;
                    if (has_center) center_normal = shaded.normal;
                }
                if (blend) {
                    // Farther first; equal depths by content, ids last (never submission order).
                    layers.clear();
                    for (std::uint32_t f = blend_head[p]; f != kNone; f = blended[f].next) {
                        const BlendedFragment& b = blended[f];
                        const glm::dvec2 at = visibility_detail::mask_centroid(b.mask, n, px, py);
                        const visibility_detail::Shaded shaded = shader.shade(
                            prepared[b.polygon], px, py, b.mask == full, at.x, at.y, false);
                        layers.push_back(
                            {&b, planes[b.polygon].at(px + 0.5, py + 0.5), clamped(shaded.color)});
                    }
                    auto key = [&](const Layer& l) {
                        const ScreenPolygon& q = polygons[l.fragment->polygon];
                        return std::make_tuple(-l.depth, l.fragment->alpha, l.fragment->mask,
                                               l.color.x, l.color.y, l.color.z, q.instance,
                                               q.primitive);
                    };
                    std::sort(layers.begin(), layers.end(),
                              [&](const Layer& a, const Layer& b) { return key(a) < key(b); });
                    const float* opaque_depth = &depth[p * std::size_t(samples)];
                    sum = glm::dvec3(0.0);
                    for (int s = 0; s < samples; ++s) {
                        glm::dvec3 c = sample_color[s];
                        for (const Layer& l : layers) {
                            const BlendedFragment& b = *l.fragment;
                            // In front of the opaque surface at the sample (LESS, as it is
                            // depth tested): blended fragments write no depth.
                            if (!(b.mask >> s & 1) ||
                                !(sample_depth(b.polygon, px, py, s) < opaque_depth[s]))
                                continue;
                            c = double(b.alpha) * l.color + (1.0 - double(b.alpha)) * c;
                        }
                        sum += c;
                    }
                    ++blended_here;
                }
                if (options.color_target) {
                    sum /= double(samples);
                    for (int c = 0; c < 3; ++c)
                        t.color[p * 4 + std::size_t(c)] =
                            visibility_detail::to_unorm8(float(sum[c]));
                }
                const std::uint32_t nearest = own[center_sample];
                if (nearest != kNone) {
                    const float z = depth[p * std::size_t(samples) + std::size_t(center_sample)];
                    t.depth[p] = frame.camera.reversed_z ? 1.0f - z : z;
                    if (options.normal_target) t.normal[p] = center_normal;
                    if (options.id_targets) {
                        t.instance_id[p] = polygons[nearest].instance;
                        t.primitive_id[p] = polygons[nearest].primitive;
                    }
                }
            }
        pixels_blended += blended_here;
    };
    arena.execute([&] { tbb::parallel_for(tbb::blocked_range<int>(0, height, 8), resolve_rows); });

    result.stats.fragments_alpha_discarded = discarded;
    result.stats.fragments_blended = blended.size();
    result.stats.pixels_blended = pixels_blended.load();
    result.stats.triangles_rasterized = polygons.size();
    visibility_detail::finish_stats(result.stats, frame.camera, scene, start);
    return result;
}

}  // namespace zraster
