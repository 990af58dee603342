// The HUD and the help overlay.
#include "view_hud.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "bitmap_text.hpp"

namespace zraster::cli {
namespace {

// Large windows get the font at twice its size, for legibility.
int text_scale(const RgbaImage& image) {
    return image.height >= 480 && image.width >= 800 ? 2 : 1;
}

}  // namespace

std::string hud_line(const ViewState& state, const FrameResult& frame, double fps) {
    const RenderArguments a = state.render_arguments();
    const RenderStats& s = frame.stats;
    std::string counts;
    if (a.visibility == "painter" || a.visibility == "bsp" || a.visibility == "warnock")
        counts = fmt::format("{} tris in, {} polygons", s.triangles_in, frame.polygons);
    else
        counts = fmt::format("{} tris in, {} culled, {} rasterized", s.triangles_in,
                             s.triangles_trivially_rejected + s.triangles_backface_culled,
                             s.triangles_rasterized);
    std::string line =
        fmt::format("{:.1f} ms {:.0f} fps | {} | {} | view {} | {} {}{}{}{}", frame.render_ms, fps,
                    counts, state.algorithm_name(), debug_view_name(state.debug_view()), a.shading,
                    a.reversed_z ? "reversed-Z" : a.depth_format, a.occlusion_cull ? " occl" : "",
                    a.no_cull || a.cull == "none" ? " nocull" : "",
                    a.wireframe ? " wire" : (a.hidden_line ? " hidden-line" : ""));
    const std::string note = state.note();
    if (!note.empty()) line += " | " + note;
    if (!frame.error.empty()) line += " | " + frame.error;
    return line;
}

void draw_hud(RgbaImage& image, const std::string& line) {
    const int scale = text_scale(image);
    const int height = (kTextLineHeight - 2) * scale;
    fill_rect(image, 0, 0, std::min(image.width, (text_width(line) + 6) * scale), height + 2,
              Rgba{0, 0, 0, 160});
    draw_text(image, 3 * scale, 2 * scale, line, Rgba{255, 255, 255, 255}, scale);
}

const std::string& help_text() {
    static const std::string text =
        "left drag     orbit\n"
        "right/middle  pan\n"
        "wheel         zoom\n"
        "1 2 3         flat, Gouraud, Phong shading\n"
        "v             visibility: z-buffer, painter's, BSP, Warnock, A-buffer\n"
        "a             antialiasing on/off\n"
        "w             edges: wireframe, hidden-line, none\n"
        "c             back-face culling on/off\n"
        "o             occlusion culling on/off\n"
        "z             depth: D32F, D24, D16, reversed-Z\n"
        "d             next debug view\n"
        "r             reset\n"
        "s             screenshot (zraster-view-N.png)\n"
        "h             this help\n"
        "q, Esc        quit";
    return text;
}

void draw_help(RgbaImage& image) {
    const int scale = text_scale(image);
    const std::string& text = help_text();
    const int lines = int(std::count(text.begin(), text.end(), '\n')) + 1;
    const int x = 10 * scale, y = 20 * scale;
    fill_rect(image, x - 6 * scale, y - 6 * scale, x + (text_width(text) + 6) * scale,
              y + (lines * kTextLineHeight + 6) * scale, Rgba{0, 0, 0, 190});
    draw_text(image, x, y, text, Rgba{255, 255, 160, 255}, scale);
}

}  // namespace zraster::cli
