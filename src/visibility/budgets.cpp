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
    return 2048 * std::uint64_t{polygons} + 10'000'000;
}

std::uint64_t bsp_polygon_budget(const RenderLimits& limits, std::size_t input_polygons) {
    if (limits.max_bsp_polygons != 0) return limits.max_bsp_polygons;
    const std::uint64_t n = input_polygons;
    // (Capped for memory: 2^24 polygons are about 4 GB; a larger input may still be split
    // once.)
    return std::min(16 * n + 65'536, std::max(std::uint64_t{1} << 24, 2 * n));
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
