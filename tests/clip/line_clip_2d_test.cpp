// 2D line clipping: Cohen-Sutherland, Liang-Barsky and Cyrus-Beck agree on random segments and on
// the hand-made special cases (axis-parallel, degenerate, on the boundary, through corners);
// trivial cases are decided from outcodes alone; Cyrus-Beck on general convex windows against a
// sampling reference.
#include <zraster/line_clip.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace zraster {
namespace {

struct Results {
    ClippedLine2 cs, lb, cb;
    LineClipStats cs_stats, lb_stats, cb_stats;
};

Results clip_all(glm::dvec2 a, glm::dvec2 b, const ClipRect& r) {
    Results out;
    out.cs = clip_line_cohen_sutherland(a, b, r, &out.cs_stats);
    out.lb = clip_line_liang_barsky(a, b, r, &out.lb_stats);
    out.cb = clip_line_cyrus_beck(a, b, make_convex_window(r), &out.cb_stats);
    return out;
}

bool near(glm::dvec2 p, glm::dvec2 q, double scale) {
    const double tol = 1e-9 * scale;
    return std::abs(p.x - q.x) <= tol && std::abs(p.y - q.y) <= tol;
}

bool inside(glm::dvec2 p, const ClipRect& r) {
    return p.x >= r.x_min && p.x <= r.x_max && p.y >= r.y_min && p.y <= r.y_max;
}

// Checks that the three clippers agree, and with `expected` when given.
void expect_agreement(glm::dvec2 a, glm::dvec2 b, const ClipRect& r,
                      const ClippedLine2* expected = nullptr) {
    const Results res = clip_all(a, b, r);
    const double scale =
        std::max({1.0, std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y),
                  std::abs(r.x_min), std::abs(r.x_max), std::abs(r.y_min), std::abs(r.y_max)});
    const auto where = [&] {
        return testing::Message() << "segment (" << a.x << "," << a.y << ")-(" << b.x << "," << b.y
                                  << ") window [" << r.x_min << "," << r.x_max << "]x[" << r.y_min
                                  << "," << r.y_max << "]";
    };
    ASSERT_EQ(res.cs.visible, res.lb.visible) << where();
    ASSERT_EQ(res.cb.visible, res.lb.visible) << where();
    if (expected) {
        ASSERT_EQ(res.lb.visible, expected->visible) << where();
    }
    if (!res.lb.visible) return;
    for (const ClippedLine2* c : {&res.cs, &res.cb}) {
        EXPECT_TRUE(near(c->a, res.lb.a, scale)) << where();
        EXPECT_TRUE(near(c->b, res.lb.b, scale)) << where();
    }
    if (expected) {
        EXPECT_TRUE(near(res.lb.a, expected->a, scale)) << where();
        EXPECT_TRUE(near(res.lb.b, expected->b, scale)) << where();
    }
    // Cohen-Sutherland and Liang-Barsky keep their endpoints in the closed window exactly.
    EXPECT_TRUE(inside(res.cs.a, r) && inside(res.cs.b, r)) << where();
    EXPECT_TRUE(inside(res.lb.a, r) && inside(res.lb.b, r)) << where();
    // The same outcode test decides the same trivial cases in all three.
    EXPECT_EQ(res.cs_stats.trivial_accepts, res.lb_stats.trivial_accepts) << where();
    EXPECT_EQ(res.cb_stats.trivial_accepts, res.lb_stats.trivial_accepts) << where();
    EXPECT_EQ(res.cs_stats.trivial_rejects, res.lb_stats.trivial_rejects) << where();
    EXPECT_EQ(res.cb_stats.trivial_rejects, res.lb_stats.trivial_rejects) << where();
}

