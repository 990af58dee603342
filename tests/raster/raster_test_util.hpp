// Helpers for the rasterizer tests: triangles given directly in window coordinates (y down).
#pragma once
#include <zraster/raster.hpp>

#include <vector>

namespace zraster::test {

// Clip-space position (w = 1) of a window-space point for a width x height viewport.
inline glm::vec4 window_to_clip(double x, double y, int width, int height, double depth = 0.5) {
    return {static_cast<float>(2.0 * x / width - 1.0), static_cast<float>(1.0 - 2.0 * y / height),
            static_cast<float>(2.0 * depth - 1.0), 1.0f};
}

struct CoverageGrid {
    int width, height;
    std::vector<int> hits;
    explicit CoverageGrid(int w, int h)
        : width(w), height(h), hits(std::size_t(w) * std::size_t(h), 0) {}
    int at(int x, int y) const {
        return hits[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

// Rasterizes a window-space triangle (no culling) and adds its coverage to grid. Returns false
// when setup rejected it (degenerate or no coverage).
inline bool rasterize_window_triangle(CoverageGrid& grid, glm::dvec2 a, glm::dvec2 b,
                                      glm::dvec2 c) {
    SetupSettings settings;
    settings.viewport = {grid.width, grid.height};
    settings.cull = CullMode::None;
    TriangleSetup t;
    const std::array<glm::vec4, 3> clip{window_to_clip(a.x, a.y, grid.width, grid.height),
                                        window_to_clip(b.x, b.y, grid.width, grid.height),
                                        window_to_clip(c.x, c.y, grid.width, grid.height)};
    if (setup_triangle(clip, settings, t) != SetupResult::Visible) return false;
    for_each_covered_pixel(t, 0, 0, grid.width, grid.height, [&](int x, int y) {
        ++grid.hits[std::size_t(y) * std::size_t(grid.width) + std::size_t(x)];
    });
    return true;
}

}  // namespace zraster::test
