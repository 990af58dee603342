// `zraster explain abuffer`: one pixel's fragment list and coverage masks, zoomed. The masks are
// the A-buffer's own (polygon_coverage, which render_abuffer uses to build its lists).
#include <zraster/abuffer.hpp>
#include <zraster/visibility.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <bit>

#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

// One fragment of a pixel's list (24 bytes: the A-buffer's own size per fragment).
struct PixelFragment {
    std::uint32_t polygon;
    std::uint32_t next;  // the pixel's next fragment, kEnd at the end
    std::uint64_t mask;
    double depth;
};

// The polygon's window depth at (x, y), from the plane through its first three vertices.
double depth_at(const ScreenPolygon& p, double x, double y) {
    const glm::dvec3 a = p.vertices[0].window, b = p.vertices[1].window, c = p.vertices[2].window;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (n.z == 0.0) return a.z;
    return a.z - (n.x * (x - a.x) + n.y * (y - a.y)) / n.z;
}

Rgba to_rgba(const glm::vec3& c) {
    const auto b = [](float v) {
        return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    return {b(c.x), b(c.y), b(c.z), 255};
}

// Draws an n x n sample grid at (x, y), cells of `cell` pixels, the samples of `mask` filled.
void mask_grid(Figure& f, double x, double y, int n, double cell, std::uint64_t mask, Rgba color) {
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const bool covered = (mask >> (j * n + i)) & 1u;
            f.rect(
                x + i * cell, y + j * cell, x + (i + 1) * cell, y + (j + 1) * cell,
                FigureStyle{covered ? color : Rgba{245, 245, 245, 255}, Rgba{120, 120, 120, 255}});
        }
}

}  // namespace

