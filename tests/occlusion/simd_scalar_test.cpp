// The SIMD occlusion kernels against their scalar twins, bit for bit: the same tiles after
// thousands of random occluders (small and large, crossing the near plane and the screen edges)
// and the same answer for every random rectangle and box.
#include <zraster/occlusion_buffer.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cstring>

#include "occlusion/occlusion_test_util.hpp"
#include "support/simd_target_scope.hpp"

namespace zraster {
namespace {

void buffers_and_answers_match() {
    std::printf("SIMD target: %s\n", OcclusionBuffer::simd_target());
    for (const auto& [width, height] : {std::pair{320, 200}, std::pair{97, 61}}) {
        OcclusionBuffer simd(width, height), scalar(width, height);
        scalar.set_simd(false);
        SplitMix64 rng(5);
        std::vector<glm::vec4> clip;
        std::vector<std::uint32_t> indices;
        for (int t = 0; t < 6000; ++t) {
            // Mostly small triangles, some large ones, some crossing the near plane (z < -w).
            const double size = t % 10 == 0 ? 1.5 : rng.uniform(0.01, 0.2);
            const double cx = rng.uniform(-1.2, 1.2), cy = rng.uniform(-1.2, 1.2);
            const double depth = rng.uniform(-0.95, 0.95);
            for (int k = 0; k < 3; ++k) {
                const double w = rng.uniform(0.5, 3.0);
                const double z =
                    t % 17 == 0 ? rng.uniform(-1.5, 1.0) : depth + rng.uniform(-0.05, 0.05);
                clip.emplace_back((cx + rng.uniform(-size, size)) * w,
                                  (cy + rng.uniform(-size, size)) * w, z * w, w);
                indices.push_back(static_cast<std::uint32_t>(indices.size()));
            }
        }
        OccluderOptions options;
        options.cull = OccluderCull::None;
        // In pieces, testing between them, so the answers see partly filled buffers too.
        int occluded = 0;
        for (std::size_t begin = 0; begin < indices.size(); begin += 3 * 500) {
            const std::size_t n = std::min<std::size_t>(3 * 500, indices.size() - begin);
            const std::span<const std::uint32_t> part(indices.data() + begin, n);
            simd.render_occluders(std::span<const glm::vec4>(clip), part, options);
            scalar.render_occluders(std::span<const glm::vec4>(clip), part, options);
            const auto a = simd.raw_storage(), b = scalar.raw_storage();
            ASSERT_EQ(a.size(), b.size());
            ASSERT_EQ(std::memcmp(a.data(), b.data(), a.size()), 0) << "after " << begin / 3;
            for (int k = 0; k < 400; ++k) {
                const int x0 = static_cast<int>(rng.uniform(-10, width));
                const int y0 = static_cast<int>(rng.uniform(-10, height));
                const int x1 = x0 + static_cast<int>(rng.uniform(0, width / 2));
                const int y1 = y0 + static_cast<int>(rng.uniform(0, height / 2));
                const float depth = static_cast<float>(rng.uniform(0.0, 1.0));
                const OcclusionResult r = simd.test_pixel_rect(x0, y0, x1, y1, depth);
                ASSERT_EQ(r, scalar.test_pixel_rect(x0, y0, x1, y1, depth));
                occluded += r == OcclusionResult::Occluded;
                const glm::vec2 lo(rng.uniform(-1.1, 1.0), rng.uniform(-1.1, 1.0));
                const glm::vec2 hi = lo + glm::vec2(rng.uniform(0, 0.5), rng.uniform(0, 0.5));
                ASSERT_EQ(simd.test_rect(lo, hi, depth), scalar.test_rect(lo, hi, depth));
            }
        }
        EXPECT_GT(occluded, 100) << "the rectangles should not all be visible";
    }
}

TEST(OcclusionSimd, BuffersAndAnswersMatchTheScalarPath) {
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        const test::SimdTargetScope scope(target);
        SCOPED_TRACE(hwy::TargetName(target));
        buffers_and_answers_match();
        if (HasFatalFailure()) return;
    }
}

TEST(OcclusionSimd, SceneAnswersMatchTheScalarPath) {
    const test::OcclusionScene scene = test::city_scene(3, 400);
    const auto scalar = test::buffer_answers(scene, false);
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        const test::SimdTargetScope scope(target);
        EXPECT_EQ(test::buffer_answers(scene, true), scalar) << hwy::TargetName(target);
    }
}

}  // namespace
}  // namespace zraster
