// Triangle setup in lanes (src/raster/setup_lanes.hpp): on every instruction set, every lane's
// setup is setup_triangle's bit for bit, the lanes it leaves to the scalar setup are exactly
// the ones it must (coordinates past the limit, triangles setup_triangle rejects), and the
// cases with their own branches in setup_triangle (snapped planes for slivers whose unsnapped
// orientation flips, the fill rule's ties, every cull mode and winding) are all exercised; and
// the single jobs it computes for a tile's window are the ones the triangle's setup gives.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <bit>
#include <cstdlib>

#include "raster/setup_lanes.hpp"

namespace zraster::detail {
namespace {

void expect_same_plane(const PlaneEquation& a, const PlaneEquation& b, const char* name) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(a.a), std::bit_cast<std::uint32_t>(b.a)) << name;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(a.b), std::bit_cast<std::uint32_t>(b.b)) << name;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(a.c), std::bit_cast<std::uint32_t>(b.c)) << name;
}

// The fields a setup with these settings defines.
void expect_same_setup(const TriangleSetup& a, const TriangleSetup& b,
                       const SetupSettings& settings) {
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.edge_a, b.edge_a);
    EXPECT_EQ(a.edge_b, b.edge_b);
    EXPECT_EQ(a.edge_c, b.edge_c);
    EXPECT_EQ(a.min_x, b.min_x);
    EXPECT_EQ(a.min_y, b.min_y);
    EXPECT_EQ(a.max_x, b.max_x);
    EXPECT_EQ(a.max_y, b.max_y);
    EXPECT_EQ(a.front_facing, b.front_facing);
    expect_same_plane(a.depth, b.depth, "depth");
    if (!settings.barycentric_planes) return;
    expect_same_plane(a.q, b.q, "q");
    expect_same_plane(a.p1, b.p1, "p1");
    expect_same_plane(a.p2, b.p2, "p2");
    if (!settings.screen_linear_planes) return;
    expect_same_plane(a.l1, b.l1, "l1");
    expect_same_plane(a.l2, b.l2, "l2");
}

// Checks lane `lane`'s single job against the setup (`visible`: setup_triangle accepted it), as
// the tile rasterizer would run the triangle as one job in the window; returns whether it is one.
bool expect_single_job(const VertexLanes& in, int lane, const SetupLanes& lanes,
                       const TriangleSetup& t, bool visible, const JobWindow& w) {
    bool small = visible;
    for (int k = 0; k < 3; ++k)
        small &= std::abs(std::int64_t{in.x[k][lane]}) < kSetupLanesCoordinateLimit &&
                 std::abs(std::int64_t{in.y[k][lane]}) < kSetupLanesCoordinateLimit;
    std::int64_t width = 0, height = 0;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            width = std::max(width, std::int64_t{in.x[a][lane]} - in.x[b][lane]);
            height = std::max(height, std::int64_t{in.y[a][lane]} - in.y[b][lane]);
        }
    const int x0 = std::max(t.min_x, w.x0), x1 = std::min(t.max_x, w.x1 - 1);
    const int y0 = std::max(t.min_y, w.y0), y1 = std::min(t.max_y, w.y1 - 1);
    const bool single = small && width < kSingleJobExtent && height < kSingleJobExtent &&
                        x0 <= x1 && y0 <= y1 && x1 - x0 + 1 <= w.max_columns;
    EXPECT_EQ(lanes.single_job[lane], single ? 1 : 0) << lane;
    if (!single) return false;
    EXPECT_EQ(lanes.job_x0[lane], x0 - w.x0);
    EXPECT_EQ(lanes.job_y0[lane], y0 - w.y0);
    EXPECT_EQ(lanes.job_width[lane], x1 - x0 + 1);
    EXPECT_EQ(lanes.job_height[lane], y1 - y0 + 1);
    EXPECT_EQ(lanes.job_plane_dx[lane], x0 - t.min_x);
    EXPECT_EQ(lanes.job_plane_dy[lane], y0 - t.min_y);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(lanes.job_e[k][lane], t.edge_a[k] * x0 + t.edge_b[k] * y0 + t.edge_c[k]) << k;
        EXPECT_EQ(lanes.job_step_x[k][lane], t.edge_a[k]) << k;
        EXPECT_EQ(lanes.job_step_y[k][lane], t.edge_b[k]) << k;
    }
    return true;
}