void explain_abuffer(const ExplainInput& in, ExplainOutput& out) {
    const int n = in.arguments.aa > 1 ? in.arguments.aa : 4;
    const int w = in.options.width, h = in.options.height;
    // The frame with its zoomed inset, and the lists' heads (one per pixel).
    check_explain_pixels(1,
                         (std::uint64_t(w) + 128) * std::uint64_t(std::max(h, 120)) +
                             std::uint64_t(w) * std::uint64_t(h),
                         in.max_pixels, "explain abuffer's picture and per-pixel lists");
    // The frame first: the A-buffer refuses fragments past its budget (--max-abuffer-fragments)
    // before storing them, and frees its own when done. The lists below hold the same fragments
    // (polygon_coverage's masks are the ones it stores), so they are within the budget too, and
    // allocated once at their size.
    ABufferOptions abuffer;
    abuffer.samples_per_side = n;
    abuffer.max_fragments = in.arguments.max_abuffer_fragments;
    ABufferStats counted;
    const RenderResult frame = render_abuffer(in.scene, in.options, abuffer, &counted);
    const std::vector<ScreenPolygon> polygons = project_scene(in.scene, in.options, true);
    constexpr std::uint32_t kEnd = 0xffffffffu;
    std::vector<std::uint32_t> head(std::size_t(w) * std::size_t(h), kEnd);
    std::vector<PixelFragment> fragments;
    fragments.reserve(counted.fragments);
    for (std::size_t i = 0; i < polygons.size(); ++i)
        for (const PixelCoverage& c : polygon_coverage(polygons[i], Viewport{w, h}, n)) {
            const std::size_t p = std::size_t(c.y) * std::size_t(w) + std::size_t(c.x);
            fragments.push_back(
                {std::uint32_t(i), head[p], c.mask, depth_at(polygons[i], c.x + 0.5, c.y + 0.5)});
            head[p] = std::uint32_t(fragments.size() - 1);
        }
    // An edge pixel a slide can show: a partly covered fragment over a farther surface, and a
    // short list (about three fragments; sphere poles gather dozens).
    const std::uint64_t full = n == 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (n * n)) - 1;
    std::size_t best = 0, best_score = 0;
    for (std::size_t p = 0; p < head.size(); ++p) {
        std::size_t size = 0;
        bool partial = false;
        double nearest = 0.0, farthest = 0.0;
        for (std::uint32_t f = head[p]; f != kEnd; f = fragments[f].next) {
            const PixelFragment& fragment = fragments[f];
            partial |= fragment.mask != full;
            nearest = size == 0 ? fragment.depth : std::min(nearest, fragment.depth);
            farthest = size == 0 ? fragment.depth : std::max(farthest, fragment.depth);
            ++size;
        }
        if (size < 2) continue;
        const bool layered = farthest - nearest > 1e-3;
        const std::size_t score = (partial ? 100 : 0) + (layered ? 50 : 0) +
                                  (size <= 6 ? 10 + std::min<std::size_t>(size, 4) : 0);
        if (score > best_score) {
            best = p;
            best_score = score;
        }
    }
    std::vector<PixelFragment> list;
    for (std::uint32_t f = head.empty() ? kEnd : head[best]; f != kEnd; f = fragments[f].next)
        list.push_back(fragments[f]);
    std::reverse(list.begin(), list.end());  // (in the order they were made, as before the sort)
    std::sort(list.begin(), list.end(),
              [](const PixelFragment& a, const PixelFragment& b) { return a.depth < b.depth; });
    const int px = int(best % std::size_t(w)), py = int(best / std::size_t(w));

    RgbaImage image = color_image(frame.targets);
    const int zoom = 8, around = 7;
    RgbaImage inset(2 * around + 1, 2 * around + 1, Rgba{0, 0, 0, 255});
    for (int y = -around; y <= around; ++y)
        for (int x = -around; x <= around; ++x)
            if (px + x >= 0 && py + y >= 0 && px + x < w && py + y < h)
                inset.blend(x + around, y + around, image.at(px + x, py + y));
    RgbaImage picture(w + inset.width * zoom + 8, std::max(h, inset.height * zoom),
                      Rgba{255, 255, 255, 255});
    paste(picture, image, 0, 0);
    outline_polygon(picture,
                    std::vector<glm::dvec2>{
                        {px - 3, py - 3}, {px + 3, py - 3}, {px + 3, py + 3}, {px - 3, py + 3}},
                    Rgba{255, 0, 0, 255});
    paste(picture, inset, w + 8, 0, zoom);
    outline_polygon(
        picture,
        std::vector<glm::dvec2>{{w + 8 + around * zoom, around * zoom},
                                {w + 8 + (around + 1) * zoom - 1, around * zoom},
                                {w + 8 + (around + 1) * zoom - 1, (around + 1) * zoom - 1},
                                {w + 8 + around * zoom, (around + 1) * zoom - 1}},
        Rgba{255, 0, 0, 255});
    out.still("abuffer-pixel",
              captioned(picture, fmt::format("the A-buffer's frame ({}x{} samples per pixel); "
                                             "pixel ({}, {}) marked, zoomed on the right",
                                             n, n, px, py)),
              "the frame and the chosen pixel, on an edge where fragments cover it partly");

    const double cell = 64.0 / n;
    Figure f(40 + 150 * int(list.size() + 1), 200);
    f.text({10, 8}, fmt::format("pixel ({}, {}): {} fragments, nearest first; each grid is the "
                                "polygon's coverage mask of {} samples",
                                px, py, list.size(), n * n));
    std::uint64_t taken = 0;
    std::vector<Rgba> sample_color(std::size_t(n * n), Rgba{200, 200, 200, 255});
    for (std::size_t k = 0; k < list.size(); ++k) {
        const ScreenPolygon& p = polygons[list[k].polygon];
        const double x = 20 + 150.0 * double(k);
        mask_grid(f, x, 40, n, cell, list[k].mask, to_rgba(p.color));
        f.text({x, 112}, fmt::format("z = {:.5f}\n{} of {} samples\ntriangle {}", list[k].depth,
                                     std::popcount(list[k].mask), n * n, p.primitive));
        // Opaque surfaces: each sample takes the nearest fragment covering it.
        for (int s = 0; s < n * n; ++s)
            if (((list[k].mask >> s) & 1u) && !((taken >> s) & 1u))
                sample_color[std::size_t(s)] = to_rgba(p.color);
        taken |= list[k].mask;
    }
    const double x = 20 + 150.0 * double(list.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            f.rect(x + i * cell, 40 + j * cell, x + (i + 1) * cell, 40 + (j + 1) * cell,
                   FigureStyle{sample_color[std::size_t(j * n + i)], Rgba{120, 120, 120, 255}});
    f.text({x, 112}, "resolved: each sample\ntakes the nearest\nfragment covering it");
    out.figure("abuffer-fragments", f,
               "the pixel's fragment list sorted by depth, each with its coverage mask, and the "
               "samples resolved front to back (flat colors; the frame shades each fragment)");
}

}  // namespace zraster::cli
