// Wireframe and hidden-line drawing: the edges of the triangles the front end kept, as
// Bresenham lines (Bresenham 1965) from their snapped window positions, with window depth
// interpolated along the line.
//
// Hidden-line: an edge pixel shows when its depth is not behind the surface depth at that pixel
// by more than a slope-scaled offset (OpenGL's polygon offset idea, applied to the line instead
// of the surface): the line's pixels are lattice points up to half a pixel from the pixel center
// where the surface depth was evaluated, so the offset is half the triangle's depth change per
// pixel in x plus in y, plus a small constant. Back edges are then hidden by the front surfaces.
//
// Cost: O(total edge length inside the image, in pixels), one thread, after the tiles (edges
// cross tiles).
#include <zraster/lines.hpp>

#include <cmath>

#include "render/frame.hpp"

namespace zraster::detail {
namespace {

glm::ivec2 lattice_point(const ScreenVertex& v) {
    // Pixel (x, y) has its center at (x + 0.5, y + 0.5): the nearest pixel to the vertex.
    return {static_cast<int>(std::floor(double(v.x) / double(kSubpixelScale))),
            static_cast<int>(std::floor(double(v.y) / double(kSubpixelScale)))};
}

}  // namespace

void draw_edges(Frame& frame) {
    const RenderOptions& options = *frame.options;
    const TargetViews& targets = frame.targets.views;
    const bool hidden_line = options.edges == RenderOptions::Edges::HiddenLine;
    const bool reversed = effective_depth_compare(options) == CompareFunc::Greater ||
                          effective_depth_compare(options) == CompareFunc::GreaterEqual;
    const int width = targets.width, height = targets.height;
    std::uint8_t rgba[4];
    for (int c = 0; c < 3; ++c)
        rgba[c] = static_cast<std::uint8_t>(
            std::lround(std::fmin(std::fmax(options.edge_color[c], 0.0f), 1.0f) * 255.0f));
    rgba[3] = 255;

    if (!hidden_line && targets.color != nullptr) {  // wireframe: the surfaces are not shown
        const std::uint8_t bg[4] = {
            static_cast<std::uint8_t>(
                std::lround(std::fmin(std::fmax(options.background.x, 0.f), 1.f) * 255)),
            static_cast<std::uint8_t>(
                std::lround(std::fmin(std::fmax(options.background.y, 0.f), 1.f) * 255)),
            static_cast<std::uint8_t>(
                std::lround(std::fmin(std::fmax(options.background.z, 0.f), 1.f) * 255)),
            255};
        for (int y = 0; y < height; ++y) {
            std::uint8_t* row = target_row(targets.color, targets.color_pitch, y);
            for (int x = 0; x < width; ++x) std::copy(bg, bg + 4, row + std::size_t(x) * 4);
        }
    }
    if (targets.color == nullptr) return;

    std::vector<LinePixel>& line = frame.line;  // (kept: its capacity serves the next frame)
    TriangleSetup setup;
    for (const Chunk& chunk : frame.chunks)
        for (const TriangleRef& ref : chunk.refs) {
            const std::array<ScreenVertex, 3> v{frame.screen_vertex(chunk, ref, 0),
                                                frame.screen_vertex(chunk, ref, 1),
                                                frame.screen_vertex(chunk, ref, 2)};
            float offset = 0.0f;
            if (hidden_line) {
                if (setup_triangle(v, frame.setup_settings, setup) != SetupResult::Visible)
                    continue;
                offset = 0.5f * (std::fabs(setup.depth.a) + std::fabs(setup.depth.b)) + 1e-6f;
            }
            for (int k = 0; k < 3; ++k) {
                const ScreenVertex& a = v[static_cast<std::size_t>(k)];
                const ScreenVertex& b = v[static_cast<std::size_t>((k + 1) % 3)];
                line.clear();
                bresenham_line_depth_in(lattice_point(a), a.z, lattice_point(b), b.z, width, height,
                                        line);
                for (const LinePixel& p : line) {
                    if (hidden_line) {
                        const float surface =
                            target_row(targets.depth, targets.depth_pitch, p.y)[p.x];
                        const bool visible =
                            reversed ? p.depth >= surface - offset : p.depth <= surface + offset;
                        if (!visible) continue;
                    }
                    std::copy(
                        rgba, rgba + 4,
                        target_row(targets.color, targets.color_pitch, p.y) + std::size_t(p.x) * 4);
                }
            }
        }
}

}  // namespace zraster::detail
