// The occlusion buffer against an exact z-buffer on random scenes: it never calls a visible box
// occluded, and it culls at least 95% of the boxes the exact z-buffer hides, on a city-like grid
// of buildings and on random large occluders. Also: every pixel's depth bound is at least the
// exact depth there.
#include <zraster/occlusion_buffer.hpp>

#include <gtest/gtest.h>

#include "occlusion/occlusion_test_util.hpp"

namespace zraster::test {
namespace {

struct Tally {
    int visible = 0, hidden = 0, culled = 0, false_occluded = 0, outside_but_seen = 0;
};

void check_scene(const OcclusionScene& scene, Tally& tally, const char* name, int seed) {
    const std::vector<Exact> exact = exact_visibility(scene);
    const std::vector<OcclusionResult> answers = buffer_answers(scene);
    for (std::size_t i = 0; i < exact.size(); ++i) {
        if (exact[i] == Exact::Visible) {
            ++tally.visible;
            tally.false_occluded += answers[i] == OcclusionResult::Occluded;
            tally.outside_but_seen += answers[i] == OcclusionResult::OutsideView;
            EXPECT_EQ(answers[i], OcclusionResult::Visible)
                << name << " seed " << seed << " box " << i << " is visible";
        } else if (exact[i] == Exact::Hidden) {
            ++tally.hidden;
            tally.culled += answers[i] == OcclusionResult::Occluded;
        }
    }
}

void report(const Tally& t, const char* name) {
    std::printf(
        "%s: %d visible boxes (0 may be called occluded: %d were), %d hidden, %d culled "
        "(%.1f%%)\n",
        name, t.visible, t.false_occluded, t.hidden, t.culled,
        t.hidden ? 100.0 * t.culled / t.hidden : 0.0);
    EXPECT_EQ(t.false_occluded, 0);
    EXPECT_EQ(t.outside_but_seen, 0);
    ASSERT_GT(t.hidden, 50) << "the scenes should hide many boxes";
    EXPECT_GE(t.culled, 0.95 * t.hidden) << name;
}

TEST(OcclusionConservative, CityGridNeverCullsVisibleAndCulls95Percent) {
    Tally tally;
    for (int seed = 1; seed <= 4; ++seed) check_scene(city_scene(seed, 150), tally, "city", seed);
    report(tally, "city");
}

TEST(OcclusionConservative, RandomLargeOccludersNeverCullVisibleAndCull95Percent) {
    Tally tally;
    for (int seed = 1; seed <= 6; ++seed)
        check_scene(random_occluder_scene(seed, 120), tally, "random occluders", seed);
    report(tally, "random occluders");
}

// Boxes peeking around wall edges, just behind them: many barely visible, none may be culled.
TEST(OcclusionConservative, BoxesPeekingAroundWallEdgesAreNeverCulledWhenVisible) {
    Tally tally;
    for (int seed = 1; seed <= 6; ++seed)
        check_scene(peeking_scene(seed, 200), tally, "peeking", seed);
    std::printf("peeking: %d visible boxes, %d hidden, %d culled\n", tally.visible, tally.hidden,
                tally.culled);
    EXPECT_EQ(tally.false_occluded, 0);
    EXPECT_GT(tally.visible, 150) << "the scene should have many barely visible boxes";
    EXPECT_GT(tally.culled, 100);
}

// Pixel by pixel: the buffer's depth bound is never nearer than the exact z-buffer's depth.
TEST(OcclusionConservative, DepthBoundsAreNeverNearerThanExactDepth) {
    for (int seed = 1; seed <= 10; ++seed) {
        const OcclusionScene scene = random_occluder_scene(seed + 100, 0);
        const RenderOptions options = exact_options(scene);
        const RenderResult exact = render(boxes_scene(scene.occluders), options);
        OcclusionBuffer buffer(scene.width, scene.height);
        const glm::mat4 vp = view_projection(scene);
        // The reference snaps vertices to 1/256 pixel: the margin the buffer must be given for
        // it (with 0, an edge passing within 1/512 pixel of a center may cover it here and not
        // there).
        OccluderOptions options_for_snapping;
        options_for_snapping.subpixel_margin = 1.0f / 256.0f;
        for (const Placed& p : scene.occluders) {
            const Mesh box = make_box(p.half_extent);
            buffer.render_occluders(std::span<const glm::vec3>(box.positions), box.indices,
                                    vp * p.transform, options_for_snapping);
        }
        std::vector<float> bounds(exact.targets.depth.size());
        buffer.depth_bounds(bounds);
        int covered = 0, nearer = 0;
        for (std::size_t i = 0; i < bounds.size(); ++i) {
            nearer += bounds[i] < exact.targets.depth[i];
            covered += exact.targets.depth[i] < 1.0f && bounds[i] < 1.0f;
        }
        EXPECT_EQ(nearer, 0) << "seed " << seed;
        EXPECT_GT(covered, 0);
    }
}

}  // namespace
}  // namespace zraster::test
