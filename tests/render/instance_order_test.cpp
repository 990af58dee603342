// RenderOptions::instance_order: drawing instances nearest first gives the same image as
// submission order when no two instances meet at exactly equal depth, and hierarchical z then
// skips the work hidden behind the nearest instance (fragments passed drop to about one
// layer's worth).
#include <zraster/render.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include "occlusion/occlusion_test_util.hpp"

namespace zraster {
namespace {

// Walls one behind the other, submitted farthest first (the worst order for a z-buffer), each
// with its own material so the image shows which wall won, and a sphere in front.
Scene layered_scene(int layers) {
    Scene scene;
    scene.meshes.push_back(make_box(glm::vec3(6.0f, 4.0f, 0.2f)));
    scene.meshes.push_back(make_uv_sphere(0.8f, 16, 24));
    for (int i = 0; i < layers; ++i) {
        Instance wall;
        wall.mesh = 0;
        wall.transform = test::place({0.0f, 0.0f, -8.0f - 1.5f * float(layers - 1 - i)});
        scene.instances.push_back(wall);
    }
    Instance ball;
    ball.mesh = 1;
    ball.transform = test::place({1.0f, 0.5f, -4.0f});
    scene.instances.push_back(ball);
    return scene;
}

RenderOptions layered_options(InstanceOrder order) {
    RenderOptions o = test::wall_view_options(320, 200);
    o.instance_order = order;
    return o;
}

TEST(InstanceOrder, FrontToBackKeepsTheImageAndSkipsHiddenLayers) {
    const Scene scene = layered_scene(8);
    const RenderResult submitted = render(scene, layered_options(InstanceOrder::Submission));
    const RenderResult sorted = render(scene, layered_options(InstanceOrder::FrontToBack));
    EXPECT_TRUE(sorted.targets.color == submitted.targets.color);
    EXPECT_TRUE(sorted.targets.depth == submitted.targets.depth);
    // Instance ids are the scene's, whatever the drawing order.
    EXPECT_TRUE(sorted.targets.instance_id == submitted.targets.instance_id);
    EXPECT_TRUE(sorted.targets.primitive_id == submitted.targets.primitive_id);
    // The nearest wall (the last submitted, id 7) and the ball (id 8) are what is seen.
    std::size_t wall = 0, ball = 0;
    for (const std::int32_t id : sorted.targets.instance_id) {
        wall += id == 7;
        ball += id == 8;
        ASSERT_TRUE(id == -1 || id == 7 || id == 8) << id;
    }
    EXPECT_GT(wall, 10000u);
    EXPECT_GT(ball, 500u);
    // Back to front, every wall passes the depth test where it is seen; front to back, the
    // farther walls fail it, mostly whole blocks at a time.
    EXPECT_GT(submitted.stats.fragments_passed, 3 * wall);  // farther walls look smaller
    EXPECT_LT(sorted.stats.fragments_passed, 2 * (wall + ball));
    EXPECT_GT(sorted.stats.blocks_hidden, 5 * submitted.stats.blocks_hidden + 100);
}

// Drawing order is deterministic: ties in distance keep submission order, and the same
// options give the same bits on every thread count.
TEST(InstanceOrder, TiesKeepSubmissionOrderAndThreadsDoNotMatter) {
    Scene scene = layered_scene(3);
    // A copy of the ball at the same place: equal distance, equal depth everywhere. Under LESS
    // the first drawn keeps every pixel, and that must be the first submitted (id 3).
    scene.instances.push_back(scene.instances.back());
    RenderOptions o = layered_options(InstanceOrder::FrontToBack);
    const RenderResult two = render(scene, o);
    std::size_t first = 0;
    for (const std::int32_t id : two.targets.instance_id) {
        first += id == 3;
        ASSERT_NE(id, 4);
    }
    EXPECT_GT(first, 500u);
    o.threads = 1;
    const RenderResult one = render(scene, o);
    EXPECT_TRUE(one.targets.color == two.targets.color);
    EXPECT_TRUE(one.targets.instance_id == two.targets.instance_id);
}

}  // namespace
}  // namespace zraster
