// See debug_view_legend.hpp.
#include "debug_view_legend.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "bitmap_text.hpp"

namespace zraster::cli {
namespace {

constexpr int kMargin = 4;
constexpr int kBarHeight = 8;
constexpr Rgba kPanel{0, 0, 0, 176};
constexpr Rgba kText{255, 255, 255, 255};

std::string end_value(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

}  // namespace

void draw_debug_view_legend(RgbaImage& image, DebugView view, const DebugViewScale& scale) {
    if (view == DebugView::None) return;
    const std::string line = debug_view_legend(view, scale);
    const bool bar = debug_view_has_scale(view);
    const int bar_width = std::clamp(image.width / 3, 16, 256);
    const int width = std::max(text_width(line), bar ? bar_width : 0) + 2 * kMargin;
    const int height =
        kTextLineHeight * (bar ? 2 : 1) + (bar ? kBarHeight + kMargin : 0) + 2 * kMargin;
    const int x0 = 0, y0 = image.height - height;
    fill_rect(image, x0, y0, x0 + width, image.height, kPanel);
    int y = y0 + kMargin;
    draw_text(image, x0 + kMargin, y, line, kText);
    if (!bar) return;
    y += kTextLineHeight;
    for (int i = 0; i < bar_width; ++i) {
        const auto rgb = debug_view_scale_color(double(i) / double(bar_width - 1));
        fill_rect(image, x0 + kMargin + i, y, x0 + kMargin + i + 1, y + kBarHeight,
                  Rgba{rgb[0], rgb[1], rgb[2], 255});
    }
    y += kBarHeight + 2;
    // Depth puts near (the low end) at yellow, the bar's right end.
    const bool near_right = view == DebugView::Depth;
    const std::string left = end_value(near_right ? scale.high : scale.low);
    const std::string right = end_value(near_right ? scale.low : scale.high);
    draw_text(image, x0 + kMargin, y, left, kText);
    draw_text(image, x0 + kMargin + bar_width - text_width(right), y, right, kText);
}

}  // namespace zraster::cli
