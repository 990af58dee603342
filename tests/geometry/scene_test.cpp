#include <zraster/scene.hpp>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace zraster {
namespace {

Mesh triangle(const std::string& name) {
    Mesh m;
    m.name = name;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    return m;
}

TEST(Scene, FromMeshesMakesOneIdentityInstanceEach) {
    std::vector<Mesh> meshes;
    meshes.push_back(triangle("a"));
    meshes.push_back(triangle("b"));
    meshes[1].positions.push_back({0, 0, 2});
    const Scene s = scene_from_meshes(std::move(meshes));
    ASSERT_EQ(s.instances.size(), 2u);
    for (std::uint32_t i = 0; i < 2; ++i) {
        EXPECT_EQ(s.instances[i].mesh, i);
        EXPECT_EQ(s.instances[i].transform, glm::mat4(1.0f));
        EXPECT_FALSE(s.instances[i].shading.has_value());
    }
    EXPECT_EQ(s.instances[1].name, "b");
    EXPECT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(s.triangle_count(), 2u);
    EXPECT_EQ(s.vertex_count(), 7u);
    // Bounds are filled in.
    EXPECT_EQ(s.meshes[1].bounds.hi, glm::vec3(1, 1, 2));
    EXPECT_EQ(s.bounds().lo, glm::vec3(0, 0, 0));
    EXPECT_EQ(s.bounds().hi, glm::vec3(1, 1, 2));
}

TEST(Scene, InstancesAreCountedAndTransformed) {
    Scene s = scene_from_meshes({triangle("t")});
    s.instances.push_back({.mesh = 0,
                           .transform = glm::translate(glm::mat4(1.0f), {10, 0, 0}),
                           .shading = ShadingMode::Flat,
                           .name = "moved"});
    EXPECT_EQ(s.triangle_count(), 2u);
    EXPECT_EQ(s.vertex_count(), 6u);
    const auto world = s.world_positions();
    ASSERT_EQ(world.size(), 6u);
    EXPECT_EQ(world[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(world[4], glm::vec3(11, 0, 0));
    const Bounds3f b = s.bounds();
    EXPECT_EQ(b.lo, glm::vec3(0, 0, 0));
    EXPECT_EQ(b.hi, glm::vec3(11, 1, 0));
    // The bounds contain every world position.
    for (const glm::vec3& p : world)
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(p[k] >= b.lo[k] && p[k] <= b.hi[k]);
}

TEST(Scene, EmptySceneHasEmptyBounds) {
    const Scene s;
    EXPECT_TRUE(s.bounds().empty());
    EXPECT_EQ(s.triangle_count(), 0u);
    EXPECT_TRUE(s.world_positions().empty());
}

}  // namespace
}  // namespace zraster
