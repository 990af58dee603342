// An RGBA8 image in memory, rows top to bottom, and the few drawing operations the viewer's HUD
// and the explain pictures need (rectangles, blending, lines, convex and general polygons).
#pragma once
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace zraster::cli {

struct Rgba {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

struct RgbaImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> pixels;  // width * height * 4

    RgbaImage() = default;
    RgbaImage(int w, int h, Rgba fill = {});
    // Alpha-blends `color` over pixel (x, y); outside the image nothing happens.
    void blend(int x, int y, Rgba color);
    Rgba at(int x, int y) const;
};

// Every pixel of [x0, x1) x [y0, y1) within the image, alpha-blended.
void fill_rect(RgbaImage& image, int x0, int y0, int x1, int y1, Rgba color);
// Bresenham's pixels (zraster's line rasterizer), `width` pixels thick.
void draw_line(RgbaImage& image, glm::dvec2 a, glm::dvec2 b, Rgba color, int width = 1);
// The pixels whose centers are inside the polygon (even-odd rule; any simple or self-crossing
// polygon), in window coordinates (pixel centers at +0.5).
void fill_polygon(RgbaImage& image, std::span<const glm::dvec2> polygon, Rgba color);
void outline_polygon(RgbaImage& image, std::span<const glm::dvec2> polygon, Rgba color,
                     int width = 1);
// `source` copied with its top-left corner at (x, y), scaled up `scale` times (nearest).
void paste(RgbaImage& image, const RgbaImage& source, int x, int y, int scale = 1);
// The RGB bytes (alpha dropped), as the command's PNGs store color.
std::vector<std::uint8_t> rgb_bytes(const RgbaImage& image);

}  // namespace zraster::cli
