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
// Cost: O(touched pixels x samples x polygon edges) for coverage and depth, one shading per
// (pixel, visible polygon); memory 8 bytes per sample (float depth, polygon index), so 16 x
// that of a depth buffer at 4 x 4, plus about 300 bytes per polygon for shading. Opaque only:
// material opacity is ignored (use the A-buffer).
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
#include <chrono>
#include <limits>
#include <string>

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
    const std::vector<ScreenPolygon> polygons = project_scene(scene, options, true);
    const visibility_detail::FrameContext frame =
        visibility_detail::make_frame_context(scene, options);
    const int width = options.width, height = options.height;
    const int samples = n * n;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);

    // Coverage and depth per sample, polygons in submission order.
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<float> depth(pixels * std::size_t(samples), std::numeric_limits<float>::infinity());
    std::vector<std::uint32_t> owner(pixels * std::size_t(samples), kNone);
    std::vector<double> offset(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) offset[std::size_t(i)] = (i + 0.5) / n;
    for (std::size_t index = 0; index < polygons.size(); ++index) {
        const visibility_detail::DepthPlane plane = visibility_detail::depth_plane(polygons[index]);
        for (const PixelCoverage& c : polygon_coverage(polygons[index], {width, height}, n)) {
            const std::size_t base =
                (std::size_t(c.y) * std::size_t(width) + std::size_t(c.x)) * std::size_t(samples);
            for (int s = 0; s < samples; ++s) {
                if (!(c.mask >> s & 1)) continue;
                const float z = float(
                    plane.at(c.x + offset[std::size_t(s % n)], c.y + offset[std::size_t(s / n)]));
                if (z < depth[base + std::size_t(s)]) {
                    depth[base + std::size_t(s)] = z;
                    owner[base + std::size_t(s)] = std::uint32_t(index);
                }
            }
        }
    }

    // Deferred shading and resolve, parallel over rows.
    const SurfaceShader shader(frame);
    std::vector<SurfaceShader::Prepared> prepared(polygons.size());
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, polygons.size(),
                          [&](std::size_t i) { shader.prepare(polygons[i], prepared[i]); });
    });
    RenderResult result;
    result.targets = visibility_detail::blank_targets(options);
    RenderTargets& t = result.targets;
    const glm::dvec3 background =
        glm::clamp(glm::dvec3(options.background), glm::dvec3(0.0), glm::dvec3(1.0));
    const int center_sample = (n / 2) * n + n / 2;  // for depth, ids, normal
    auto resolve_rows = [&](const tbb::blocked_range<int>& rows) {
        for (int py = rows.begin(); py < rows.end(); ++py)
            for (int px = 0; px < width; ++px) {
                const std::size_t p = std::size_t(py) * std::size_t(width) + std::size_t(px);
                const std::uint32_t* own = &owner[p * std::size_t(samples)];
                glm::dvec3 sum(0.0);
                std::uint64_t done = 0;  // samples already accounted for
                glm::vec3 center_normal(0.0f);
                for (int s = 0; s < samples; ++s) {
                    if (done >> s & 1) continue;
                    if (own[s] == kNone) {
                        sum += background;
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
                    sum += double(count) *
                           glm::clamp(glm::dvec3(shaded.color), glm::dvec3(0.0), glm::dvec3(1.0));
                    if (has_center) center_normal = shaded.normal;
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
    };
    arena.execute([&] { tbb::parallel_for(tbb::blocked_range<int>(0, height, 8), resolve_rows); });

    result.stats.triangles_rasterized = polygons.size();
    visibility_detail::finish_stats(result.stats, frame.camera, scene, start);
    return result;
}

}  // namespace zraster
