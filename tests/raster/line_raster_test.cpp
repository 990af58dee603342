// Line rasterization: Bresenham against the endpoint and tie rule of lines.hpp, checked with exact
// integer arithmetic in all eight octants; the DDA against Bresenham (equal except on exact ties,
// which are counted); the depth-interpolating variant.
#include <zraster/lines.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace zraster {
namespace {

using I64 = std::int64_t;

struct Segment {
    glm::ivec2 a, b;
};

// Random segments in octant `octant` (0..7): the signs of dx, dy and whether |dx| >= |dy|.
std::vector<Segment> octant_segments(int octant, int count, int range, std::mt19937_64& rng) {
    std::uniform_int_distribution<int> coord(-range, range);
    std::vector<Segment> out;
    while (static_cast<int>(out.size()) < count) {
        const glm::ivec2 a(coord(rng), coord(rng)), b(coord(rng), coord(rng));
        const int dx = b.x - a.x, dy = b.y - a.y;
        const int o = (dx < 0 ? 4 : 0) + (dy < 0 ? 2 : 0) + (std::abs(dx) >= std::abs(dy) ? 1 : 0);
        if (o == octant) out.push_back({a, b});
    }
    return out;
}

// 2 * dmajor * (signed minor distance from the pixel to the ideal line), exactly: positive when
// the pixel is on the larger-coordinate side. |value| <= |dmajor| means within half a pixel.
I64 twice_scaled_offset(const Segment& s, glm::ivec2 p, bool x_major) {
    const I64 dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const I64 rx = p.x - s.a.x, ry = p.y - s.a.y;
    // x-major: (y - ideal_y) * dx = ry * dx - rx * dy; the sign of dx is folded in below.
    const I64 num = x_major ? ry * dx - rx * dy : rx * dy - ry * dx;
    const I64 d_major = x_major ? dx : dy;
    return 2 * (d_major < 0 ? -num : num);
}

void check_bresenham(const Segment& s) {
    const std::vector<glm::ivec2> px = bresenham_line(s.a, s.b);
    const I64 dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const bool x_major = std::llabs(dx) >= std::llabs(dy);
    const I64 n = std::max(std::llabs(dx), std::llabs(dy));
    const auto where = [&] {
        return testing::Message() << "(" << s.a.x << "," << s.a.y << ")-(" << s.b.x << "," << s.b.y
                                  << ")";
    };
    ASSERT_EQ(static_cast<I64>(px.size()), n + 1) << where();
    EXPECT_EQ(px.front(), s.a) << where();
    EXPECT_EQ(px.back(), s.b) << where();
    for (std::size_t i = 0; i < px.size(); ++i) {
        if (i > 0) {
            const glm::ivec2 step = px[i] - px[i - 1];
            // 8-connected, and exactly one pixel per major coordinate.
            ASSERT_LE(std::abs(step.x), 1) << where();
            ASSERT_LE(std::abs(step.y), 1) << where();
            ASSERT_EQ(std::abs(x_major ? step.x : step.y), 1) << where();
        }
        // Within half a pixel of the ideal line in the minor axis (exact, no epsilon needed),
        // and a tie goes to the larger minor coordinate.
        const I64 off = twice_scaled_offset(s, px[i], x_major);
        ASSERT_LE(std::llabs(off), n) << where() << " pixel " << i;
        if (n > 0 && std::llabs(off) == n) {
            ASSERT_GT(off, 0) << where() << " tie broken downwards";
        }
    }
    // Symmetric: b -> a is the same pixel list, reversed.
    std::vector<glm::ivec2> back = bresenham_line(s.b, s.a);
    std::reverse(back.begin(), back.end());
    ASSERT_EQ(back, px) << where();
}

TEST(Bresenham, AllOctantsOnRandomSegments) {
    std::mt19937_64 rng(1965);
    for (int octant = 0; octant < 8; ++octant) {
        for (const Segment& s : octant_segments(octant, 1500, 40, rng)) check_bresenham(s);
        for (const Segment& s : octant_segments(octant, 300, 3000, rng)) check_bresenham(s);
        if (HasFatalFailure()) return;
    }
}

TEST(Bresenham, AxisAlignedDiagonalAndPointSegments) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> coord(-100, 100);
    for (int k = 0; k < 500; ++k) {
        const glm::ivec2 a(coord(rng), coord(rng));
        const int len = coord(rng);
        for (const glm::ivec2 b : {a, a + glm::ivec2(len, 0), a + glm::ivec2(0, len),
                                   a + glm::ivec2(len, len), a + glm::ivec2(len, -len)})
            check_bresenham({a, b});
    }
    EXPECT_EQ(bresenham_line({3, -4}, {3, -4}), std::vector<glm::ivec2>{glm::ivec2(3, -4)});
    const std::vector<glm::ivec2> vertical{{2, 5}, {2, 4}, {2, 3}};
    EXPECT_EQ(bresenham_line({2, 5}, {2, 3}), vertical);
}