TEST(LineClip2D, ThreeClippersAgreeOnRandomSegments) {
    std::mt19937_64 rng(1984);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    LineClipStats cs, lb, cb;
    int accepted = 0, clipped = 0, rejected = 0;
    for (int k = 0; k < 100000; ++k) {
        const double scale = std::pow(10.0, 4.0 * unit(rng) - 2.0);  // 0.01 .. 100
        ClipRect r;
        r.x_min = scale * (2.0 * unit(rng) - 1.0);
        r.y_min = scale * (2.0 * unit(rng) - 1.0);
        r.x_max = r.x_min + scale * (0.05 + unit(rng));
        r.y_max = r.y_min + scale * (0.05 + unit(rng));
        // Endpoints in the window grown by its size on every side, or (a third of them) in the
        // window itself: all cases occur often.
        const double w = r.x_max - r.x_min, h = r.y_max - r.y_min;
        auto point = [&] {
            if (unit(rng) < 1.0 / 3.0)
                return glm::dvec2(r.x_min + w * unit(rng), r.y_min + h * unit(rng));
            return glm::dvec2(r.x_min - w + 3.0 * w * unit(rng), r.y_min - h + 3.0 * h * unit(rng));
        };
        const glm::dvec2 a = point(), b = point();
        const ClippedLine2 c = clip_line_cohen_sutherland(a, b, r, &cs);
        const ClippedLine2 l = clip_line_liang_barsky(a, b, r, &lb);
        const ClippedLine2 y = clip_line_cyrus_beck(a, b, make_convex_window(r), &cb);
        const double tol = 1e-9 * std::max({1.0, scale, std::abs(a.x), std::abs(a.y), std::abs(b.x),
                                            std::abs(b.y)});
        ASSERT_EQ(c.visible, l.visible) << k;
        ASSERT_EQ(y.visible, l.visible) << k;
        if (!l.visible) {
            ++rejected;
            continue;
        }
        (l.a == a && l.b == b) ? ++accepted : ++clipped;
        for (const ClippedLine2* o : {&c, &y}) {
            ASSERT_LE(std::abs(o->a.x - l.a.x), tol) << k;
            ASSERT_LE(std::abs(o->a.y - l.a.y), tol) << k;
            ASSERT_LE(std::abs(o->b.x - l.b.x), tol) << k;
            ASSERT_LE(std::abs(o->b.y - l.b.y), tol) << k;
        }
    }
    // The distribution exercises every path, and the trivial decisions coincide.
    EXPECT_GT(accepted, 5000);
    EXPECT_GT(clipped, 20000);
    EXPECT_GT(rejected, 20000);
    EXPECT_EQ(cs.segments, 100000);
    EXPECT_EQ(cs.trivial_accepts, lb.trivial_accepts);
    EXPECT_EQ(cs.trivial_rejects, lb.trivial_rejects);
    EXPECT_EQ(cb.trivial_accepts, lb.trivial_accepts);
    EXPECT_EQ(cb.trivial_rejects, lb.trivial_rejects);
    EXPECT_GT(cs.trivial_rejects, 0);
    // Cohen-Sutherland moves at most two endpoints twice each per segment, in exact arithmetic.
    EXPECT_LE(cs.subdivisions, 4 * (cs.segments - cs.trivial_accepts - cs.trivial_rejects));
    RecordProperty("cs_subdivisions", std::to_string(cs.subdivisions));
    RecordProperty("lb_divisions", std::to_string(lb.subdivisions));
    RecordProperty("cb_divisions", std::to_string(cb.subdivisions));
}

