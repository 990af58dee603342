// The viewer's overlays: the one-line HUD (timing, triangle counts, algorithm, view) and the
// help text of the h key, drawn into the frame before it is shown.
#pragma once
#include <string>

#include "rgba_image.hpp"
#include "view_state.hpp"
#include "view_worker.hpp"

namespace zraster::cli {

// "12.3 ms 81 fps | 69666 tris in, 34512 culled, 30122 rasterized | z-buffer | view none | ..."
// fps: frames shown per second (measured by the window), not the inverse of the render time.
std::string hud_line(const ViewState& state, const FrameResult& frame, double fps);
void draw_hud(RgbaImage& image, const std::string& line);
void draw_help(RgbaImage& image);
// The key and mouse bindings, one per line (the help overlay and docs/viewer.md).
const std::string& help_text();

}  // namespace zraster::cli
