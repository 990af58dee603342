// `zraster explain bresenham | dda`: the pixels chosen for a few lines on a grid, and the error
// term (Bresenham) or accumulated coordinate (DDA) of every step of the first line.
#include <zraster/lines.hpp>

#include <fmt/format.h>

#include <cmath>

#include "explain_algorithms.hpp"

namespace zraster::cli {
namespace {

constexpr int kColumns = 26, kRows = 14, kCell = 20;

const std::vector<std::pair<glm::ivec2, glm::ivec2>>& example_lines() {
    static const std::vector<std::pair<glm::ivec2, glm::ivec2>> lines = {
        {{1, 1}, {18, 7}}, {{3, 12}, {9, 2}}, {{12, 12}, {24, 10}}, {{20, 2}, {24, 9}}};
    return lines;
}

glm::dvec2 center(glm::dvec2 lattice) {
    return (lattice + 0.5) * double(kCell);
}

// The grid, and each line's pixels with its ideal line through the pixel centers.
template <typename Pixels>
Figure line_grid(Pixels pixels_of, const std::string& title) {
    Figure f(kColumns * kCell, kRows * kCell + 200);
    for (int y = 0; y < kRows; ++y)
        for (int x = 0; x < kColumns; ++x)
            f.rect(x * kCell, y * kCell, (x + 1) * kCell, (y + 1) * kCell,
                   FigureStyle{{0, 0, 0, 0}, {215, 215, 215, 255}});
    for (std::size_t k = 0; k < example_lines().size(); ++k) {
        const auto [a, b] = example_lines()[k];
        const Rgba color = k == 0 ? Rgba{60, 120, 230, 200} : Rgba{120, 170, 120, 200};
        for (const glm::ivec2 p : pixels_of(a, b))
            f.rect(p.x * kCell + 1, p.y * kCell + 1, (p.x + 1) * kCell - 1, (p.y + 1) * kCell - 1,
                   FigureStyle{color});
        f.line(center(a), center(b), {200, 30, 30, 255}, 1);
    }
    f.text({6, kRows * kCell + 6}, title);
    return f;
}

}  // namespace

void explain_bresenham(const ExplainInput&, ExplainOutput& out) {
    const auto [a, b] = example_lines()[0];
    const int dx = b.x - a.x, dy = b.y - a.y;
    std::string table = fmt::format(
        "first line (blue) ({},{}) to ({},{}): dx = {}, dy = {}; error e = 2 (dy (x - x0) - dx (y "
        "- y0)),\nkept within [-dx, dx] (a tie at +-dx goes up):\n",
        a.x, a.y, b.x, b.y, dx, dy);
    int column = 0;
    for (const glm::ivec2 p : bresenham_line(a, b)) {
        const int e = 2 * (dy * (p.x - a.x) - dx * (p.y - a.y));
        table +=
            fmt::format("x={:2} y={:2} e={:4}{}", p.x, p.y, e, ++column % 4 == 0 ? "\n" : "   ");
    }
    out.figure("bresenham",
               line_grid([](glm::ivec2 p, glm::ivec2 q) { return bresenham_line(p, q); }, table),
               "the pixels Bresenham's algorithm chooses for four lines (red: the ideal lines), "
               "and the error term at each step of the first");
}

void explain_dda(const ExplainInput&, ExplainOutput& out) {
    const auto [a, b] = example_lines()[0];
    const double slope = double(b.y - a.y) / double(b.x - a.x);
    std::string table = fmt::format(
        "first line (blue) ({},{}) to ({},{}): slope {:.4f}; y accumulated in floating point, "
        "pixel row = floor(y + 0.5):\n",
        a.x, a.y, b.x, b.y, slope);
    double y = a.y;
    int column = 0;
    for (const glm::ivec2 p : dda_line(glm::dvec2(a), glm::dvec2(b))) {
        table += fmt::format("x={:2} y={:7.4f} -> {:2}{}", p.x, y, p.y,
                             ++column % 4 == 0 ? "\n" : "   ");
        y += slope;
    }
    out.figure(
        "dda",
        line_grid([](glm::ivec2 p, glm::ivec2 q) { return dda_line(glm::dvec2(p), glm::dvec2(q)); },
                  table),
        "the pixels the DDA chooses for four lines (red: the ideal lines), and the "
        "accumulated y at each step of the first");
}

}  // namespace zraster::cli