TEST(LineClip2D, TrivialCasesAreDecidedByOutcodesAlone) {
    const ClipRect r{0, 0, 10, 10};
    const ConvexWindow window = make_convex_window(r);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> in(0.0, 10.0), out(11.0, 30.0);
    LineClipStats cs, lb, cb;
    for (int k = 0; k < 1000; ++k) {
        const glm::dvec2 a(in(rng), in(rng)), b(in(rng), in(rng));
        EXPECT_TRUE(clip_line_cohen_sutherland(a, b, r, &cs).visible);
        EXPECT_TRUE(clip_line_liang_barsky(a, b, r, &lb).visible);
        EXPECT_TRUE(clip_line_cyrus_beck(a, b, window, &cb).visible);
    }
    for (const LineClipStats* s : {&cs, &lb, &cb}) {
        EXPECT_EQ(s->trivial_accepts, 1000);
        EXPECT_EQ(s->trivial_rejects, 0);
        EXPECT_EQ(s->subdivisions, 0);
    }
    EXPECT_EQ(cs.iterations, 1000);  // one pass of the outcode loop each
    cs = lb = cb = {};
    // Both endpoints beyond the same side (the four sides in turn; some cross a second side).
    for (int k = 0; k < 1000; ++k) {
        glm::dvec2 a(in(rng), in(rng)), b(out(rng), out(rng));
        const int side = k % 4;
        if (side == 0) a.x = -out(rng), b.x = -out(rng);  // left
        if (side == 1) a.x = out(rng), b.x = out(rng);    // right
        if (side == 2) a.y = -out(rng), b.y = -out(rng);  // bottom
        if (side == 3) a.y = out(rng), b.y = out(rng);    // top
        EXPECT_FALSE(clip_line_cohen_sutherland(a, b, r, &cs).visible);
        EXPECT_FALSE(clip_line_liang_barsky(a, b, r, &lb).visible);
        EXPECT_FALSE(clip_line_cyrus_beck(a, b, window, &cb).visible);
    }
    for (const LineClipStats* s : {&cs, &lb, &cb}) {
        EXPECT_EQ(s->trivial_rejects, 1000);
        EXPECT_EQ(s->trivial_accepts, 0);
        EXPECT_EQ(s->subdivisions, 0);
    }
    // Outside but not on a common side: the outcodes cannot decide, the clippers must work.
    cs = lb = cb = {};
    const glm::dvec2 a(-5, 8), b(2, 15);  // passes above the top-left corner
    EXPECT_FALSE(clip_line_cohen_sutherland(a, b, r, &cs).visible);
    EXPECT_FALSE(clip_line_liang_barsky(a, b, r, &lb).visible);
    EXPECT_FALSE(clip_line_cyrus_beck(a, b, window, &cb).visible);
    for (const LineClipStats* s : {&cs, &lb, &cb}) {
        EXPECT_EQ(s->trivial_rejects + s->trivial_accepts, 0);
        EXPECT_GT(s->subdivisions, 0);
    }
}

TEST(LineClip2D, HorizontalAndVerticalSegments) {
    const ClipRect r{-1, -2, 3, 4};
    const struct {
        glm::dvec2 a, b;
        ClippedLine2 expected;
    } cases[] = {
        {{-5, 1}, {7, 1}, {true, {-1, 1}, {3, 1}}},        // horizontal, across
        {{7, 1}, {-5, 1}, {true, {3, 1}, {-1, 1}}},        // same, reversed
        {{0, 1}, {7, 1}, {true, {0, 1}, {3, 1}}},          // from inside out
        {{-5, 1}, {-2, 1}, {false, {}, {}}},               // left of the window
        {{-5, 5}, {7, 5}, {false, {}, {}}},                // above it
        {{2, -9}, {2, 9}, {true, {2, -2}, {2, 4}}},        // vertical, across
        {{2, 9}, {2, 0}, {true, {2, 4}, {2, 0}}},          // from above into it
        {{5, -9}, {5, 9}, {false, {}, {}}},                // right of the window
        {{2, 5}, {2, 9}, {false, {}, {}}},                 // above it
        {{0.5, 0}, {1.5, 0}, {true, {0.5, 0}, {1.5, 0}}},  // inside
    };
    for (const auto& c : cases) expect_agreement(c.a, c.b, r, &c.expected);
}

