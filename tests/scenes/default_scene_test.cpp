// The showcase scene must show what it promises: interpenetration, texturing, the three shading
// modes side by side, all in front of the recommended camera.
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <set>

namespace zraster {
namespace {

bool overlap(const Bounds3f& a, const Bounds3f& b) {
    for (int k = 0; k < 3; ++k)
        if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
}

TEST(DefaultScene, Contents) {
    const Scene s = make_procedural_scene("builtin:default");
    EXPECT_EQ(s.name, "builtin:default");
    EXPECT_GE(s.instances.size(), 5u);

    std::set<ShadingMode> modes;
    for (const Instance& i : s.instances) {
        ASSERT_LT(i.mesh, s.meshes.size());
        if (i.shading) modes.insert(*i.shading);
    }
    EXPECT_EQ(modes,
              (std::set<ShadingMode>{ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}));

    bool textured = false;
    for (const Mesh& m : s.meshes) {
        ASSERT_LT(m.material, s.materials.size());
        EXPECT_EQ(m.normals.size(), m.vertex_count()) << m.name;
        EXPECT_FALSE(m.bounds.empty()) << m.name;
        if (s.materials[m.material].base_color_texture) {
            textured = true;
            EXPECT_EQ(m.uvs.size(), m.vertex_count()) << m.name;
        }
    }
    EXPECT_TRUE(textured);
}

TEST(DefaultScene, ObjectsInterpenetrate) {
    const Scene s = make_procedural_scene("builtin:default");
    // Ignore the ground (everything touches it): two objects must overlap each other.
    int pairs = 0;
    for (std::size_t a = 0; a < s.instances.size(); ++a) {
        for (std::size_t b = a + 1; b < s.instances.size(); ++b) {
            const Instance& ia = s.instances[a];
            const Instance& ib = s.instances[b];
            if (ia.name == "ground" || ib.name == "ground") continue;
            pairs += overlap(s.meshes[ia.mesh].bounds.transformed(ia.transform),
                             s.meshes[ib.mesh].bounds.transformed(ib.transform));
        }
    }
    EXPECT_GE(pairs, 1);
    // And something is sunk below the ground plane.
    EXPECT_LT(s.bounds().lo.y, -0.1f);
}

TEST(DefaultScene, CameraSeesTheObjectsAndTheHorizon) {
    const auto camera = builtin_camera("builtin:default");
    ASSERT_TRUE(camera.has_value());
    EXPECT_GT(camera->eye.y, 1.5);
    EXPECT_LT(camera->eye.y, 4.0);
    EXPECT_LT(camera->target.y, camera->eye.y);  // looking slightly down
    const glm::dvec3 forward = glm::normalize(camera->target - camera->eye);
    const double pitch_degrees = glm::degrees(std::asin(forward.y));
    EXPECT_LT(pitch_degrees, 0.0);
    // The horizon (pitch 0) is inside the vertical field of view.
    EXPECT_LT(-pitch_degrees, camera->fovy_degrees / 2);

    const Scene s = make_procedural_scene("builtin:default");
    const double aspect = 16.0 / 9.0;
    const double tan_y = std::tan(glm::radians(camera->fovy_degrees) / 2);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera->up));
    const glm::dvec3 up = glm::cross(right, forward);
    for (const Instance& i : s.instances) {
        if (i.name == "ground") continue;
        // Every object's center is in the 16:9 frame, between the near and far planes.
        const glm::dvec3 c{s.meshes[i.mesh].bounds.transformed(i.transform).center()};
        const glm::dvec3 d = c - camera->eye;
        const double z = glm::dot(d, forward);
        EXPECT_GT(z, camera->near) << i.name;
        EXPECT_LT(z, camera->far) << i.name;
        EXPECT_LT(std::abs(glm::dot(d, up)) / z, tan_y) << i.name;
        EXPECT_LT(std::abs(glm::dot(d, right)) / z, tan_y * aspect) << i.name;
    }
    // The ground's far edge is within the far plane.
    const Bounds3f ground = s.bounds();
    EXPECT_LT(glm::length(glm::dvec3(ground.lo.x, 0.0, ground.lo.z) - camera->eye), camera->far);
    EXPECT_FALSE(builtin_camera("builtin:sphere").has_value());
}

}  // namespace
}  // namespace zraster
