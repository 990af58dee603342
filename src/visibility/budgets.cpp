// The budgets of the object-space visibility algorithms (RenderLimits, visibility.hpp): set by
// the caller, or scaled to the input. The automatic ones leave a margin of 5x or more over the
// real meshes measured (bunny, cat, Duck, teapot, suzanne, elephant at 640x480 and 1920x1080)
// and refuse random triangle soups of a few thousand triangles within seconds.
#include <zraster/visibility.hpp>

#include <algorithm>
#include <bit>

namespace zraster {

std::uint64_t painter_comparison_budget(const RenderLimits& limits, std::size_t polygons) {
    if (limits.max_painter_comparisons != 0) return limits.max_painter_comparisons;
    // (Capped for time: at 0.1 to 0.2 us a comparison, 10^8 is 10 to 20 s on one core. A
    // million coincident polygons asked for 2 x 10^9 comparisons, over three minutes.)
    return std::min<std::uint64_t>(2048 * std::uint64_t{polygons} + 10'000'000, 100'000'000);
}

std::uint64_t bsp_polygon_budget(const RenderLimits& limits, std::size_t input_polygons) {
    if (limits.max_bsp_polygons != 0) return limits.max_bsp_polygons;
    const std::uint64_t n = input_polygons;
    // (Capped for memory: 2^22 polygons of about 250 bytes are 1 GB.)
    return std::min(16 * n + 65'536, std::uint64_t{1} << 22);
}

std::uint64_t bsp_classification_budget(const RenderLimits& limits, std::size_t input_polygons) {
    if (limits.max_bsp_classifications != 0) return limits.max_bsp_classifications;
    // A convex mesh (each plane has every other polygon behind it) makes the tree a chain: about
    // 6.5 n^2 classifications with the 12 candidates scored (a 6,016-triangle sphere: 2.4 x 10^8);
    // meshes measured need 680 (bunny) to 1,440 (teapot) per polygon. (Capped for time: at 15 to
    // 20 ns each, 5 x 10^8 classifications take about 8 to 10 s.)
    constexpr std::uint64_t kCap = 500'000'000;
    const std::uint64_t n = input_polygons;
    if (n > (std::uint64_t{1} << 16)) return kCap;  // (16 n^2 is past the cap; no overflow)
    return std::min<std::uint64_t>(16 * n * n + 10'000'000, kCap);
}

std::uint64_t projected_polygon_budget(const RenderLimits& limits) {
    if (limits.max_projected_polygons != 0) return limits.max_projected_polygons;
    // 0.7 KB a polygon through the painter's sort, 2 KB in the A-buffer: at most about 1 GB.
    return std::uint64_t{1} << 19;
}

std::uint64_t painted_fragment_budget(const RenderLimits& limits, int width, int height) {
    if (limits.max_painted_fragments != 0) return limits.max_painted_fragments;
    const std::uint64_t pixels = static_cast<std::uint64_t>(std::max(width, 0)) *
                                 static_cast<std::uint64_t>(std::max(height, 0));
    // An overdraw of 16 is generous for meshes; a filled pixel is shaded in about 0.2 us
    // (910,828 in 0.18 s for sphere:2000 at 1920x1080), so 2^26 of them take about 13 s.
    return std::min((std::uint64_t{16} * pixels) + (std::uint64_t{1} << 24),
                    std::uint64_t{1} << 26);
}

std::uint64_t warnock_classification_budget(const RenderLimits& limits, std::size_t polygons,
                                            int width, int height) {
    if (limits.max_warnock_classifications != 0) return limits.max_warnock_classifications;
    const auto side = static_cast<std::uint64_t>(std::max({width, height, 1}));
    const std::uint64_t levels = std::bit_width(side) + 1;  // of the region quadtree
    const std::uint64_t pixels = static_cast<std::uint64_t>(std::max(width, 0)) *
                                 static_cast<std::uint64_t>(std::max(height, 0));
    return 64 * std::uint64_t{polygons} * levels + 4 * pixels + 10'000'000;
}

}  // namespace zraster
