// Sutherland-Hodgman polygon clipping: on random star-shaped (concave) polygons against random
// convex windows the area of the result equals the exact intersection area, computed here
// independently; zero-width bridges of a concave result; the homogeneous version agrees with the
// 2D one.
#include <zraster/polygon_clip.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace zraster {
namespace {

using Polygon = std::vector<glm::dvec2>;

const double kTwoPi = 2.0 * std::acos(-1.0);

double cross(glm::dvec2 u, glm::dvec2 v) {
    return u.x * v.y - u.y * v.x;
}

double signed_area(const Polygon& p) {
    double twice = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) twice += cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * twice;
}

// The reference: a convex polygon clipped by the half-plane left of the directed line p -> q.
// (Written from scratch here, and used with the roles swapped: the WINDOW is clipped by each
// triangle's edges, so it shares no code path with the algorithm under test.)
Polygon clip_convex_left_of(const Polygon& poly, glm::dvec2 p, glm::dvec2 q) {
    Polygon out;
    const glm::dvec2 e = q - p;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 u = poly[i], v = poly[(i + 1) % poly.size()];
        const double su = cross(e, u - p), sv = cross(e, v - p);
        if (su >= 0) out.push_back(u);
        if ((su < 0) != (sv < 0)) out.push_back(u + (su / (su - sv)) * (v - u));
    }
    return out;
}

// Exact intersection area of a star-shaped polygon (star around `center`, vertices
// counter-clockwise by angle) with a convex counter-clockwise window: the fan triangles
// (center, p_i, p_i+1) tile the star without overlap, each is convex, so the area is the sum of
// the convex-convex intersection areas.
double reference_area(const Polygon& star, glm::dvec2 center, const Polygon& window_ccw) {
    double area = 0.0;
    for (std::size_t i = 0; i < star.size(); ++i) {
        const glm::dvec2 tri[3] = {center, star[i], star[(i + 1) % star.size()]};
        Polygon piece = window_ccw;
        for (int k = 0; k < 3 && !piece.empty(); ++k)
            piece = clip_convex_left_of(piece, tri[k], tri[(k + 1) % 3]);
        area += signed_area(piece);
    }
    return area;
}

// A star-shaped polygon around c: sorted random angles (gaps < pi, so c is in its kernel) and
// random radii. Concave as soon as the radii vary.
Polygon random_star(std::mt19937_64& rng, glm::dvec2 c, int n, double r_min, double r_max) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (;;) {
        std::vector<double> angles(static_cast<std::size_t>(n));
        for (double& a : angles) a = kTwoPi * unit(rng);
        std::sort(angles.begin(), angles.end());
        bool ok = true;
        for (std::size_t i = 0; i < angles.size(); ++i) {
            const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + kTwoPi;
            ok = ok && next - angles[i] < 0.9 * kTwoPi / 2 && next - angles[i] > 1e-6;
        }
        if (!ok) continue;
        Polygon p;
        for (double a : angles) {
            const double r = r_min + (r_max - r_min) * unit(rng);
            p.emplace_back(c.x + r * std::cos(a), c.y + r * std::sin(a));
        }
        return p;
    }
}

// A random convex window (counter-clockwise): points on a rotated ellipse at sorted angles with
// gaps kept away from zero, or an axis-aligned rectangle.
Polygon random_convex_window(std::mt19937_64& rng, bool rectangle) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const glm::dvec2 c(unit(rng) - 0.5, unit(rng) - 0.5);
    if (rectangle) {
        const double hw = 0.2 + unit(rng), hh = 0.2 + unit(rng);
        return {c + glm::dvec2(-hw, -hh), c + glm::dvec2(hw, -hh), c + glm::dvec2(hw, hh),
                c + glm::dvec2(-hw, hh)};
    }
    const int n = 3 + static_cast<int>(unit(rng) * 9);
    const double rx = 0.3 + unit(rng), ry = 0.3 + unit(rng), rot = kTwoPi * unit(rng);
    const double base = kTwoPi * unit(rng);
    Polygon w;
    for (int i = 0; i < n; ++i) {
        // Jittered but ordered angles: every gap is between 0.2 and 0.8 of 2 pi / n.
        const double t = base + kTwoPi * (i + 0.2 + 0.6 * unit(rng)) / n;
        const glm::dvec2 e(rx * std::cos(t), ry * std::sin(t));
        w.push_back(c + glm::dvec2(e.x * std::cos(rot) - e.y * std::sin(rot),
                                   e.x * std::sin(rot) + e.y * std::cos(rot)));
    }
    return w;
}

