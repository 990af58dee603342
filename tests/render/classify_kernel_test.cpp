// The batch classifier of the front end (src/render/classify_kernel.hpp): its SIMD version gives
// exactly the scalar reference's output, and the scalar reference makes classify_triangle's
// decisions, on random triangles with every kind of case mixed in (bad indices, vertices
// outside the view volume, coordinates too large for the fast path, degenerate triangles, ties
// on pixel centers, every cull mode and winding).
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <vector>

#include "render/classify_kernel.hpp"

namespace zraster::detail {
namespace {

void expect_equal(const ClassifyOutput& a, const ClassifyOutput& b) {
    ASSERT_EQ(a.count, b.count);
    EXPECT_EQ(a.degenerate, b.degenerate);
    EXPECT_EQ(a.culled, b.culled);
    EXPECT_EQ(a.no_coverage, b.no_coverage);
    for (std::uint32_t k = 0; k < a.count; ++k) {
        ASSERT_EQ(a.triangle[k], b.triangle[k]) << k;
        ASSERT_EQ(a.flags[k], b.flags[k]) << k;
        ASSERT_EQ(a.min_x[k], b.min_x[k]) << k;
        ASSERT_EQ(a.min_y[k], b.min_y[k]) << k;
        ASSERT_EQ(a.max_x[k], b.max_x[k]) << k;
        ASSERT_EQ(a.max_y[k], b.max_y[k]) << k;
    }
}

TEST(ClassifyKernel, SimdMatchesScalarAndClassifyTriangle) {
    SplitMix64 rng(99);
    std::uint64_t visible = 0, slow = 0, culled = 0, no_coverage = 0, degenerate = 0;
    for (int round = 0; round < 300; ++round) {
        const int vertices = 50 + int(rng.next() % 400);
        std::vector<ScreenVertex> screen(std::size_t(vertices) + 7);
        std::vector<std::uint32_t> outcode(screen.size(), 0);
        SetupSettings settings;
        settings.viewport = {1 + int(rng.next() % 300), 1 + int(rng.next() % 300)};
        settings.cull = CullMode(rng.next() % 3);
        settings.front_face = FrontFace(rng.next() % 2);
        const double extent = 256.0 * (rng.next() % 2 ? 8 : 400);  // tiny or screen-sized
        for (ScreenVertex& v : screen) {
            // Snap some to pixel-center multiples: ties in the pixel box.
            v.x = std::int32_t(rng.uniform(-0.2, 1.2) * extent);
            v.y = std::int32_t(rng.uniform(-0.2, 1.2) * extent);
            if (rng.next() % 4 == 0) v.x = v.x / 256 * 256 + 128;
            if (rng.next() % 50 == 0) v.x = std::int32_t(rng.next() % 2 ? 1 << 26 : -(1 << 25));
            if (rng.next() % 50 == 0) v.y = kClassifyCoordinateLimit;
        }
        // Outside vertices as the vertex stage leaves them (x = kOutsideScreenX).
        for (std::size_t v = 0; v < outcode.size(); ++v)
            if (rng.next() % 30 == 0) {
                outcode[v] = std::uint32_t(1) << (rng.next() % 6);
                screen[v].x = kOutsideScreenX;
            }
        const std::uint32_t first_vertex = 7;
        const std::uint32_t vertex_total = std::uint32_t(vertices);
        const std::size_t triangles = 1 + rng.next() % 256;
        std::vector<std::uint32_t> indices(3 * triangles);
        for (std::size_t i = 0; i < indices.size(); ++i) {
            indices[i] = std::uint32_t(rng.next() % vertex_total);
            if (rng.next() % 200 == 0) indices[i] = vertex_total + std::uint32_t(rng.next() % 3);
            if (i % 3 == 2 && rng.next() % 20 == 0) indices[i] = indices[i - 1];  // degenerate
        }
        ClassifyInput in;
        in.indices = indices.data();
        in.triangle_total = indices.size() / 3;
        in.vertex_total = vertex_total;
        in.first_vertex = first_vertex;
        in.screen = screen.data();
        in.settings = settings;
        ClassifyOutput simd, scalar;
        classify_triangles_scalar(in, 0, triangles, scalar);
        SCOPED_TRACE(round);
        // Every instruction set this machine runs (AVX-512, AVX2, SSE4, ...), not just the best.
        for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
            hwy::SetSupportedTargetsForTest(target);
            simd.degenerate = simd.culled = simd.no_coverage = 0;  // they accumulate
            classify_triangles(in, 0, triangles, simd);
            SCOPED_TRACE(hwy::TargetName(target));
            expect_equal(simd, scalar);
        }
        hwy::SetSupportedTargetsForTest(0);
        // The reference against classify_triangle, triangle by triangle.
        std::uint32_t k = 0;
        for (std::size_t t = 0; t < triangles; ++t) {
            const std::uint32_t* c = &indices[3 * t];
            if (c[0] >= vertex_total || c[1] >= vertex_total || c[2] >= vertex_total) {
                ASSERT_EQ(scalar.triangle[k], t);
                ASSERT_EQ(scalar.flags[k++], ClassifyOutput::kSlow);
                continue;
            }
            const ScreenVertex &a = screen[first_vertex + c[0]], &b = screen[first_vertex + c[1]],
                               &d = screen[first_vertex + c[2]];
            const bool inside = (outcode[first_vertex + c[0]] | outcode[first_vertex + c[1]] |
                                 outcode[first_vertex + c[2]]) == 0;
            bool small = true;
            for (const ScreenVertex* v : {&a, &b, &d})
                small &= std::abs(std::int64_t{v->x}) < kClassifyCoordinateLimit &&
                         std::abs(std::int64_t{v->y}) < kClassifyCoordinateLimit;
            if (!inside || !small) {
                ASSERT_EQ(scalar.triangle[k], t);
                ASSERT_EQ(scalar.flags[k++], ClassifyOutput::kSlow);
                ++slow;
                continue;
            }
            TriangleBounds bounds{};
            switch (classify_triangle(a, b, d, settings, bounds)) {
                case SetupResult::Visible:
                    ASSERT_EQ(scalar.triangle[k], t);
                    EXPECT_EQ(scalar.min_x[k], bounds.min_x);
                    EXPECT_EQ(scalar.max_y[k], bounds.max_y);
                    EXPECT_EQ(scalar.flags[k++], bounds.front_facing ? ClassifyOutput::kFront : 0);
                    ++visible;
                    break;
                case SetupResult::Culled:
                    ++culled;
                    break;
                case SetupResult::NoCoverage:
                    ++no_coverage;
                    break;
                case SetupResult::Degenerate:
                    ++degenerate;
                    break;
            }
        }
        EXPECT_EQ(k, scalar.count);
    }
    // Every kind of case occurred often.
    EXPECT_GT(visible, 1000u);
    EXPECT_GT(slow, 1000u);
    EXPECT_GT(culled, 1000u);
    EXPECT_GT(no_coverage, 1000u);
    EXPECT_GT(degenerate, 100u);
}

}  // namespace
}  // namespace zraster::detail
