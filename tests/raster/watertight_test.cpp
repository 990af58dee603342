// Watertightness of the edge-function rasterizer: triangles sharing an edge never leave a gap
// and never both claim a pixel, for many random orientations, including vertices and edges
// exactly on pixel centers.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "raster/raster_test_util.hpp"

namespace zraster::test {
namespace {

// True when point p is inside the convex polygon (counter-clockwise or clockwise) by at least
// margin pixels from every edge.
bool strictly_inside(const std::vector<glm::dvec2>& poly, glm::dvec2 p, double margin) {
    double sign = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const glm::dvec2 e = b - a;
        const double cross = e.x * (p.y - a.y) - e.y * (p.x - a.x);
        const double distance = cross / glm::length(e);
        if (sign == 0.0) sign = distance > 0 ? 1.0 : -1.0;
        if (distance * sign < margin) return false;
    }
    return true;
}

bool strictly_convex(const std::vector<glm::dvec2>& poly) {
    int positive = 0, negative = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()],
                         c = poly[(i + 2) % poly.size()];
        const double cross = (b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x);
        positive += cross > 0;
        negative += cross < 0;
    }
    return positive == int(poly.size()) || negative == int(poly.size());
}

TEST(Watertight, RandomQuadsSplitAlongADiagonal) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    constexpr int kSize = 48;
    int gaps = 0, double_hits = 0, shared_edge_pixels = 0, quads = 0;
    for (int iteration = 0; iteration < 4000; ++iteration) {
        const bool on_grid = iteration % 2 == 0;  // half the cases: coordinates on half pixels
        const glm::dvec2 center(8 + 32 * unit(rng), 8 + 32 * unit(rng));
        const double rx = 1 + 18 * unit(rng), ry = 1 + 18 * unit(rng), rot = 6.3 * unit(rng);
        double angles[4];
        for (double& a : angles) a = 6.283185307179586 * unit(rng);
        std::sort(angles, angles + 4);
        std::vector<glm::dvec2> quad;
        for (double a : angles) {
            glm::dvec2 p(rx * std::cos(a), ry * std::sin(a));
            p = glm::dvec2(p.x * std::cos(rot) - p.y * std::sin(rot),
                           p.x * std::sin(rot) + p.y * std::cos(rot)) +
                center;
            if (on_grid) p = glm::round(p * 2.0) / 2.0;
            quad.push_back(p);
        }
        // Rounding to half pixels can make the quad non-convex; then its two triangles overlap
        // by construction, which is not what this test is about.
        if (!strictly_convex(quad)) continue;
        ++quads;
        CoverageGrid g(kSize, kSize);
        rasterize_window_triangle(g, quad[0], quad[1], quad[2]);
        rasterize_window_triangle(g, quad[0], quad[2], quad[3]);
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const int h = g.at(x, y);
                if (h > 1) ++double_hits;
                const glm::dvec2 c(x + 0.5, y + 0.5);
                if (h == 0 && quad.size() == 4 && strictly_inside(quad, c, 0.01)) ++gaps;
                // Pixels whose center is on the shared diagonal: the interesting ones.
                const glm::dvec2 d = quad[2] - quad[0];
                if (std::abs(d.x * (c.y - quad[0].y) - d.y * (c.x - quad[0].x)) < 1e-9 && h)
                    ++shared_edge_pixels;
            }
    }
    EXPECT_GT(quads, 3500);
    EXPECT_EQ(gaps, 0);
    EXPECT_EQ(double_hits, 0);
    EXPECT_GT(shared_edge_pixels, 100) << "the test should exercise centers exactly on the edge";
}

TEST(Watertight, JitteredGridMeshCoversEveryPixelOnce) {
    // A 16x16-cell grid over the whole viewport with jittered interior vertices, each cell split
    // along a random diagonal: every pixel is covered exactly once.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(-1.4, 1.4);
    constexpr int kSize = 64, kCells = 16;
    const double step = double(kSize) / kCells;
    std::vector<glm::dvec2> v((kCells + 1) * (kCells + 1));
    for (int j = 0; j <= kCells; ++j)
        for (int i = 0; i <= kCells; ++i) {
            glm::dvec2 p(i * step, j * step);
            if (i > 0 && i < kCells) p.x += jitter(rng);
            if (j > 0 && j < kCells) p.y += jitter(rng);
            v[std::size_t(j * (kCells + 1) + i)] = p;
        }
    CoverageGrid g(kSize, kSize);
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
            const auto at = [&](int di, int dj) {
                return v[std::size_t((j + dj) * (kCells + 1) + i + di)];
            };
            if (rng() & 1) {
                rasterize_window_triangle(g, at(0, 0), at(1, 0), at(1, 1));
                rasterize_window_triangle(g, at(0, 0), at(1, 1), at(0, 1));
            } else {
                rasterize_window_triangle(g, at(0, 0), at(1, 0), at(0, 1));
                rasterize_window_triangle(g, at(1, 0), at(1, 1), at(0, 1));
            }
        }
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) ASSERT_EQ(g.at(x, y), 1) << x << "," << y;
}

}  // namespace
}  // namespace zraster::test