TEST(SutherlandHodgman, AreaEqualsExactIntersectionOnRandomStarPolygons) {
    std::mt19937_64 rng(1974);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int partial = 0;
    for (int k = 0; k < 4000; ++k) {
        const Polygon window_ccw = random_convex_window(rng, k % 3 == 0);
        const ConvexWindow window = make_convex_window(window_ccw);
        const glm::dvec2 c(2.0 * unit(rng) - 1.0, 2.0 * unit(rng) - 1.0);
        const Polygon star =
            random_star(rng, c, 3 + k % 40, 0.05 + 0.5 * unit(rng), 0.6 + 1.5 * unit(rng));
        const double expected = reference_area(star, c, window.vertices);
        const double star_area = signed_area(star);
        const double scale = std::max(star_area, signed_area(window.vertices));
        const Polygon clipped = clip_polygon_sutherland_hodgman(star, window);
        ASSERT_NEAR(signed_area(clipped), expected, 1e-12 * scale) << k;
        // The opposite orientation: same area, negative, and the same pieces.
        const Polygon star_cw(star.rbegin(), star.rend());
        ASSERT_NEAR(signed_area(clip_polygon_sutherland_hodgman(star_cw, window)), -expected,
                    1e-12 * scale)
            << k;
        // Every output vertex is in the window (the boundary counts).
        for (const glm::dvec2& p : clipped) {
            for (std::size_t e = 0; e < window.vertices.size(); ++e)
                ASSERT_GE(glm::dot(window.inward_normals[e], p - window.vertices[e]), -1e-12) << k;
        }
        if (expected > 1e-3 * scale && expected < star_area - 1e-3 * scale) ++partial;
    }
    EXPECT_GT(partial, 1000);  // most cases really cut the polygon
}

TEST(SutherlandHodgman, ConcaveResultHasZeroWidthBridgesAndExactArea) {
    // An arch (an upside-down U) whose crossbar lies above the window: the intersection is the two
    // legs, disjoint. Sutherland-Hodgman returns one polygon joining them along y = 10.
    const Polygon arch{{1, 2}, {3, 2}, {3, 12}, {7, 12}, {7, 2}, {9, 2}, {9, 14}, {1, 14}};
    const ConvexWindow window = make_convex_window(ClipRect{0, 0, 10, 10});
    const Polygon out = clip_polygon_sutherland_hodgman(arch, window);
    EXPECT_DOUBLE_EQ(signed_area(out), 2 * 8 + 2 * 8);  // two 2 x 8 legs, exactly
    // The bridge: edges along y = 10 that cover [3, 7] once in each direction.
    double rightwards = 0, leftwards = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const glm::dvec2 p = out[i], q = out[(i + 1) % out.size()];
        if (p.y != 10.0 || q.y != 10.0) continue;  // exactly on it: snapped to the window edge
        const double lo = std::max(3.0, std::min(p.x, q.x)), hi = std::min(7.0, std::max(p.x, q.x));
        if (hi <= lo) continue;
        (q.x > p.x ? rightwards : leftwards) += hi - lo;
    }
    EXPECT_DOUBLE_EQ(rightwards, 4.0);
    EXPECT_DOUBLE_EQ(leftwards, 4.0);
}

TEST(SutherlandHodgman, InsideOutsideAndContainingCases) {
    const ConvexWindow window = make_convex_window(ClipRect{0, 0, 10, 10});
    const Polygon inside{{1, 1}, {4, 2}, {2, 5}};
    EXPECT_EQ(clip_polygon_sutherland_hodgman(inside, window), inside);
    const Polygon outside{{11, 1}, {14, 2}, {12, 5}};
    EXPECT_TRUE(clip_polygon_sutherland_hodgman(outside, window).empty());
    // Touching the window only along an edge: nothing with area.
    const Polygon touching{{10, 1}, {14, 2}, {10, 5}};
    EXPECT_DOUBLE_EQ(std::abs(signed_area(clip_polygon_sutherland_hodgman(touching, window))), 0.0);
    const Polygon around{{-5, -5}, {20, -5}, {20, 20}, {-5, 20}};
    EXPECT_DOUBLE_EQ(signed_area(clip_polygon_sutherland_hodgman(around, window)), 100.0);
}

// A zig-zag polygon whose every other vertex is outside x <= 1: each crossing adds a vertex, so
// one plane turns n vertices into 3n / 2, more than the n + 1 of a convex polygon.
Polygon zigzag(int teeth) {
    Polygon p;
    for (int i = 0; i < teeth; ++i) {
        const double y = -0.9 + 1.8 * i / teeth;
        p.emplace_back(0.5, y);
        p.emplace_back(1.5, y + 0.9 / teeth);
    }
    p.emplace_back(0.5, 0.9);
    p.emplace_back(-0.5, 0.9);
    p.emplace_back(-0.5, -0.9);
    return p;
}

