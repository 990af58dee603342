// The legend of a debug view (--view) in the command's pictures: the view's color bar with its
// end values and a line saying what the colors mean, in the bottom-left corner. The library
// leaves the picture as pure data (every pixel checkable); the command, which writes it for a
// person, adds the legend and prints the same line to stderr.
#pragma once
#include <zraster/debug_view.hpp>

#include "rgba_image.hpp"

namespace zraster::cli {

// Draws the legend of `view` over the bottom-left corner of `image` (nothing for None).
void draw_debug_view_legend(RgbaImage& image, DebugView view, const DebugViewScale& scale);

}  // namespace zraster::cli
