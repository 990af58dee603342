// The vertex stage's kernel (src/render/vertex_kernel.hpp): the SIMD version gives the scalar
// reference's clip positions and outcodes bit for bit everywhere, and its screen vertices where
// the outcode is 0, on every instruction set the machine runs; positions include NaN, infinity,
// huge values, points behind the eye and on w = 0, and points beyond the guard band.
#include <zraster/camera.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstring>
#include <limits>
#include <vector>

#include "render/frame.hpp"
#include "render/vertex_kernel.hpp"

namespace zraster::detail {
namespace {

TEST(VertexKernel, SimdMatchesScalarOnEveryTarget) {
    SplitMix64 rng(17);
    const float inf = std::numeric_limits<float>::infinity();
    int inside = 0, outside = 0, non_finite = 0;
    for (int round = 0; round < 40; ++round) {
        Camera camera;
        camera.eye = {rng.uniform(-1, 1), rng.uniform(-1, 1), 5.0};
        camera.near = rng.uniform(0.01, 1.0);
        camera.far = 50.0;
        camera.reversed_z = rng.next() % 2;
        std::vector<glm::vec3> positions(1 + rng.next() % 500);
        for (glm::vec3& p : positions) {
            p = glm::vec3(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-3, 3));
            switch (rng.next() % 40) {
                case 0:
                    p.x = std::numeric_limits<float>::quiet_NaN();
                    break;
                case 1:
                    p.y = -inf;
                    break;
                case 2:
                    p.z = 1e30f;
                    break;
                case 3:
                    p *= 1e6f;
                    break;  // beyond the guard band
                case 4:
                    p = glm::vec3(camera.eye);
                    break;  // the eye: w = 0 (near-clipped)
                default:
                    break;
            }
        }
        const int width = 1 + int(rng.next() % 2000), height = 1 + int(rng.next() % 2000);
        VertexJob job;
        job.positions = positions.data();
        job.count = positions.size();
        job.mvp = camera.view_projection(double(width) / height);
        job.clip.depth_range = camera.clip_depth_range();
        job.clip.guard_x = float(kGuardBand / (0.5 * width));
        job.clip.guard_y = float(kGuardBand / (0.5 * height));
        job.setup.viewport = {width, height};
        job.setup.depth_range = camera.clip_depth_range();
        std::vector<glm::vec4> clip_a(job.count), clip_b(job.count);
        std::vector<ScreenVertex> screen_a(job.count), screen_b(job.count);
        std::vector<std::uint32_t> code_a(job.count), code_b(job.count);
        job.clip_out = clip_a.data();
        job.screen_out = screen_a.data();
        job.outcode_out = code_a.data();
        transform_vertices_scalar(job);
        for (std::size_t k = 0; k < job.count; ++k) {
            inside += code_a[k] == 0;
            non_finite += code_a[k] == kNonFinite;
            outside += code_a[k] != 0 && code_a[k] != kNonFinite;
        }
        job.clip_out = clip_b.data();
        job.screen_out = screen_b.data();
        job.outcode_out = code_b.data();
        for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
            hwy::SetSupportedTargetsForTest(target);
            SCOPED_TRACE(std::string(hwy::TargetName(target)) + " round " + std::to_string(round));
            transform_vertices(job);
            ASSERT_EQ(std::memcmp(clip_a.data(), clip_b.data(), job.count * sizeof(glm::vec4)), 0);
            ASSERT_EQ(code_a, code_b);
            for (std::size_t k = 0; k < job.count; ++k) {
                if (code_a[k] != 0) continue;
                ASSERT_EQ(std::memcmp(&screen_a[k], &screen_b[k], sizeof(ScreenVertex)), 0) << k;
            }
        }
        hwy::SetSupportedTargetsForTest(0);
    }
    EXPECT_GT(inside, 1000);
    EXPECT_GT(outside, 300);
    EXPECT_GT(non_finite, 50);
}

}  // namespace
}  // namespace zraster::detail
