// Homogeneous line clipping (Blinn & Newell) against a brute-force parametric reference, trivial
// cases from outcodes alone, and segments that pass behind the eye.
#include <zraster/camera.hpp>
#include <zraster/line_clip.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace zraster {
namespace {

bool in_volume(const glm::dvec4& p, ClipDepthRange range, double eps) {
    const double z_lo = range == ClipDepthRange::ZeroToOne ? 0.0 : -p.w;
    return p.x >= -p.w - eps && p.x <= p.w + eps && p.y >= -p.w - eps && p.y <= p.w + eps &&
           p.z >= z_lo - eps && p.z <= p.w + eps;
}

struct Interval {
    bool visible = false;
    double t0 = 0, t1 = 0;
};

// Brute force: every parameter where any of the six plane functions vanishes splits [0, 1] into
// pieces on which the inside/outside state is constant; test each piece at its midpoint, and
// take the hull of the inside pieces. (Convexity says the inside pieces are contiguous; checked.)
Interval reference_clip(const glm::dvec4& a, const glm::dvec4& b, ClipDepthRange range) {
    auto plane_values = [&](const glm::dvec4& p) {
        const double z_lo = range == ClipDepthRange::ZeroToOne ? p.z : p.w + p.z;
        return std::array<double, 6>{p.w + p.x, p.w - p.x, p.w + p.y, p.w - p.y, z_lo, p.w - p.z};
    };
    const std::array<double, 6> fa = plane_values(a), fb = plane_values(b);
    std::vector<double> cuts{0.0, 1.0};
    for (std::size_t k = 0; k < 6; ++k) {
        if (fa[k] == fb[k]) continue;
        const double t = fa[k] / (fa[k] - fb[k]);
        if (t > 0.0 && t < 1.0) cuts.push_back(t);
    }
    std::sort(cuts.begin(), cuts.end());
    Interval r;
    bool ended = false;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        if (cuts[i + 1] - cuts[i] < 1e-12) continue;
        const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
        const bool in = in_volume(a + mid * (b - a), range, 0.0);
        if (in) {
            EXPECT_FALSE(ended) << "inside pieces not contiguous";
            if (!r.visible) r.t0 = cuts[i];
            r.visible = true;
            r.t1 = cuts[i + 1];
        } else if (r.visible) {
            ended = true;
        }
    }
    return r;
}

glm::dvec4 random_clip_point(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> w(-1.0, 3.0), c(-4.0, 4.0);
    return {c(rng), c(rng), c(rng), w(rng)};
}

TEST(LineClip3D, MatchesBruteForceReference) {
    std::mt19937_64 rng(1978);
    for (ClipDepthRange range : {ClipDepthRange::NegativeOneToOne, ClipDepthRange::ZeroToOne}) {
        int visible = 0, clipped = 0;
        for (int k = 0; k < 50000; ++k) {
            const glm::dvec4 a = random_clip_point(rng), b = random_clip_point(rng);
            const ClippedLine4 c = clip_line_homogeneous(a, b, range);
            const Interval ref = reference_clip(a, b, range);
            // A kept piece shorter than the reference's resolution may be missed by it.
            if (c.visible && !ref.visible && c.t1 - c.t0 < 1e-9) continue;
            ASSERT_EQ(c.visible, ref.visible) << k;
            if (!c.visible) continue;
            ++visible;
            if (c.t0 > 0.0 || c.t1 < 1.0) ++clipped;
            ASSERT_NEAR(c.t0, ref.t0, 1e-9) << k;
            ASSERT_NEAR(c.t1, ref.t1, 1e-9) << k;
            const glm::dvec4 d = b - a;
            for (int i = 0; i < 4; ++i) {
                ASSERT_NEAR(c.a[i], (a + c.t0 * d)[i], 1e-9) << k;
                ASSERT_NEAR(c.b[i], (a + c.t1 * d)[i], 1e-9) << k;
            }
            ASSERT_TRUE(in_volume(c.a, range, 1e-12)) << k;
            ASSERT_TRUE(in_volume(c.b, range, 1e-12)) << k;
            ASSERT_EQ(outcode(c.a, range), 0u) << k;  // the cut coordinate is exactly on its plane
            ASSERT_EQ(outcode(c.b, range), 0u) << k;
        }
        EXPECT_GT(visible, 2000);
        EXPECT_GT(clipped, 1000);
    }
}

TEST(LineClip3D, OutcodesUseTheClipPlaneBits) {
    const auto R = ClipDepthRange::NegativeOneToOne;
    EXPECT_EQ(outcode(glm::dvec4(0, 0, 0, 1), R), 0u);
    EXPECT_EQ(outcode(glm::dvec4(-2, 0, 0, 1), R), std::uint32_t{kClipLeft});
    EXPECT_EQ(outcode(glm::dvec4(2, 0, 0, 1), R), std::uint32_t{kClipRight});
    EXPECT_EQ(outcode(glm::dvec4(0, -2, 0, 1), R), std::uint32_t{kClipBottom});
    EXPECT_EQ(outcode(glm::dvec4(0, 2, 0, 1), R), std::uint32_t{kClipTop});
    EXPECT_EQ(outcode(glm::dvec4(0, 0, -2, 1), R), std::uint32_t{kClipDepthMin});
    EXPECT_EQ(outcode(glm::dvec4(0, 0, 2, 1), R), std::uint32_t{kClipDepthMax});
    EXPECT_EQ(outcode(glm::dvec4(0, 0, -0.5, 1), ClipDepthRange::ZeroToOne),
              std::uint32_t{kClipDepthMin});
    // Behind the eye (w < 0) every plane with a w term is violated at once.
    EXPECT_EQ(outcode(glm::dvec4(0, 0, 0, -1), R), 0x3Fu);
    // NaN is outside of every plane (the convention of clip.hpp's frustum_outcode).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(outcode(glm::dvec4(nan, 0, 0, 1), R), std::uint32_t{kClipLeft | kClipRight});
    EXPECT_EQ(outcode(glm::dvec4(0, 0, 0, nan), R), 0x3Fu);
    // A segment with a NaN end is dropped, not returned with NaN in it.
    EXPECT_FALSE(clip_line_homogeneous({nan, 0, 0, 1}, {0, 0, 0, 1}).visible);
    EXPECT_FALSE(clip_line_homogeneous({0, 0, 0, 1}, {0, 0, nan, 1}).visible);
    // On the boundary is inside.
    EXPECT_EQ(outcode(glm::dvec4(1, -1, 1, 1), R), 0u);
}

