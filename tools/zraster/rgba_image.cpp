// Drawing into RGBA8 images.
#include "rgba_image.hpp"

#include <zraster/lines.hpp>

#include <algorithm>
#include <cmath>

namespace zraster::cli {

RgbaImage::RgbaImage(int w, int h, Rgba fill)
    : width(w), height(h), pixels(std::size_t(w) * std::size_t(h) * 4) {
    for (std::size_t i = 0; i < pixels.size(); i += 4) {
        pixels[i] = fill.r;
        pixels[i + 1] = fill.g;
        pixels[i + 2] = fill.b;
        pixels[i + 3] = fill.a;
    }
}

void RgbaImage::blend(int x, int y, Rgba color) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    std::uint8_t* p = &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    const int a = color.a;
    const auto mix = [a](int under, int over) {
        return std::uint8_t((over * a + under * (255 - a) + 127) / 255);
    };
    p[0] = mix(p[0], color.r);
    p[1] = mix(p[1], color.g);
    p[2] = mix(p[2], color.b);
    p[3] = std::uint8_t(std::max<int>(p[3], a));
}

Rgba RgbaImage::at(int x, int y) const {
    const std::uint8_t* p = &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
    return {p[0], p[1], p[2], p[3]};
}

void fill_rect(RgbaImage& image, int x0, int y0, int x1, int y1, Rgba color) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width);
    y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) image.blend(x, y, color);
}

void draw_line(RgbaImage& image, glm::dvec2 a, glm::dvec2 b, Rgba color, int width) {
    // Window coordinates to Bresenham's lattice (lines.hpp): minus half a pixel.
    const glm::ivec2 from(glm::floor(a)), to(glm::floor(b));
    const int limit = 1 << 20;  // far outside any picture: not drawn
    if (glm::any(glm::greaterThan(glm::abs(glm::dvec2(from)), glm::dvec2(limit))) ||
        glm::any(glm::greaterThan(glm::abs(glm::dvec2(to)), glm::dvec2(limit))))
        return;
    const int lo = -(width - 1) / 2, hi = width / 2;
    for (const glm::ivec2 p : bresenham_line(from, to))
        for (int dy = lo; dy <= hi; ++dy)
            for (int dx = lo; dx <= hi; ++dx) image.blend(p.x + dx, p.y + dy, color);
}

void fill_polygon(RgbaImage& image, std::span<const glm::dvec2> polygon, Rgba color) {
    if (polygon.size() < 3) return;
    double y_min = polygon[0].y, y_max = polygon[0].y;
    for (const glm::dvec2& p : polygon) {
        y_min = std::min(y_min, p.y);
        y_max = std::max(y_max, p.y);
    }
    const int row0 = std::max(0, int(std::floor(y_min))),
              row1 = std::min(image.height - 1, int(std::ceil(y_max)));
    std::vector<double> crossings;
    for (int y = row0; y <= row1; ++y) {
        const double center = y + 0.5;
        crossings.clear();
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const glm::dvec2 p = polygon[i], q = polygon[(i + 1) % polygon.size()];
            if ((p.y <= center) == (q.y <= center)) continue;  // half-open: no double count
            crossings.push_back(p.x + (center - p.y) / (q.y - p.y) * (q.x - p.x));
        }
        std::sort(crossings.begin(), crossings.end());
        for (std::size_t i = 0; i + 1 < crossings.size(); i += 2) {
            // Pixels whose centers x + 0.5 lie in [left, right).
            const int x0 = std::max(0, int(std::ceil(crossings[i] - 0.5)));
            const int x1 = std::min(image.width, int(std::ceil(crossings[i + 1] - 0.5)));
            for (int x = x0; x < x1; ++x) image.blend(x, y, color);
        }
    }
}

void outline_polygon(RgbaImage& image, std::span<const glm::dvec2> polygon, Rgba color, int width) {
    for (std::size_t i = 0; i < polygon.size(); ++i)
        draw_line(image, polygon[i], polygon[(i + 1) % polygon.size()], color, width);
}

void paste(RgbaImage& image, const RgbaImage& source, int x, int y, int scale) {
    for (int sy = 0; sy < source.height; ++sy)
        for (int sx = 0; sx < source.width; ++sx)
            fill_rect(image, x + sx * scale, y + sy * scale, x + (sx + 1) * scale,
                      y + (sy + 1) * scale, source.at(sx, sy));
}

std::vector<std::uint8_t> rgb_bytes(const RgbaImage& image) {
    std::vector<std::uint8_t> rgb(std::size_t(image.width) * std::size_t(image.height) * 3);
    for (std::size_t i = 0, j = 0; j < rgb.size(); i += 4, j += 3) {
        rgb[j] = image.pixels[i];
        rgb[j + 1] = image.pixels[i + 1];
        rgb[j + 2] = image.pixels[i + 2];
    }
    return rgb;
}

}  // namespace zraster::cli