TEST(HomogeneousPolygonClip, AgreesWithTheTwoDimensionalClipper) {
    std::mt19937_64 rng(1978);
    const ConvexWindow square = make_convex_window(ClipRect{-1, -1, 1, 1});
    const std::array<glm::vec4, 6> planes = view_volume_planes(ClipDepthRange::NegativeOneToOne);
    for (int k = 0; k < 500; ++k) {
        Polygon poly = k == 0 ? zigzag(20) : random_star(rng, {0.3, -0.2}, 3 + k % 30, 0.2, 1.8);
        // In clip space at w = 1, z = 0 (inside in depth), scaled by a random w > 0: the same
        // polygon after the divide.
        const float w = 0.5f + static_cast<float>(k % 7);
        std::vector<ClipVertex> hom;
        for (const glm::dvec2& p : poly)
            hom.push_back({glm::vec4(float(p.x) * w, float(p.y) * w, 0.0f, w),
                           glm::vec3(float(p.x), float(p.y), 1.0f)});
        const std::vector<ClipVertex> clipped = clip_polygon_homogeneous(hom, planes);
        Polygon projected;
        for (const ClipVertex& v : clipped) {
            projected.emplace_back(v.position.x / v.position.w, v.position.y / v.position.w);
            // The payload is carried along linearly: here it is the 2D position itself.
            ASSERT_NEAR(v.weights.x, projected.back().x, 1e-5);
            ASSERT_NEAR(v.weights.y, projected.back().y, 1e-5);
        }
        Polygon poly_f;  // the 2D clipper on the same float-rounded input
        for (const glm::dvec2& p : poly) poly_f.emplace_back(float(p.x), float(p.y));
        const Polygon reference = clip_polygon_sutherland_hodgman(poly_f, square);
        ASSERT_EQ(projected.size(), reference.size()) << k;
        ASSERT_NEAR(signed_area(projected), signed_area(reference), 1e-5) << k;
        if (k == 0) {
            EXPECT_EQ(clipped.size(), 20u * 3u + 3u);  // 3 per tooth, plus the spine
        }
    }
}

// One plane can turn a concave polygon of n vertices into more than n + 1 (the convex bound):
// a comb of k teeth crossing x = 0 (n = 2k + 1 vertices) gives k tips plus 2k crossings. The
// bound max_clip_output(n) = n + n/2 + 1 holds, and the tight case (in and out vertices
// alternating all around) reaches floor(3n/2).
TEST(HomogeneousPolygonClip, ConcaveOutputExceedsTheConvexBound) {
    const glm::vec4 keep_right(1.0f, 0.0f, 0.0f, 0.0f);  // keep x >= 0
    for (int k = 1; k <= 12; ++k) {
        std::vector<ClipVertex> comb;
        auto add = [&](float x, float y) {
            comb.push_back({glm::vec4(x, y, 0.0f, 1.0f), glm::vec3(0.0f)});
        };
        add(-2.0f, 0.0f);  // spine, outside
        for (int t = 0; t < k; ++t) {
            add(1.0f, float(t) + 0.5f);                  // tip, inside
            if (t + 1 < k) add(-1.0f, float(t) + 1.0f);  // valley, outside
        }
        add(-2.0f, float(k));
        const std::size_t n = comb.size();
        ASSERT_EQ(n, std::size_t(2 * k + 1));
        std::vector<ClipVertex> out(max_clip_output(n));
        const int count = clip_polygon_against_plane(comb, keep_right, out);
        EXPECT_EQ(count, 3 * k);
        EXPECT_LE(std::size_t(count), max_clip_output(n));
        if (k >= 3) {
            EXPECT_GT(std::size_t(count), n + 1);
        }
        // Alternating in/out all around (self-intersecting, but the count is what matters).
        std::vector<ClipVertex> alternating;
        for (int i = 0; i < 2 * k; ++i)
            alternating.push_back(
                {glm::vec4(i % 2 ? -1.0f : 1.0f, float(i), 0.0f, 1.0f), glm::vec3(0.0f)});
        std::vector<ClipVertex> out2(max_clip_output(alternating.size()));
        EXPECT_EQ(clip_polygon_against_plane(alternating, keep_right, out2), 3 * k);
        EXPECT_EQ(std::size_t(3 * k), alternating.size() * 3 / 2);
    }
}

}  // namespace
}  // namespace zraster
