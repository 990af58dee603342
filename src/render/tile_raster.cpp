// Binning and per-tile rasterization. Each tile owns its pixels and walks its bin in submission
// order, so tiles can run on any thread in any order and the image stays the same.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "render/frame.hpp"
#include "render/shade_fragment.hpp"

namespace zraster::detail {
namespace {

std::uint8_t to_unorm8(float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

void rasterize_tiles(const Frame& frame, RenderTargets& targets, RenderStats& stats) {
    const RenderOptions& options = *frame.options;
    const int width = options.width, height = options.height;
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int tiles_y = (height + kTileSize - 1) / kTileSize;

    // Bins: for each tile, the indices of the triangles whose bounding box touches it, in order.
    std::vector<std::vector<std::uint32_t>> bins(static_cast<std::size_t>(tiles_x * tiles_y));
    for (std::uint32_t i = 0; i < frame.triangles.size(); ++i) {
        const TriangleSetup& s = frame.triangles[i].setup;
        for (int ty = s.min_y / kTileSize; ty <= s.max_y / kTileSize; ++ty)
            for (int tx = s.min_x / kTileSize; tx <= s.max_x / kTileSize; ++tx)
                bins[static_cast<std::size_t>(ty * tiles_x + tx)].push_back(i);
    }

    DepthBuffer depth(width, height, options.depth_format);
    depth.clear(depth_clear_value(options));
    const CompareFunc compare = effective_depth_compare(options);
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    const glm::u8vec4 background(to_unorm8(options.background.x), to_unorm8(options.background.y),
                                 to_unorm8(options.background.z), 255);
    if (options.color_target) {
        targets.color.resize(pixels * 4);
        for (std::size_t i = 0; i < pixels; ++i)
            std::copy(&background[0], &background[0] + 4, &targets.color[i * 4]);
    }
    if (options.normal_target) targets.normal.assign(pixels, glm::vec3(0.0f));
    if (options.id_targets) {
        targets.instance_id.assign(pixels, -1);
        targets.primitive_id.assign(pixels, -1);
    }
    if (options.coverage_counts) {
        targets.front_hits.assign(pixels, 0);
        targets.back_hits.assign(pixels, 0);
    }

    const bool shade = options.color_target || options.normal_target;
    std::vector<std::uint64_t> shaded_per_tile(bins.size(), 0);
    tbb::parallel_for(std::size_t{0}, bins.size(), [&](std::size_t tile) {
        const int x0 = int(tile % std::size_t(tiles_x)) * kTileSize;
        const int y0 = int(tile / std::size_t(tiles_x)) * kTileSize;
        const int x1 = std::min(width, x0 + kTileSize), y1 = std::min(height, y0 + kTileSize);
        std::uint64_t shaded = 0;
        for (const std::uint32_t index : bins[tile]) {
            const RasterTriangle& t = frame.triangles[index];
            for_each_covered_pixel(t.setup, x0, y0, x1, y1, [&](int px, int py) {
                if (options.depth_test &&
                    !depth.test_and_write(px, py, depth_at(t.setup, px, py), compare,
                                          options.depth_write))
                    return;
                const std::size_t p = std::size_t(py) * std::size_t(width) + std::size_t(px);
                if (options.coverage_counts) ++(t.setup.front_facing ? targets.front_hits[p]
                                                                   : targets.back_hits[p]);
                if (options.id_targets) {
                    targets.instance_id[p] =
                        static_cast<std::int32_t>(frame.instances[t.instance].scene_instance);
                    targets.primitive_id[p] = static_cast<std::int32_t>(t.primitive);
                }
                if (!shade) return;
                ++shaded;
                const ShadedFragment f = shade_fragment(frame, t, px, py, options.normal_target);
                if (options.color_target) {
                    std::uint8_t* c = &targets.color[p * 4];
                    c[0] = to_unorm8(f.color.x);
                    c[1] = to_unorm8(f.color.y);
                    c[2] = to_unorm8(f.color.z);
                    c[3] = 255;
                }
                if (options.normal_target) targets.normal[p] = f.normal;
            });
        }
        shaded_per_tile[tile] = shaded;
    });
    for (const std::uint64_t n : shaded_per_tile) stats.fragments_shaded += n;

    targets.width = width;
    targets.height = height;
    targets.depth.resize(pixels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            targets.depth[std::size_t(y) * std::size_t(width) + std::size_t(x)] = depth.read(x, y);
}

}  // namespace zraster::detail
