// The `zraster info` summary.
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

bool has_line(const std::string& text, const std::string& line) {
    return text.find(line + "\n") != std::string::npos;
}

TEST(DescribeScene, BoxTextured) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const auto path = test::shared_data("meshes/gltf/BoxTextured.glb");
    const std::string text = describe_scene(load_scene(path));
    EXPECT_TRUE(has_line(text, "source: " + path.string())) << text;
    EXPECT_TRUE(has_line(text, "meshes: 1")) << text;
    EXPECT_TRUE(has_line(text,
                         "  mesh 0 'Mesh': 12 triangles, 24 vertices, material 1 'Texture', "
                         "bounds (-0.5, -0.5, -0.5) - (0.5, 0.5, 0.5)"))
        << text;
    EXPECT_TRUE(has_line(text, "instances: 1")) << text;
    EXPECT_TRUE(has_line(text,
                         "  instance 0 'nodes[1]': mesh 0, "
                         "matrix [1 0 0 0; 0 0 1 0; 0 -1 0 0; 0 0 0 1]"))
        << text;
    EXPECT_TRUE(has_line(text, "total: 12 triangles, 24 vertices (over instances)")) << text;
    EXPECT_TRUE(has_line(text, "world bounds: (-0.5, -0.5, -0.5) - (0.5, 0.5, 0.5)")) << text;
    EXPECT_TRUE(has_line(text, "materials: 2")) << text;
    // A glTF material without alphaMode: opaque.
    EXPECT_TRUE(has_line(text,
                         "  material 1 'Texture': base color (1, 1, 1), texture 211x211, "
                         "alpha opaque"))
        << text;
    EXPECT_EQ(text.find("warnings"), std::string::npos);
}

TEST(DescribeScene, ExactWorldBoundsWarningsAndLongLists) {
    Mesh mesh;
    mesh.name = "tri";
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2};
    Scene scene = scene_from_meshes({mesh});
    scene.name = "generated";
    for (int i = 1; i < 60; ++i) {
        Instance instance = scene.instances[0];
        instance.transform[3] = glm::vec4(static_cast<float>(i), 0, 0, 1);
        instance.name = "copy";
        scene.instances.push_back(instance);
    }
    const std::string text = describe_scene(scene, {"generated: something odd"});
    EXPECT_TRUE(has_line(text, "instances: 60")) << text;
    EXPECT_TRUE(has_line(text, "  instance 0 'tri': mesh 0, identity")) << text;
    EXPECT_TRUE(has_line(text, "  instance 1 'copy': mesh 0, translation (1, 0, 0)")) << text;
    EXPECT_TRUE(has_line(text, "  ... and 10 more")) << text;
    EXPECT_TRUE(has_line(text, "total: 60 triangles, 180 vertices (over instances)")) << text;
    EXPECT_TRUE(has_line(text, "world bounds: (0, 0, 0) - (60, 1, 0)")) << text;
    EXPECT_TRUE(has_line(text,
                         "  material 0 'default': base color (0.8, 0.75, 0.7), texture none, "
                         "alpha blend (opacity 1), alpha 1 everywhere"))
        << text;
    EXPECT_TRUE(has_line(text, "warnings: 1")) << text;
    EXPECT_TRUE(has_line(text, "  generated: something odd")) << text;
}

std::shared_ptr<const Texture> describe_texture(int width, std::uint8_t red, std::uint8_t alpha) {
    std::vector<std::uint8_t> rgba(std::size_t(width) * 4, 255);
    rgba[0] = red;
    rgba[3] = alpha;
    return std::make_shared<const Texture>(width, 1, rgba);
}

// Each material's alpha mode and whether its alpha can be below 1, naming every factor that can
// make it so (material.hpp: opacity x texture alpha x opacity texture red).
TEST(DescribeScene, MaterialAlpha) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2};
    Scene scene = scene_from_meshes({mesh});
    const auto add = [&](const std::string& name, AlphaMode mode, float opacity, auto&& change) {
        Material m;
        m.name = name;
        m.alpha_mode = mode;
        m.opacity = opacity;
        change(m);
        scene.materials.push_back(m);
    };
    const auto none = [](Material&) {};
    add("wall", AlphaMode::Opaque, 1.0f, [](Material& m) {
        m.base_color_texture = describe_texture(2, 255, 0);  // alpha ignored
    });
    add("leaf", AlphaMode::Mask, 1.0f, [](Material& m) {
        m.alpha_cutoff = 0.3f;
        m.base_color_texture = describe_texture(2, 255, 0);
    });
    add("fence", AlphaMode::Mask, 0.8f, none);
    add("solid", AlphaMode::Mask, 1.0f, [](Material& m) {
        m.base_color_texture = describe_texture(4, 0, 255);  // dark but opaque
    });
    add("glass", AlphaMode::Blend, 0.5f, none);
    add("decal", AlphaMode::Blend, 0.25f, [](Material& m) {
        m.base_color_texture = describe_texture(2, 255, 10);
        m.opacity_texture = describe_texture(3, 128, 255);
    });
    add("white", AlphaMode::Blend, 1.0f, [](Material& m) {
        m.opacity_texture = describe_texture(3, 255, 0);  // read in red: 1 everywhere
    });
    const std::string text = describe_scene(scene);
    const std::string base = ": base color (0.8, 0.75, 0.7), texture ";
    EXPECT_TRUE(has_line(text, "  material 1 'wall'" + base + "2x1, alpha opaque")) << text;
    EXPECT_TRUE(has_line(text, "  material 2 'leaf'" + base +
                                   "2x1, alpha mask (cutoff 0.3), alpha below 1 from texture "
                                   "alpha"))
        << text;
    EXPECT_TRUE(has_line(text, "  material 3 'fence'" + base +
                                   "none, alpha mask (cutoff 0.5, opacity 0.8), alpha below 1 "
                                   "from opacity"))
        << text;
    EXPECT_TRUE(has_line(
        text, "  material 4 'solid'" + base + "4x1, alpha mask (cutoff 0.5), alpha 1 everywhere"))
        << text;
    EXPECT_TRUE(has_line(text, "  material 5 'glass'" + base +
                                   "none, alpha blend (opacity 0.5), alpha below 1 from opacity"))
        << text;
    EXPECT_TRUE(has_line(text, "  material 6 'decal'" + base +
                                   "2x1, opacity texture 3x1, alpha blend (opacity 0.25), alpha "
                                   "below 1 from opacity, texture alpha, opacity texture"))
        << text;
    EXPECT_TRUE(has_line(text, "  material 7 'white'" + base +
                                   "none, opacity texture 3x1, alpha blend (opacity 1), alpha 1 "
                                   "everywhere"))
        << text;
}

}  // namespace
}  // namespace zraster
