// stb_easy_font makes quads (axis-aligned rectangles) for the glyphs; they are filled here.
#include "bitmap_text.hpp"

#include <cstring>
#include <vector>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace zraster::cli {
namespace {

// stb_easy_font's vertex: x, y, z and an RGBA color (unused: the caller's color is drawn).
struct FontVertex {
    float x, y, z;
    unsigned char color[4];
};
static_assert(sizeof(FontVertex) == 16);

}  // namespace

void draw_text(RgbaImage& image, int x, int y, const std::string& text, Rgba color, int scale) {
    // About 270 bytes per character (stb_easy_font's worst case).
    std::vector<FontVertex> vertices(text.size() * 70 + 64);
    std::string copy = text;
    const int quads = stb_easy_font_print(0.0f, 0.0f, copy.data(), nullptr, vertices.data(),
                                          int(vertices.size() * sizeof(FontVertex)));
    for (int q = 0; q < quads; ++q) {
        const FontVertex& a = vertices[std::size_t(q) * 4];
        const FontVertex& c = vertices[std::size_t(q) * 4 + 2];
        fill_rect(image, x + int(a.x) * scale, y + int(a.y) * scale, x + int(c.x) * scale,
                  y + int(c.y) * scale, color);
    }
}

int text_width(const std::string& text) {
    std::string copy = text;
    return stb_easy_font_width(copy.data());
}

}  // namespace zraster::cli
