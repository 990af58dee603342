// The pixels of a frame inside a triangle's or polygon's bounding box: a bound, known before it
// is rasterized, of the pixels rasterizing it visits. Summed over a frame's triangles it bounds
// the work of the paths that draw every fragment (nothing hidden is skipped), which
// RenderLimits::max_covered_samples budgets.
#pragma once
#include <zraster/error.hpp>
#include <zraster/precision.hpp>

#include <algorithm>
#include <cstdint>
#include <string>

namespace zraster::detail {

// Snapped coordinates (1/kSubpixelScale pixel, y down): the pixels from the one holding the
// minimum to the one holding the maximum, within [0, width) x [0, height). (A pixel is covered
// only when its center is inside, so this over-counts by at most one pixel a side.)
inline std::uint64_t bounding_box_pixels(std::int64_t min_x, std::int64_t min_y, std::int64_t max_x,
                                         std::int64_t max_y, int width, int height) {
    const auto span = [](std::int64_t lo, std::int64_t hi, int side) -> std::uint64_t {
        const std::int64_t first = std::max<std::int64_t>(lo >> kSubpixelBits, 0);
        const std::int64_t end = std::min<std::int64_t>((hi >> kSubpixelBits) + 1, side);
        return end > first ? std::uint64_t(end - first) : 0;
    };
    return span(min_x, max_x, width) * span(min_y, max_y, height);
}

// Refuses `samples` (pixels inside the bounding boxes times samples per pixel, summed) past
// `limit`, before any is rasterized; `what` says which triangles are drawn whole and why.
inline void check_covered_samples(std::uint64_t samples, std::uint64_t limit,
                                  const std::string& what) {
    if (samples <= limit) return;
    throw LimitExceeded("", "max_covered_samples",
                        what + ": their bounding boxes cover " + std::to_string(samples) +
                            " samples, more than the limit of " + std::to_string(limit) +
                            " (RenderLimits::max_covered_samples): large triangles drawn over "
                            "each other many times, or a frame too large for them");
}

}  // namespace zraster::detail
