// RenderOptions::occlusion_cull: the image (color, depth, ids) is bit-identical with and without
// it, while RenderStats counts the instances it skipped; it stays off where it could change the
// image (reversed-Z, D24, wireframe).
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <set>

#include "occlusion/occlusion_test_util.hpp"

namespace zraster {
namespace {

// A wall in front of a field of spheres; a few spheres beside the wall stay visible.
Scene wall_scene() {
    Scene scene;
    scene.meshes.push_back(make_box(glm::vec3(7.0f, 4.5f, 0.5f)));
    scene.meshes.push_back(make_uv_sphere(0.6f, 8, 12));
    Instance wall;
    wall.mesh = 0;
    wall.transform = test::place({0.0f, 0.0f, -8.0f});
    scene.instances.push_back(wall);
    SplitMix64 rng(3);
    for (int i = 0; i < 300; ++i) {
        Instance s;
        s.mesh = 1;
        const float x = static_cast<float>(rng.uniform(-14.0, 14.0));
        const float y = static_cast<float>(rng.uniform(-5.0, 5.0));
        const float z = static_cast<float>(rng.uniform(-30.0, -10.0));
        s.transform = test::place({x, y, z});
        scene.instances.push_back(s);
    }
    return scene;
}

RenderOptions wall_options() {
    return test::wall_view_options();
}

void expect_same_image(const RenderTargets& a, const RenderTargets& b) {
    EXPECT_TRUE(a.color == b.color);
    EXPECT_TRUE(a.depth == b.depth);
    EXPECT_TRUE(a.instance_id == b.instance_id);
    EXPECT_TRUE(a.primitive_id == b.primitive_id);
}

TEST(OcclusionCull, WallHidesInstancesAndTheImageIsUnchanged) {
    const Scene scene = wall_scene();
    RenderOptions options = wall_options();
    const RenderResult plain = render(scene, options);
    options.occlusion_cull = true;
    const RenderResult culled = render(scene, options);
    expect_same_image(plain.targets, culled.targets);
    EXPECT_EQ(plain.stats.instances_occlusion_culled, 0u);
    EXPECT_GT(culled.stats.instances_occlusion_culled, 50u);
    EXPECT_LT(culled.stats.triangles_in, plain.stats.triangles_in);
    // Some spheres are visible beside the wall, and were not culled.
    std::set<std::int32_t> seen(plain.targets.instance_id.begin(), plain.targets.instance_id.end());
    EXPECT_GT(seen.size(), 5u);
    // The scalar path culls the same.
    options.simd = false;
    const RenderResult scalar = render(scene, options);
    expect_same_image(plain.targets, scalar.targets);
    EXPECT_EQ(scalar.stats.instances_occlusion_culled, culled.stats.instances_occlusion_culled);
}

// RenderResult::instance_outcomes names each instance's fate, agreeing with the counts: every
// occlusion-culled instance has no pixel in the unculled image, every visible one was drawn, and
// nothing is recorded unless asked for.
TEST(OcclusionCull, InstanceOutcomesNameWhatWasSkipped) {
    const Scene scene = wall_scene();
    RenderOptions options = wall_options();
    options.id_targets = true;
    const RenderResult plain = render(scene, options);
    options.occlusion_cull = true;
    EXPECT_TRUE(render(scene, options).instance_outcomes.empty());
    options.report_instance_outcomes = true;
    Renderer renderer;
    const RenderResult& culled = renderer.render(scene, options);
    ASSERT_EQ(culled.instance_outcomes.size(), scene.instances.size());
    const std::set<std::int32_t> seen(plain.targets.instance_id.begin(),
                                      plain.targets.instance_id.end());
    std::size_t counts[4] = {};
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const InstanceOutcome outcome = culled.instance_outcomes[i];
        ++counts[std::size_t(outcome)];
        if (outcome == InstanceOutcome::OcclusionCulled) {
            EXPECT_FALSE(seen.count(std::int32_t(i))) << i;
        }
        if (seen.count(std::int32_t(i))) {
            EXPECT_EQ(outcome, InstanceOutcome::Drawn) << i;
        }
    }
    EXPECT_EQ(counts[std::size_t(InstanceOutcome::OcclusionCulled)],
              culled.stats.instances_occlusion_culled);
    EXPECT_EQ(counts[std::size_t(InstanceOutcome::FrustumCulled)],
              culled.stats.instances_frustum_culled);
    EXPECT_GT(culled.stats.instances_occlusion_culled, 50u);
    // The Renderer's next frame without the request records nothing.
    options.report_instance_outcomes = false;
    EXPECT_TRUE(renderer.render(scene, options).instance_outcomes.empty());
}

TEST(OcclusionCull, CityScenesAreUnchanged) {
    for (int seed = 1; seed <= 3; ++seed) {
        const test::OcclusionScene s = test::city_scene(seed, 300);
        std::vector<test::Placed> all = s.occluders;
        all.insert(all.end(), s.boxes.begin(), s.boxes.end());
        const Scene scene = test::boxes_scene(all);
        RenderOptions options = test::exact_options(s);
        options.color_target = true;
        options.threads = 2;
        const RenderResult plain = render(scene, options);
        options.occlusion_cull = true;
        Renderer renderer;
        const RenderResult& culled = renderer.render(scene, options);
        expect_same_image(plain.targets, culled.targets);
        EXPECT_GT(culled.stats.instances_occlusion_culled, 50u) << "seed " << seed;
        EXPECT_EQ(culled.stats.instances_frustum_culled, plain.stats.instances_frustum_culled);
    }
}

TEST(OcclusionCull, OffWhereItCouldChangeTheImage) {
    const Scene scene = wall_scene();
    RenderOptions options = wall_options();
    options.occlusion_cull = true;
    options.depth_format = DepthFormat::D24;
    EXPECT_EQ(render(scene, options).stats.instances_occlusion_culled, 0u);
    options = wall_options();
    options.occlusion_cull = true;
    options.camera->reversed_z = true;
    EXPECT_EQ(render(scene, options).stats.instances_occlusion_culled, 0u);
    options = wall_options();
    options.occlusion_cull = true;
    options.edges = RenderOptions::Edges::Wireframe;
    EXPECT_EQ(render(scene, options).stats.instances_occlusion_culled, 0u);
}

}  // namespace
}  // namespace zraster