TEST(LineClip2D, DegeneratePointSegments) {
    const ClipRect r{0, 0, 10, 10};
    for (const glm::dvec2 p : {glm::dvec2(5, 5), glm::dvec2(0, 5), glm::dvec2(10, 10),
                               glm::dvec2(0, 0), glm::dvec2(10, 3)}) {
        const ClippedLine2 expected{true, p, p};
        expect_agreement(p, p, r, &expected);
    }
    for (const glm::dvec2 p :
         {glm::dvec2(-1, 5), glm::dvec2(5, 11), glm::dvec2(-1, -1), glm::dvec2(10.000001, 10)}) {
        const ClippedLine2 expected{false, {}, {}};
        expect_agreement(p, p, r, &expected);
    }
}

TEST(LineClip2D, SegmentsOnTheWindowBoundaryAreKept) {
    const ClipRect r{0, 0, 10, 10};
    const struct {
        glm::dvec2 a, b;
        ClippedLine2 expected;
    } cases[] = {
        {{-5, 0}, {15, 0}, {true, {0, 0}, {10, 0}}},       // along the bottom edge
        {{10, 15}, {10, -5}, {true, {10, 10}, {10, 0}}},   // along the right edge
        {{0, 2}, {0, 7}, {true, {0, 2}, {0, 7}}},          // part of the left edge
        {{3, 10}, {12, 10}, {true, {3, 10}, {10, 10}}},    // top edge, leaving
        {{-5, 10}, {-1, 10}, {false, {}, {}}},             // on the top edge's line, outside
        {{10, 10}, {15, 15}, {true, {10, 10}, {10, 10}}},  // touches the corner from outside
        {{-3, 5}, {0, 5}, {true, {0, 5}, {0, 5}}},         // ends on the left edge
    };
    for (const auto& c : cases) expect_agreement(c.a, c.b, r, &c.expected);
}

TEST(LineClip2D, SegmentsThroughCorners) {
    const ClipRect r{0, 0, 10, 10};
    const struct {
        glm::dvec2 a, b;
        ClippedLine2 expected;
    } cases[] = {
        {{-5, -5}, {15, 15}, {true, {0, 0}, {10, 10}}},  // the diagonal, corner to corner
        {{15, -5}, {-5, 15}, {true, {10, 0}, {0, 10}}},  // the other diagonal
        {{-5, 5}, {5, -5}, {true, {0, 0}, {0, 0}}},      // grazes the corner (0, 0)
        {{5, 15}, {15, 5}, {true, {10, 10}, {10, 10}}},  // grazes (10, 10)
        {{-5, 4.5}, {5, -5.5}, {false, {}, {}}},         // misses (0, 0) by 0.5 / sqrt 2
        {{-4, 12}, {4, 8}, {true, {0, 10}, {4, 8}}},     // enters through the top at the corner
        {{0, 0}, {20, 10}, {true, {0, 0}, {10, 5}}},     // starts at a corner
    };
    for (const auto& c : cases) expect_agreement(c.a, c.b, r, &c.expected);
}

// Independent point-in-convex-polygon test (counter-clockwise vertices): left of every edge.
bool inside_convex(const std::vector<glm::dvec2>& ccw, glm::dvec2 p, double eps) {
    for (std::size_t i = 0; i < ccw.size(); ++i) {
        const glm::dvec2 u = ccw[(i + 1) % ccw.size()] - ccw[i], v = p - ccw[i];
        if (u.x * v.y - u.y * v.x < -eps * glm::length(u)) return false;
    }
    return true;
}