TEST(Bresenham, TiesGoToTheLargerMinorCoordinateInBothDirections) {
    // (0,0)-(2,1): at x = 1 the ideal y is 0.5, a tie: pixel (1, 1) both ways.
    const std::vector<glm::ivec2> expected{{0, 0}, {1, 1}, {2, 1}};
    EXPECT_EQ(bresenham_line({0, 0}, {2, 1}), expected);
    const std::vector<glm::ivec2> reversed{{2, 1}, {1, 1}, {0, 0}};
    EXPECT_EQ(bresenham_line({2, 1}, {0, 0}), reversed);
    // Going down in y: (0,1)-(2,0) has the tie at x = 1 too, again resolved to y = 1.
    const std::vector<glm::ivec2> down{{0, 1}, {1, 1}, {2, 0}};
    EXPECT_EQ(bresenham_line({0, 1}, {2, 0}), down);
    // y-major: (0,0)-(1,2) ties at y = 1 (ideal x = 0.5), goes to x = 1.
    const std::vector<glm::ivec2> steep{{0, 0}, {1, 1}, {1, 2}};
    EXPECT_EQ(bresenham_line({0, 0}, {1, 2}), steep);
}

TEST(Bresenham, AppendsToTheCallersBuffer) {
    std::vector<glm::ivec2> buffer{{9, 9}};
    bresenham_line({0, 0}, {3, 0}, buffer);
    bresenham_line({0, 0}, {0, 1}, buffer);
    EXPECT_EQ(buffer.size(), 1u + 4u + 2u);
    EXPECT_EQ(buffer[0], glm::ivec2(9, 9));
    EXPECT_EQ(buffer[5], glm::ivec2(0, 0));
}

TEST(Bresenham, DepthIsInterpolatedAndBitIdenticalInBothDirections) {
    std::mt19937_64 rng(42);
    std::uniform_int_distribution<int> coord(-200, 200);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f);
    for (int k = 0; k < 2000; ++k) {
        const glm::ivec2 a(coord(rng), coord(rng)), b(coord(rng), coord(rng));
        const float za = depth(rng), zb = depth(rng);
        const std::vector<LinePixel> fwd = bresenham_line_depth(a, za, b, zb);
        const std::vector<LinePixel> bwd = bresenham_line_depth(b, zb, a, za);
        const std::vector<glm::ivec2> pixels = bresenham_line(a, b);
        ASSERT_EQ(fwd.size(), pixels.size());
        ASSERT_EQ(bwd.size(), pixels.size());
        const bool x_major = std::abs(b.x - a.x) >= std::abs(b.y - a.y);
        for (std::size_t i = 0; i < fwd.size(); ++i) {
            const LinePixel& f = fwd[i];
            const LinePixel& r = bwd[bwd.size() - 1 - i];
            ASSERT_EQ(glm::ivec2(f.x, f.y), pixels[i]);
            ASSERT_EQ(glm::ivec2(r.x, r.y), pixels[i]);
            ASSERT_EQ(f.depth, r.depth) << "not bit-identical at pixel " << i;  // exactly
            if (a == b) continue;
            const double t =
                x_major ? double(f.x - a.x) / (b.x - a.x) : double(f.y - a.y) / (b.y - a.y);
            ASSERT_NEAR(f.depth, za + (zb - za) * t, 1e-6);
        }
        if (a != b) {
            EXPECT_EQ(fwd.front().depth, za);
            EXPECT_EQ(fwd.back().depth, zb);
        }
    }
    const std::vector<LinePixel> point = bresenham_line_depth({1, 2}, 0.7f, {1, 2}, 0.3f);
    ASSERT_EQ(point.size(), 1u);
    EXPECT_EQ(point[0].depth, 0.3f);
}

// The pixels of a line inside a window, found without walking the rest, are the whole line's
// pixels there, in order and bit for bit: random lines whose endpoints lie inside, outside and
// far outside (200,000 pixels away) a small window, in every octant, ties included.
TEST(Bresenham, DepthInsideAWindowIsTheWholeLinesThere) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> near(-40, 80), far(-200000, 200000);
    std::uniform_real_distribution<float> depth(0.0f, 1.0f);
    constexpr int kWidth = 48, kHeight = 32;
    for (int k = 0; k < 4000; ++k) {
        auto& coord = k % 20 == 19 ? far : near;  // (a long whole walk now and then)
        const glm::ivec2 a(coord(rng), near(rng)), b(coord(rng), coord(rng));
        const float za = depth(rng), zb = depth(rng);
        std::vector<LinePixel> expected;
        for (const LinePixel& p : bresenham_line_depth(a, za, b, zb))
            if (p.x >= 0 && p.y >= 0 && p.x < kWidth && p.y < kHeight) expected.push_back(p);
        std::vector<LinePixel> got = {{-1, -1, 0.5f}};  // appended to what is there
        bresenham_line_depth_in(a, za, b, zb, kWidth, kHeight, got);
        ASSERT_EQ(got.size(), expected.size() + 1) << k;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            ASSERT_EQ(got[i + 1].x, expected[i].x) << k;
            ASSERT_EQ(got[i + 1].y, expected[i].y) << k;
            ASSERT_EQ(got[i + 1].depth, expected[i].depth) << k;
        }
    }
}

