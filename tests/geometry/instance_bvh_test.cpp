// InstanceBvh: a frustum query returns exactly the boxes a brute-force outside_planes test keeps,
// on random box sets and random cameras (including empty and non-finite boxes), and the planes
// agree with clip-space outcodes.
#include <zraster/instance_bvh.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <limits>

namespace zraster {
namespace {

std::vector<std::uint32_t> brute_force(std::span<const Bounds3f> boxes,
                                       std::span<const glm::vec4> planes) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (!outside_planes(boxes[i], planes)) out.push_back(i);
    return out;
}

TEST(InstanceBvh, SameVisibleSetAsBruteForce) {
    SplitMix64 rng(17);
    for (const std::size_t count : {0u, 1u, 3u, 5u, 64u, 1000u, 20000u}) {
        std::vector<Bounds3f> boxes(count);
        for (Bounds3f& b : boxes) {
            const glm::vec3 c(rng.uniform(-200, 200), rng.uniform(-20, 60), rng.uniform(-200, 200));
            const glm::vec3 e(rng.uniform(0.1, 8), rng.uniform(0.1, 8), rng.uniform(0.1, 8));
            b = Bounds3f{c - e, c + e};
        }
        if (count >= 64) {
            boxes[3] = Bounds3f{};  // empty
            boxes[7].hi.x = std::numeric_limits<float>::quiet_NaN();
        }
        const InstanceBvh bvh(boxes);
        EXPECT_EQ(bvh.size(), count);
        int nonempty = 0;
        for (int view = 0; view < 40; ++view) {
            Camera camera;
            camera.eye = {rng.uniform(-150, 150), rng.uniform(1, 80), rng.uniform(-150, 150)};
            camera.target = {rng.uniform(-100, 100), 0.0, rng.uniform(-100, 100)};
            camera.fovy_degrees = rng.uniform(20, 100);
            camera.near = 0.5;
            camera.far = rng.uniform(30, 400);
            camera.reversed_z = view % 5 == 0;
            if (view % 7 == 0) {
                camera.projection = Camera::Projection::Orthographic;
                camera.ortho_height = 60.0;
            }
            const auto planes =
                frustum_planes(camera.view_projection(1.5), camera.clip_depth_range());
            std::vector<std::uint32_t> found;
            bvh.query(planes, found);
            const std::vector<std::uint32_t> expected = brute_force(boxes, planes);
            ASSERT_EQ(found, expected) << count << " boxes, view " << view;
            nonempty += !found.empty() && found.size() < count;
        }
        if (count >= 1000) {
            EXPECT_GT(nonempty, 10) << "the views should cull some boxes";
        }
    }
}

// The planes agree with the clip-space test: a point well inside clip space is inside all six
// planes, a point well outside one clip plane is outside that plane.
TEST(InstanceBvh, FrustumPlanesMatchClipSpace) {
    SplitMix64 rng(2);
    Camera camera;
    camera.eye = {3, 4, 5};
    camera.target = {0, 0, 0};
    camera.near = 0.5;
    camera.far = 40.0;
    for (const bool reversed : {false, true}) {
        camera.reversed_z = reversed;
        const glm::mat4 vp = camera.view_projection(1.3);
        const auto planes = frustum_planes(vp, camera.clip_depth_range());
        for (int i = 0; i < 2000; ++i) {
            const glm::vec3 p(rng.uniform(-30, 30), rng.uniform(-30, 30), rng.uniform(-30, 30));
            const glm::vec4 c = vp * glm::vec4(p, 1.0f);
            const float lo = reversed ? 0.0f : -c.w;
            const bool inside = c.w > 0 && std::abs(c.x) < 0.99f * c.w &&
                                std::abs(c.y) < 0.99f * c.w && c.z > lo + 0.01f * c.w &&
                                c.z < 0.99f * c.w;
            const Bounds3f point{p, p};
            if (inside) {
                EXPECT_FALSE(outside_planes(point, planes)) << i;
            }
            if (c.w > 0 && c.x > 1.01f * c.w) {
                EXPECT_TRUE(outside_planes(point, planes)) << i;
            }
        }
    }
}

}  // namespace
}  // namespace zraster
