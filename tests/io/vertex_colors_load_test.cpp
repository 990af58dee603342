// Vertex colors as the loaders fill Mesh::colors: glTF COLOR_0 (float, and normalized 8- and
// 16-bit, RGB or RGBA), PLY red/green/blue/alpha, components outside [0, 1] clamped with a
// warning; the same through the worker process; `zraster info` reports them.
#include <zraster/load.hpp>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

// The file loaded in process and through the worker: the colors must agree bit for bit, and so
// must the warnings. Returns the in-process scene.
Scene load_colors_both_ways(const std::filesystem::path& path,
                            std::vector<std::string>* warnings = nullptr) {
    SCOPED_TRACE(path.string());
    LoadOptions in_process_options, worker_options;
    worker_options.isolation = LoadIsolation::WorkerProcess;
    std::vector<std::string> in_process_warnings, worker_warnings;
    Scene in_process = load_scene(path, in_process_options, &in_process_warnings);
    const Scene worker = load_scene(path, worker_options, &worker_warnings);
    EXPECT_EQ(in_process_warnings, worker_warnings);
    EXPECT_EQ(in_process.meshes.size(), worker.meshes.size());
    for (std::size_t m = 0; m < std::min(in_process.meshes.size(), worker.meshes.size()); ++m)
        EXPECT_TRUE(in_process.meshes[m].colors == worker.meshes[m].colors) << "mesh " << m;
    if (warnings != nullptr) *warnings = in_process_warnings;
    return in_process;
}

// One triangle whose COLOR_0 is `colors` (raw bytes) of `type` ("VEC3"/"VEC4") and component
// type (5126 float, 5121 unsigned byte, 5123 unsigned short), normalized where it is not float.
std::string color_gltf(const std::string& colors, const char* type, int component_type) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    bin += colors;
    while (bin.size() % 4 != 0) bin += '\0';
    const std::string normalized = component_type == 5126 ? "" : R"(,"normalized":true)";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"COLOR_0":1},"material":0}]}],)"
           R"("materials":[{"name":"m","alphaMode":"BLEND"}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":)" +
           std::to_string(component_type) + normalized + R"(,"count":3,"type":")" + type +
           R"("}],"bufferViews":[{"buffer":0,"byteLength":36},)"
           R"({"buffer":0,"byteOffset":36,"byteLength":)" +
           std::to_string(colors.size()) + R"(}],"buffers":[{"byteLength":)" +
           std::to_string(bin.size()) + R"(,"uri":"data:application/octet-stream;base64,)" +
           test::base64(bin) + R"("}]})";
}

template <class T, std::size_t N>
std::string bytes_of(const std::array<T, N>& values) {
    return std::string(reinterpret_cast<const char*>(values.data()), sizeof(T) * N);
}

// The loaded colors of the one mesh, in file vertex order (a triangle's vertices stay in order).
std::vector<glm::vec4> only_colors(const Scene& scene) {
    EXPECT_EQ(scene.meshes.size(), 1u);
    return scene.meshes.at(0).colors;
}

TEST(VertexColorsLoad, GltfFloatRgba) {
    const std::array<float, 12> c = {1, 0, 0, 0.25f, 0, 1, 0, 0.5f, 0, 0, 1, 1};
    const Scene scene = load_colors_both_ways(
        test::write_fixture("vc-float4", "m.gltf", color_gltf(bytes_of(c), "VEC4", 5126)));
    const std::vector<glm::vec4> colors = only_colors(scene);
    ASSERT_EQ(colors.size(), 3u);
    EXPECT_EQ(colors[0], glm::vec4(1, 0, 0, 0.25f));
    EXPECT_EQ(colors[1], glm::vec4(0, 1, 0, 0.5f));
    EXPECT_EQ(colors[2], glm::vec4(0, 0, 1, 1));
}

TEST(VertexColorsLoad, GltfFloatRgbHasAlphaOne) {
    const std::array<float, 9> c = {1, 0.5f, 0, 0, 1, 0.5f, 0.5f, 0, 1};
    const std::vector<glm::vec4> colors = only_colors(load_colors_both_ways(
        test::write_fixture("vc-float3", "m.gltf", color_gltf(bytes_of(c), "VEC3", 5126))));
    ASSERT_EQ(colors.size(), 3u);
    EXPECT_EQ(colors[0], glm::vec4(1, 0.5f, 0, 1));
    EXPECT_EQ(colors[2], glm::vec4(0.5f, 0, 1, 1));
}