// True when pixel i of the integer segment s lies on an exact tie (ideal minor coordinate exactly
// half-way between two pixels).
bool is_tie(const Segment& s, glm::ivec2 p) {
    const I64 dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
    const bool x_major = std::llabs(dx) >= std::llabs(dy);
    const I64 n = std::max(std::llabs(dx), std::llabs(dy));
    return n > 0 && std::llabs(twice_scaled_offset(s, p, x_major)) == n;
}

TEST(Dda, AgreesWithBresenhamExceptOnExactTies) {
    std::mt19937_64 rng(1973);
    long long pixels = 0, ties = 0, disagreements = 0;
    for (int octant = 0; octant < 8; ++octant) {
        for (int range : {20, 500, 5000}) {
            for (const Segment& s : octant_segments(octant, 1000, range, rng)) {
                const std::vector<glm::ivec2> exact = bresenham_line(s.a, s.b);
                const std::vector<glm::ivec2> dda = dda_line(glm::dvec2(s.a), glm::dvec2(s.b));
                ASSERT_EQ(dda.size(), exact.size());
                for (std::size_t i = 0; i < exact.size(); ++i) {
                    const bool tie = is_tie(s, exact[i]);
                    ties += tie;
                    ++pixels;
                    if (dda[i] == exact[i]) continue;
                    ++disagreements;
                    // Only on a tie, and then the DDA took the other of the two nearest pixels.
                    ASSERT_TRUE(tie) << "(" << s.a.x << "," << s.a.y << ")-(" << s.b.x << ","
                                     << s.b.y << ") pixel " << i;
                    ASSERT_EQ(std::abs(dda[i].x - exact[i].x) + std::abs(dda[i].y - exact[i].y), 1);
                }
            }
        }
    }
    RecordProperty("pixels", std::to_string(pixels));
    RecordProperty("ties", std::to_string(ties));
    RecordProperty("disagreements", std::to_string(disagreements));
    std::printf("DDA vs Bresenham: %lld pixels, %lld exact ties, %lld disagreements\n", pixels,
                ties, disagreements);
    // Every disagreement is a tie (checked above). Ties are rare (this set: ~0.07% of pixels,
    // mostly on the short segments), and the DDA resolves about two thirds of them like Bresenham
    // (whenever the accumulated sum happens to be exact or to round upwards).
    EXPECT_GT(ties, 0);
    EXPECT_LE(disagreements, ties);
    EXPECT_LT(ties, pixels / 1000);
}

TEST(Dda, TieComputedExactlyIsResolvedLikeBresenham) {
    // Slope 1/2 is exact in binary: the sum hits 0.5 exactly and rounds half up.
    EXPECT_EQ(dda_line({0.0, 0.0}, {2.0, 1.0}), bresenham_line({0, 0}, {2, 1}));
    EXPECT_EQ(dda_line({2.0, 1.0}, {0.0, 0.0}), bresenham_line({2, 1}, {0, 0}));
}

TEST(Dda, RealEndpointsGiveConnectedPixelsNearTheLine) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> coord(-300.0, 300.0);
    for (int k = 0; k < 5000; ++k) {
        const glm::dvec2 a(coord(rng), coord(rng));
        const glm::dvec2 b = k % 10 == 0 ? a + glm::dvec2(coord(rng) / 1000.0, 0.0)
                                         : glm::dvec2(coord(rng), coord(rng));
        const std::vector<glm::ivec2> px = dda_line(a, b);
        const glm::dvec2 d = b - a;
        const bool x_major = std::abs(d.x) >= std::abs(d.y);
        const double a_major = x_major ? a.x : a.y, b_major = x_major ? b.x : b.y;
        const int first = static_cast<int>(std::floor(a_major + 0.5));
        const int last = static_cast<int>(std::floor(b_major + 0.5));
        ASSERT_EQ(static_cast<int>(px.size()), std::abs(last - first) + 1);
        for (std::size_t i = 0; i < px.size(); ++i) {
            const glm::ivec2 p = px[i];
            EXPECT_EQ(x_major ? p.x : p.y, first + (last >= first ? 1 : -1) * static_cast<int>(i));
            if (i > 0) {
                ASSERT_LE(std::abs(p.x - px[i - 1].x), 1);
                ASSERT_LE(std::abs(p.y - px[i - 1].y), 1);
            }
            if (d == glm::dvec2(0.0)) continue;
            const double major = x_major ? p.x : p.y, minor = x_major ? p.y : p.x;
            const double ideal =
                (x_major ? a.y : a.x) +
                (major - a_major) * ((x_major ? d.y : d.x) / (x_major ? d.x : d.y));
            ASSERT_LE(std::abs(minor - ideal), 0.5 + 1e-9);
        }
    }
}

}  // namespace
}  // namespace zraster