TEST(LineClip2D, CyrusBeckOnConvexPolygonsMatchesSampling) {
    std::mt19937_64 rng(1978);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double two_pi = 2.0 * std::acos(-1.0);
    int visible = 0;
    for (int k = 0; k < 2000; ++k) {
        // A random convex polygon: sorted angles on an ellipse, rotated.
        const int n = 3 + k % 10;
        std::vector<double> angles(static_cast<std::size_t>(n));
        for (double& t : angles) t = two_pi * unit(rng);
        std::sort(angles.begin(), angles.end());
        const double rx = 0.5 + unit(rng), ry = 0.5 + unit(rng), rot = two_pi * unit(rng);
        std::vector<glm::dvec2> poly;
        for (double t : angles) {
            const glm::dvec2 e(rx * std::cos(t), ry * std::sin(t));
            poly.emplace_back(e.x * std::cos(rot) - e.y * std::sin(rot),
                              e.x * std::sin(rot) + e.y * std::cos(rot));
        }
        ConvexWindow window;
        try {
            window = make_convex_window(poly);
        } catch (const std::invalid_argument&) {
            continue;  // nearly coincident angles
        }
        // Clockwise input gives the same window.
        std::vector<glm::dvec2> cw(poly.rbegin(), poly.rend());
        const ConvexWindow window_cw = make_convex_window(cw);
        const glm::dvec2 a(4 * unit(rng) - 2, 4 * unit(rng) - 2),
            b(4 * unit(rng) - 2, 4 * unit(rng) - 2);
        const ClippedLine2 c = clip_line_cyrus_beck(a, b, window);
        const ClippedLine2 c_cw = clip_line_cyrus_beck(a, b, window_cw);
        ASSERT_EQ(c.visible, c_cw.visible);
        // Sample the segment: a sample is inside the polygon iff it lies in the kept part.
        const glm::dvec2 d = b - a;
        double t0 = 1.0, t1 = 0.0;
        if (c.visible) {
            visible++;
            const double len2 = glm::dot(d, d);
            t0 = glm::dot(c.a - a, d) / len2;
            t1 = glm::dot(c.b - a, d) / len2;
            EXPECT_TRUE(inside_convex(window.vertices, c.a, 1e-12));
            EXPECT_TRUE(inside_convex(window.vertices, c.b, 1e-12));
            EXPECT_LE(t0, t1 + 1e-12);
        }
        for (int i = 0; i <= 200; ++i) {
            const double t = i / 200.0;
            const glm::dvec2 p = a + t * d;
            if (t > t0 + 1e-9 && t < t1 - 1e-9) {
                ASSERT_TRUE(inside_convex(window.vertices, p, 1e-12)) << k << " t=" << t;
            }
            if (t < t0 - 1e-9 || t > t1 + 1e-9) {
                ASSERT_FALSE(inside_convex(window.vertices, p, -1e-12)) << k << " t=" << t;
            }
        }
    }
    EXPECT_GT(visible, 300);
}

TEST(LineClip2D, MakeConvexWindowRejectsBadPolygons) {
    const std::vector<glm::dvec2> concave{{0, 0}, {4, 0}, {2, 1}, {4, 4}, {0, 4}};
    EXPECT_THROW(make_convex_window(concave), std::invalid_argument);
    std::vector<glm::dvec2> pentagram;
    for (int i = 0; i < 5; ++i) {
        const double t = 2.0 * std::acos(-1.0) * (2 * i) / 5.0;
        pentagram.emplace_back(std::cos(t), std::sin(t));
    }
    EXPECT_THROW(make_convex_window(pentagram), std::invalid_argument);
    const std::vector<glm::dvec2> line{{0, 0}, {1, 1}, {2, 2}};
    EXPECT_THROW(make_convex_window(line), std::invalid_argument);
    const std::vector<glm::dvec2> two{{0, 0}, {1, 1}};
    EXPECT_THROW(make_convex_window(two), std::invalid_argument);
    EXPECT_THROW(make_convex_window(ClipRect{0, 0, 0, 1}), std::invalid_argument);
    // Collinear vertices are allowed (redundant edges).
    const std::vector<glm::dvec2> with_midpoint{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
    EXPECT_NO_THROW(make_convex_window(with_midpoint));
}

}  // namespace
}  // namespace zraster