// A vertex around (cx, cy) pixels: snapped as to_screen does, the unsnapped position a little
// off it (so slivers may flip orientation unsnapped), random depth and 1/w.
ScreenVertex random_vertex(SplitMix64& rng, double cx, double cy, double extent) {
    ScreenVertex v;
    const double wx = cx + rng.uniform(-extent, extent), wy = cy + rng.uniform(-extent, extent);
    const auto snapped = snap_to_grid({wx, wy});
    v.x = std::int32_t(snapped[0]);
    v.y = std::int32_t(snapped[1]);
    // Some on pixel centers and pixel edges: ties of the fill rule and the pixel box.
    if (rng.next() % 5 == 0) v.x = v.x / 256 * 256 + 128;
    if (rng.next() % 5 == 0) v.y = v.y / 256 * 256;
    v.window_x = float(wx + rng.uniform(-2e-3, 2e-3));
    v.window_y = float(wy + rng.uniform(-2e-3, 2e-3));
    v.z = float(rng.unit());
    v.inv_w = float(rng.uniform(0.01, 10.0));
    return v;
}

TEST(SetupLanes, EveryLaneIsSetupTriangleBitForBit) {
    SplitMix64 rng(2026);
    std::uint64_t in_lanes = 0, left_to_scalar = 0, snapped_planes = 0, rejected = 0;
    std::uint64_t single_jobs = 0, not_single = 0;
    for (int round = 0; round < 3000; ++round) {
        SetupSettings settings;
        settings.viewport = {1 + int(rng.next() % 2048), 1 + int(rng.next() % 2048)};
        settings.cull = CullMode(rng.next() % 3);
        settings.front_face = FrontFace(rng.next() % 2);
        settings.barycentric_planes = rng.next() % 4 != 0;
        settings.screen_linear_planes = rng.next() % 3 == 0;
        // Sub-pixel, a few pixels, or large triangles.
        const double extent = std::array{0.4, 3.0, 40.0, 900.0}[rng.next() % 4];
        // A tile's window (its jobs are computed too), mostly with the triangles near it.
        JobWindow window;
        window.x0 = int(rng.next() % std::uint64_t(settings.viewport.width)) / 64 * 64;
        window.y0 = int(rng.next() % std::uint64_t(settings.viewport.height)) / 64 * 64;
        window.x1 = std::min(window.x0 + 64, settings.viewport.width);
        window.y1 = std::min(window.y0 + 64, settings.viewport.height);
        window.max_columns = rng.next() % 2 ? 32 : 1 + int(rng.next() % 40);
        const bool near_window = rng.next() % 4 != 0;
        VertexLanes in{};
        const int count = 1 + int(rng.next() % kSetupLanes);
        for (int lane = 0; lane < count; ++lane) {
            const double cx = near_window ? window.x0 + rng.uniform(-20.0, 84.0)
                                          : rng.uniform(-50.0, settings.viewport.width + 50.0);
            const double cy = near_window ? window.y0 + rng.uniform(-20.0, 84.0)
                                          : rng.uniform(-50.0, settings.viewport.height + 50.0);
            for (int k = 0; k < 3; ++k) in.set_vertex(k, lane, random_vertex(rng, cx, cy, extent));
            switch (rng.next() % 16) {
                case 0:  // degenerate
                    in.set_vertex(2, lane, in.vertex(1, lane));
                    break;
                case 1:  // past the lanes' coordinate limit, and just inside it
                    in.x[rng.next() % 3][lane] = (rng.next() % 2 ? 1 : -1) *
                                                 (kSetupLanesCoordinateLimit - int(rng.next() % 2));
                    break;
                case 2:  // a sliver: collinear but for one subpixel
                    in.x[2][lane] = in.x[0][lane] + 2 * (in.x[1][lane] - in.x[0][lane]);
                    in.y[2][lane] = in.y[0][lane] + 2 * (in.y[1][lane] - in.y[0][lane]) + 1;
                    break;
                case 3:  // unsnapped corners on one point: zero unsnapped area, snapped not
                    in.window_x[2][lane] = in.window_x[1][lane];
                    in.window_y[2][lane] = in.window_y[1][lane];
                    break;
                default:
                    break;
            }
        }
        SCOPED_TRACE(round);
        for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
            hwy::SetSupportedTargetsForTest(target);
            for (const bool simd : {true, false}) {
                SetupLanes lanes;
                (simd ? setup_lanes : setup_lanes_scalar)(in, count, settings, lanes, &window);
                for (int lane = 0; lane < count; ++lane) {
                    const std::array<ScreenVertex, 3> v{in.vertex(0, lane), in.vertex(1, lane),
                                                        in.vertex(2, lane)};
                    TriangleSetup expected, got;
                    const SetupResult result = setup_triangle(v, settings, expected);
                    ASSERT_EQ(load_setup(in, lanes, lane, settings, got), result) << lane;
                    bool small = true;
                    for (int k = 0; k < 3; ++k)
                        small &=
                            std::abs(std::int64_t{in.x[k][lane]}) < kSetupLanesCoordinateLimit &&
                            std::abs(std::int64_t{in.y[k][lane]}) < kSetupLanesCoordinateLimit;
                    // Left to the scalar setup exactly when it must be.
                    EXPECT_EQ(lanes.scalar[lane] != 0, !small || result != SetupResult::Visible)
                        << lane;
                    const bool single = expect_single_job(in, lane, lanes, expected,
                                                          result == SetupResult::Visible, window);
                    single_jobs += simd && single;
                    if (result != SetupResult::Visible) {
                        rejected += simd;
                        continue;
                    }
                    if (simd && !single && !lanes.scalar[lane]) ++not_single;
                    expect_same_setup(got, expected, settings);
                    if (!simd) continue;
                    (lanes.scalar[lane] ? left_to_scalar : in_lanes) += 1;
                    const double ex1 = double(v[1].window_x) - v[0].window_x,
                                 ey1 = double(v[1].window_y) - v[0].window_y,
                                 ex2 = double(v[2].window_x) - v[0].window_x,
                                 ey2 = double(v[2].window_y) - v[0].window_y;
                    const std::int64_t area =
                        (std::int64_t{v[1].x} - v[0].x) * (std::int64_t{v[2].y} - v[0].y) -
                        (std::int64_t{v[2].x} - v[0].x) * (std::int64_t{v[1].y} - v[0].y);
                    snapped_planes += !((ex1 * ey2 - ex2 * ey1) * double(area) > 0.0);
                }
            }
        }
        hwy::SetSupportedTargetsForTest(0);
    }
    // Every branch was taken, on every target. (Counted over the targets, so per target: the
    // sanitizer builds and machines without AVX-512 run fewer; two of them took 1,051 single
    // jobs each.)
    const std::size_t targets = hwy::SupportedAndGeneratedTargets().size();
    EXPECT_GT(in_lanes, 2500u * targets);
    EXPECT_GT(left_to_scalar, 25u * targets);
    EXPECT_GT(snapped_planes, 5u * targets);
    EXPECT_GT(rejected, 250u * targets);
    EXPECT_GT(single_jobs, 750u * targets);
    EXPECT_GT(not_single, 250u * targets);
}

}  // namespace
}  // namespace zraster::detail
