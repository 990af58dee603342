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
    EXPECT_TRUE(has_line(text, "  material 1 'Texture': base color (1, 1, 1), texture 211x211"))
        << text;
    EXPECT_EQ(text.find("warnings"), std::string::npos);
}

TEST(DescribeScene, ExactWorldBoundsWarningsAndLongLists) {
    Mesh mesh;
    mesh.name = "tri";
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.indices = {0, 1, 2};
    Scene scene = scene_from_meshes({mesh});
    scene.source = "generated";
    for (int i = 1; i < 60; ++i) {
        Instance instance = scene.instances[0];
        instance.transform[3] = glm::vec4(static_cast<float>(i), 0, 0, 1);
        instance.name = "copy";
        scene.instances.push_back(instance);
    }
    scene.warnings.push_back("generated: something odd");
    const std::string text = describe_scene(scene);
    EXPECT_TRUE(has_line(text, "instances: 60")) << text;
    EXPECT_TRUE(has_line(text, "  instance 0 'tri': mesh 0, identity")) << text;
    EXPECT_TRUE(has_line(text, "  instance 1 'copy': mesh 0, translation (1, 0, 0)")) << text;
    EXPECT_TRUE(has_line(text, "  ... and 10 more")) << text;
    EXPECT_TRUE(has_line(text, "total: 60 triangles, 180 vertices (over instances)")) << text;
    EXPECT_TRUE(has_line(text, "world bounds: (0, 0, 0) - (60, 1, 0)")) << text;
    EXPECT_TRUE(has_line(text, "  material 0 'default': base color (0.8, 0.75, 0.7), texture none"))
        << text;
    EXPECT_TRUE(has_line(text, "warnings: 1")) << text;
    EXPECT_TRUE(has_line(text, "  generated: something odd")) << text;
}

}  // namespace
}  // namespace zraster