TEST(LineClip3D, TrivialCasesAreDecidedByOutcodesAlone) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> in(-0.9, 0.9), w(0.5, 2.0);
    LineClipStats stats;
    for (int k = 0; k < 1000; ++k) {
        const double wa = w(rng), wb = w(rng);
        const glm::dvec4 a(in(rng)*wa, in(rng)*wa, in(rng)*wa, wa);
        const glm::dvec4 b(in(rng)*wb, in(rng)*wb, in(rng)*wb, wb);
        const ClippedLine4 c =
            clip_line_homogeneous(a, b, ClipDepthRange::NegativeOneToOne, &stats);
        ASSERT_TRUE(c.visible);
        EXPECT_EQ(c.a, a);
        EXPECT_EQ(c.b, b);
    }
    EXPECT_EQ(stats.trivial_accepts, 1000);
    EXPECT_EQ(stats.subdivisions, 0);
    stats = {};
    for (int k = 0; k < 1000; ++k) {
        // Both beyond the far plane, or both behind the eye.
        const double wa = w(rng), wb = w(rng);
        glm::dvec4 a(in(rng)*wa, in(rng)*wa, 1.5 * wa, wa), b(in(rng)*wb, in(rng)*wb, 3 * wb, wb);
        if (k % 2) a.w = -wa, b.w = -wb;
        EXPECT_FALSE(clip_line_homogeneous(a, b, ClipDepthRange::NegativeOneToOne, &stats).visible);
    }
    EXPECT_EQ(stats.trivial_rejects, 1000);
    EXPECT_EQ(stats.subdivisions, 0);
}

TEST(LineClip3D, SegmentThroughTheEyeIsCutAtTheNearPlane) {
    // Eye space: from 5 in front of the eye to 5 behind it, slightly off axis. Its projection
    // would wrap through infinity; clipped in clip space it ends exactly at the near plane.
    const double near = 0.5, far = 50.0;
    const glm::dmat4 p = perspective(std::acos(-1.0) / 3.0, 1.0, near, far);
    const glm::dvec4 eye_a(0.1, 0.2, -5.0, 1.0), eye_b(0.1, 0.2, 5.0, 1.0);
    LineClipStats stats;
    const ClippedLine4 c =
        clip_line_homogeneous(p * eye_a, p * eye_b, ClipDepthRange::NegativeOneToOne, &stats);
    ASSERT_TRUE(c.visible);
    EXPECT_EQ(stats.trivial_accepts + stats.trivial_rejects, 0);
    EXPECT_EQ(c.t0, 0.0);
    EXPECT_NEAR(c.t1, (5.0 - near) / 10.0, 1e-12);  // eye z = -5 + 10 t = -near
    EXPECT_GT(c.b.w, 0.0);
    EXPECT_EQ(c.b.z, -c.b.w);  // exactly on the near plane: window depth 0
    const glm::dvec4 eye_end = glm::inverse(p) * c.b;
    EXPECT_NEAR(eye_end.z / eye_end.w, -near, 1e-12);
    EXPECT_NEAR(eye_end.x / eye_end.w, 0.1, 1e-12);
    // Both ends behind the eye: nothing.
    EXPECT_FALSE(
        clip_line_homogeneous(p * glm::dvec4(0, 0, 1, 1), p * glm::dvec4(3, 1, 4, 1)).visible);
    // Reversed-Z (clip z in [0, w], near at z = w): the same segment, cut at its near plane.
    const glm::dmat4 rz = perspective_reversed_z(std::acos(-1.0) / 3.0, 1.0, near, far);
    const ClippedLine4 r = clip_line_homogeneous(rz * eye_a, rz * eye_b, ClipDepthRange::ZeroToOne);
    ASSERT_TRUE(r.visible);
    EXPECT_NEAR(r.t1, (5.0 - near) / 10.0, 1e-12);
    EXPECT_EQ(r.b.z, r.b.w);
}

TEST(LineClip3D, AttributesInterpolateWithT) {
    // A segment crossing the left and right planes at w = 1: t0, t1 give the crossing points.
    const glm::dvec4 a(-3, 0, 0, 1), b(1, 0, 0, 1);
    const ClippedLine4 c = clip_line_homogeneous(a, b);
    ASSERT_TRUE(c.visible);
    EXPECT_DOUBLE_EQ(c.t0, 0.5);
    EXPECT_DOUBLE_EQ(c.t1, 1.0);
    EXPECT_EQ(c.a, glm::dvec4(-1, 0, 0, 1));
    EXPECT_EQ(c.b, b);
}

}  // namespace
}  // namespace zraster