TEST(VertexColorsLoad, GltfNormalizedIntegersAreScaledToUnit) {
    const std::array<std::uint8_t, 12> bytes = {255, 0, 0, 64, 0, 255, 0, 128, 0, 0, 255, 255};
    const std::vector<glm::vec4> from_bytes = only_colors(load_colors_both_ways(
        test::write_fixture("vc-u8", "m.gltf", color_gltf(bytes_of(bytes), "VEC4", 5121))));
    ASSERT_EQ(from_bytes.size(), 3u);
    EXPECT_NEAR(from_bytes[0].w, 64 / 255.0, 1e-6);
    EXPECT_NEAR(from_bytes[1].w, 128 / 255.0, 1e-6);
    EXPECT_EQ(from_bytes[0].x, 1.0f);
    const std::array<std::uint16_t, 12> shorts = {65535, 0, 0, 16384, 0,     65535,
                                                  0,     0, 0, 0,     65535, 65535};
    const std::vector<glm::vec4> from_shorts = only_colors(load_colors_both_ways(
        test::write_fixture("vc-u16", "m.gltf", color_gltf(bytes_of(shorts), "VEC4", 5123))));
    ASSERT_EQ(from_shorts.size(), 3u);
    EXPECT_NEAR(from_shorts[0].w, 16384 / 65535.0, 1e-6);
    EXPECT_EQ(from_shorts[1].w, 0.0f);
}

TEST(VertexColorsLoad, ComponentsOutsideTheUnitRangeAreClampedWithAWarning) {
    const std::array<float, 12> c = {1.5f, -0.5f, 0, 2, 0, 1, 0, -1, 0, 0, 1, 1};
    std::vector<std::string> warnings;
    const auto path =
        test::write_fixture("vc-clamp", "m.gltf", color_gltf(bytes_of(c), "VEC4", 5126));
    const std::vector<glm::vec4> colors = only_colors(load_colors_both_ways(path, &warnings));
    ASSERT_EQ(colors.size(), 3u);
    EXPECT_EQ(colors[0], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(colors[1], glm::vec4(0, 1, 0, 0));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("vertex colors outside [0, 1] clamped"), std::string::npos)
        << warnings[0];
    EXPECT_EQ(warnings[0].rfind(path.string(), 0), 0u) << warnings[0];
}

TEST(VertexColorsLoad, PlyRgbaBytes) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
        "property uchar alpha\nelement face 2\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0 255 0 0 51\n1 0 0 0 255 0 102\n1 1 0 0 0 255 255\n"
        "0 1 0 255 255 255 0\n3 0 1 2\n3 0 2 3\n";
    const Scene scene = load_colors_both_ways(test::write_fixture("vc-ply", "m.ply", ply));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.colors.size(), mesh.positions.size());
    // Whatever order the loader keeps the vertices in, each position keeps its color.
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        const float alpha = p == glm::vec3(0, 0, 0)   ? 51 / 255.0f
                            : p == glm::vec3(1, 0, 0) ? 102 / 255.0f
                            : p == glm::vec3(1, 1, 0) ? 1.0f
                                                      : 0.0f;
        EXPECT_NEAR(mesh.colors[v].w, alpha, 1e-6) << "vertex " << v;
    }
    // PLY has no material alpha mode: Blend by default, so vertex alpha makes it transparent.
    EXPECT_EQ(scene.materials.at(mesh.material).alpha_mode, AlphaMode::Blend);
}

TEST(VertexColorsLoad, FilesWithoutColorsHaveNone) {
    const std::string ply =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
        "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    const Scene scene = load_colors_both_ways(test::write_fixture("vc-none", "m.ply", ply));
    EXPECT_TRUE(only_colors(scene).empty());
}

// OBJ's `v x y z r g b` colors are not read, by zraster's reader nor by Assimp for the files
// the reader leaves to it (a pentagon here): both load the same mesh.
TEST(VertexColorsLoad, ObjColorsAreNotRead) {
    const std::string vertices =
        "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0.5 1.5 0 1 1 0\nv 0 1 0 1 0 1\n";
    for (const char* faces : {"f 1 2 3\nf 1 3 5\n", "f 1 2 3 4 5\n"}) {
        SCOPED_TRACE(faces);
        const Scene scene = load_colors_both_ways(
            test::write_fixture("vc-obj", "m.obj", vertices + std::string(faces)));
        ASSERT_EQ(scene.meshes.size(), 1u);
        EXPECT_TRUE(scene.meshes[0].colors.empty());
    }
}

TEST(VertexColorsLoad, InfoReportsColorsAndVertexAlpha) {
    const std::array<float, 12> c = {1, 0, 0, 0.25f, 0, 1, 0, 0.5f, 0, 0, 1, 1};
    const auto path =
        test::write_fixture("vc-info", "m.gltf", color_gltf(bytes_of(c), "VEC4", 5126));
    std::vector<std::string> warnings;
    const Scene scene = load_scene(path, {}, &warnings);
    const std::string text = describe_scene(scene, warnings);
    EXPECT_NE(text.find("vertex colors (alpha 0.25 to 1)"), std::string::npos) << text;
    EXPECT_NE(text.find("alpha below 1 from vertex alpha"), std::string::npos) << text;
}

}  // namespace
}  // namespace zraster
