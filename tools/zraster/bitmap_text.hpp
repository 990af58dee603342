// Text in images: stb_easy_font's small bitmap font (Sean Barrett, public domain), for the
// viewer's HUD and the labels of the explain pictures.
#pragma once
#include <string>

#include "rgba_image.hpp"

namespace zraster::cli {

// The height of a line of text at scale 1, in pixels.
inline constexpr int kTextLineHeight = 12;

// Draws `text` (ASCII; '\n' starts a new line) with its top-left corner at (x, y), every font
// pixel a scale x scale square. Clipped to the image.
void draw_text(RgbaImage& image, int x, int y, const std::string& text, Rgba color, int scale = 1);
// The width of the widest line of `text` at scale 1.
int text_width(const std::string& text);

}  // namespace zraster::cli
