// The vertex stage's kernel (src/render/vertex_kernel.hpp): the SIMD version gives the scalar
// reference's outcodes bit for bit everywhere, and its screen vertices where the outcode is 0
// (elsewhere x = kOutsideScreenX in both), on every instruction set the machine runs; positions
// include NaN, infinity, huge values, points behind the eye and on w = 0, and points beyond the
// guard band. The world positions and unit normals it computes on request equal world_attributes()
// bit for bit.
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
        std::vector<ScreenVertex> screen_a(job.count), screen_b(job.count);
        std::vector<std::uint32_t> code_a(job.count), code_b(job.count);
        // World attributes (on most rounds; some meshes have no normals, some normals are 0).
        std::vector<glm::vec3> normals(job.count), world_a(job.count), world_b(job.count),
            normal_a(job.count), normal_b(job.count);
        for (glm::vec3& n : normals)
            n = rng.next() % 13 == 0
                    ? glm::vec3(0.0f)
                    : glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        const bool with_world = round % 5 != 0;
        job.model = glm::mat4(glm::vec4(rng.uniform(-2, 2), rng.uniform(-2, 2), 0.3f, 0.0f),
                              glm::vec4(0.1f, rng.uniform(-2, 2), rng.uniform(-2, 2), 0.0f),
                              glm::vec4(rng.uniform(-2, 2), 0.2f, rng.uniform(0.1, 3), 0.0f),
                              glm::vec4(rng.uniform(-5, 5), rng.uniform(-5, 5), 1.0f, 1.0f));
        job.normal_matrix = glm::transpose(glm::inverse(glm::mat3(job.model)));
        job.normals = round % 4 == 1 ? nullptr : normals.data();
        job.screen_out = screen_a.data();
        job.outcode_out = code_a.data();
        job.world_out = with_world ? world_a.data() : nullptr;
        job.normal_out = with_world ? normal_a.data() : nullptr;
        transform_vertices_scalar(job);
        for (std::size_t k = 0; with_world && k < job.count; ++k) {
            glm::vec3 world, normal;
            world_attributes(job.model, job.normal_matrix, positions[k],
                             job.normals ? normals[k] : glm::vec3(0, 1, 0), world, normal);
            ASSERT_EQ(std::memcmp(&world, &world_a[k], sizeof world), 0);
            ASSERT_EQ(std::memcmp(&normal, &normal_a[k], sizeof normal), 0);
        }
        for (std::size_t k = 0; k < job.count; ++k) {
            inside += code_a[k] == 0;
            non_finite += code_a[k] == kNonFinite;
            outside += code_a[k] != 0 && code_a[k] != kNonFinite;
        }
        job.screen_out = screen_b.data();
        job.outcode_out = code_b.data();
        job.world_out = with_world ? world_b.data() : nullptr;
        job.normal_out = with_world ? normal_b.data() : nullptr;
        for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
            hwy::SetSupportedTargetsForTest(target);
            SCOPED_TRACE(std::string(hwy::TargetName(target)) + " round " + std::to_string(round));
            transform_vertices(job);
            ASSERT_EQ(code_a, code_b);
            ASSERT_EQ(std::memcmp(world_a.data(), world_b.data(), job.count * 12), 0);
            ASSERT_EQ(std::memcmp(normal_a.data(), normal_b.data(), job.count * 12), 0);
            for (std::size_t k = 0; k < job.count; ++k) {
                if (code_a[k] != 0) {
                    // The classifier's sign of a vertex outside, whatever the path.
                    ASSERT_EQ(screen_a[k].x, kOutsideScreenX) << k;
                    ASSERT_EQ(screen_b[k].x, kOutsideScreenX) << k;
                    continue;
                }
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
