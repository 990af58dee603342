// What load_scene builds: node transforms as instances, computed normals, welded OBJ vertices,
// the uv convention, and what it keeps (degenerate triangles) or drops (points, lines).
#include <zraster/load.hpp>
#include <zraster/render.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <cstring>
#include <map>

namespace zraster {
namespace {

std::filesystem::path write_fixture(const std::filesystem::path& dir, const std::string& name,
                                    std::string_view content) {
    test::write_bytes(dir / name, content);
    return dir / name;
}

glm::vec3 world(const Scene& scene, const Instance& instance, std::uint32_t vertex) {
    const glm::vec4 p =
        instance.transform * glm::vec4(scene.meshes[instance.mesh].positions[vertex], 1.0f);
    return glm::vec3(p) / p.w;
}

void expect_vec3_near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

// One triangle (0,0,0) (1,0,0) (0,1,0) in an external buffer, placed by `nodes`.
std::filesystem::path write_gltf(const std::filesystem::path& dir, const std::string& nodes,
                                 const std::string& scene_nodes) {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::uint16_t indices[4] = {0, 1, 2, 0};  // padded to 4 bytes
    std::string bin(sizeof positions + sizeof indices, '\0');
    std::memcpy(bin.data(), positions, sizeof positions);
    std::memcpy(bin.data() + sizeof positions, indices, sizeof indices);
    test::write_bytes(dir / "tri.bin", bin);
    const std::string json = R"({"asset": {"version": "2.0"},
  "buffers": [{"uri": "tri.bin", "byteLength": 44}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "nodes": )" + nodes + R"(,
  "scenes": [{"nodes": )" + scene_nodes +
                             R"(}], "scene": 0})";
    return write_fixture(dir, "scene.gltf", json);
}

TEST(LoadStructure, NodeTransformsAccumulateParentFirst) {
    const auto dir = test::temp_dir("io-structure-nodes");
    const auto path = write_gltf(dir, R"([
        {"name": "parent", "translation": [10, 0, 0], "children": [1]},
        {"name": "child", "scale": [2, 2, 2], "mesh": 0},
        {"name": "lifted", "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,5,0,1], "mesh": 0},
        {"name": "turned", "translation": [0, 0, 3], "rotation": [0, 0, 0.70710678, 0.70710678],
         "mesh": 0}])",
                                 "[0, 2, 3]");
    const Scene scene = load_scene(path);
    ASSERT_EQ(scene.meshes.size(), 1u);  // one mesh, placed three times
    ASSERT_EQ(scene.instances.size(), 3u);
    EXPECT_EQ(scene.triangle_count(), 3u);
    std::map<std::string, const Instance*> by_name;
    for (const Instance& i : scene.instances) {
        EXPECT_EQ(i.mesh, 0u);
        by_name[i.name] = &i;
    }
    ASSERT_TRUE(by_name.contains("child") && by_name.contains("lifted") &&
                by_name.contains("turned"));
    // parent * child: scaled by 2, then moved by 10 (not moved by 10, then scaled by 2).
    expect_vec3_near(world(scene, *by_name["child"], 1), {12, 0, 0});
    expect_vec3_near(world(scene, *by_name["child"], 2), {10, 2, 0});
    // glTF matrices are column-major like glm: the translation is the last column.
    expect_vec3_near(world(scene, *by_name["lifted"], 1), {1, 5, 0});
    EXPECT_EQ(by_name["lifted"]->transform[3], glm::vec4(0, 5, 0, 1));
    // T * R: a quarter turn about z, then the translation.
    expect_vec3_near(world(scene, *by_name["turned"], 1), {0, 1, 3});
    // Mesh bounds stay in mesh space.
    EXPECT_EQ(scene.meshes[0].bounds.lo, glm::vec3(0, 0, 0));
    EXPECT_EQ(scene.meshes[0].bounds.hi, glm::vec3(1, 1, 0));
}

// glTF: "the determinant of the node's global transform defines the winding order". A mirrored
// placement draws a copy of the mesh turned the other way (one copy, shared by every mirrored
// placement), so its outside faces out: the renderer, like OpenGL, culls by screen winding.
TEST(LoadStructure, MirroredPlacementsKeepTheMeshsOutsideFacingOut) {
    const auto dir = test::temp_dir("io-structure-mirrored");
    const auto path = write_gltf(dir, R"([
        {"name": "plain", "mesh": 0},
        {"name": "mirrored", "translation": [3, 0, 0], "scale": [-1, 1, 1], "mesh": 0},
        {"name": "mirrored twice", "scale": [-1, -1, 1], "translation": [0, 3, 0], "mesh": 0},
        {"name": "parent", "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1],
         "children": [4]},
        {"name": "child of a mirror", "translation": [6, 0, 0], "mesh": 0}])",
                                 "[0, 1, 2, 3]");
    const Scene scene = load_scene(path);
    ASSERT_EQ(scene.meshes.size(), 2u);
    EXPECT_EQ(scene.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(scene.meshes[1].indices, (std::vector<std::uint32_t>{0, 2, 1}));
    EXPECT_EQ(scene.meshes[1].name, "tri (mirrored)");
    EXPECT_EQ(scene.meshes[1].positions, scene.meshes[0].positions);
    std::map<std::string, std::uint32_t> mesh_of;
    for (const Instance& i : scene.instances) mesh_of[i.name] = i.mesh;
    EXPECT_EQ(mesh_of["plain"], 0u);
    EXPECT_EQ(mesh_of["mirrored"], 1u);
    EXPECT_EQ(mesh_of["mirrored twice"], 0u);  // a half turn, not a mirror
    EXPECT_EQ(mesh_of["child of a mirror"], 1u);

    // Drawn with back faces culled, each seen from 3 units in front of its middle on +z (the
    // side the triangle faces): a mirrored placement shows as many pixels as the plain one,
    // give or take the pixels its mirrored edges round to (it was culled whole before).
    RenderOptions options;
    options.width = 256;
    options.height = 256;
    options.cull = CullMode::Back;
    options.id_targets = true;
    const auto covered = [&](const char* name) {
        Scene one = scene;
        std::erase_if(one.instances, [&](const Instance& i) { return i.name != name; });
        const Bounds3f box = one.bounds();
        const glm::vec3 middle = 0.5f * (box.lo + box.hi);
        Camera camera;
        camera.eye = glm::dvec3(middle) + glm::dvec3(0, 0, 3);
        camera.target = glm::dvec3(middle);
        camera.near = 0.5;
        camera.far = 10;
        options.camera = camera;
        const RenderResult result = render(one, options);
        std::size_t n = 0;
        for (const std::int32_t id : result.targets.instance_id) n += id >= 0;
        return n;
    };
    const std::size_t plain = covered("plain");
    EXPECT_GT(plain, 2000u);
    EXPECT_NEAR(double(covered("mirrored")), double(plain), 0.1 * double(plain));
    EXPECT_NEAR(double(covered("mirrored twice")), double(plain), 0.1 * double(plain));
    // The z mirror turns the triangle to face -z: seen from +z it is its back, culled.
    EXPECT_EQ(covered("child of a mirror"), 0u);
}

// Assimp gives an AMF file without colors vertex colors of (0, 0, 0, 0): multiplied in, they
// hid every mesh. Read as no colors, with a warning.
TEST(LoadStructure, VertexColorsAllZeroAreReadAsNone) {
    const auto dir = test::temp_dir("io-structure-zero-colors");
    const auto path = dir / "t.amf";
    test::write_bytes(path,
                      R"(<?xml version="1.0" encoding="UTF-8"?><amf unit="millimeter">)"
                      R"(<object id="0"><mesh><vertices>)"
                      R"(<vertex><coordinates><x>0</x><y>0</y><z>0</z></coordinates></vertex>)"
                      R"(<vertex><coordinates><x>1</x><y>0</y><z>0</z></coordinates></vertex>)"
                      R"(<vertex><coordinates><x>0</x><y>1</y><z>0</z></coordinates></vertex>)"
                      R"(</vertices><volume><triangle><v1>0</v1><v2>1</v2><v3>2</v3>)"
                      R"(</triangle></volume></mesh></object></amf>)");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(path, LoadOptions{}, &warnings);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_TRUE(scene.meshes[0].colors.empty());
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("vertex colors all (0, 0, 0, 0), as the importer reads a file "
                               "without colors: ignored"),
              std::string::npos)
        << warnings[0];
}

TEST(LoadStructure, TransformThatOverflowsIsNonFinite) {
    const auto dir = test::temp_dir("io-structure-overflow");
    const auto path = write_gltf(dir, R"([
        {"name": "huge", "scale": [3e38, 3e38, 3e38], "children": [1]},
        {"name": "more", "scale": [10, 10, 10], "mesh": 0}])",
                                 "[0]");
    test::expect_input_error([&] { load_scene(path); }, path,
                             "non-finite vertex coordinates (mesh tri, vertex ");
}

TEST(LoadStructure, BoxTexturedNodeMatrixAndUvConvention) {
    ZRASTER_REQUIRE_SHARED_DATA();
    for (const char* file :
         {"meshes/gltf/BoxTextured.glb", "meshes/gltf/BoxTextured/BoxTextured.gltf"}) {
        SCOPED_TRACE(file);
        const Scene scene = load_scene(test::shared_data(file));
        ASSERT_EQ(scene.instances.size(), 1u);
        // The file's root node matrix (column-major) [1,0,0,0, 0,0,-1,0, 0,1,0,0, 0,0,0,1].
        const glm::mat4& m = scene.instances[0].transform;
        EXPECT_EQ(m[0], glm::vec4(1, 0, 0, 0));
        EXPECT_EQ(m[1], glm::vec4(0, 0, -1, 0));
        EXPECT_EQ(m[2], glm::vec4(0, 1, 0, 0));
        EXPECT_EQ(m[3], glm::vec4(0, 0, 0, 1));
        // The first vertices of the file: position (-0.5, -0.5, 0.5), normal +z, TEXCOORD_0
        // (6, 0); position (-0.5, 0.5, 0.5), TEXCOORD_0 (6, 0.99999988). glTF's uv origin is
        // the image's first row, zraster's too, so they come out as stored in the file.
        const Mesh& mesh = scene.meshes[0];
        ASSERT_EQ(mesh.uvs.size(), 24u);
        int checked = 0;
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            if (mesh.normals[v] != glm::vec3(0, 0, 1) || mesh.positions[v].x != -0.5f) continue;
            if (mesh.positions[v].y == -0.5f) {
                EXPECT_EQ(mesh.uvs[v], glm::vec2(6.0f, 0.0f));
                ++checked;
            } else if (mesh.positions[v].y == 0.5f) {
                EXPECT_NEAR(mesh.uvs[v].x, 6.0f, 1e-6f);
                EXPECT_NEAR(mesh.uvs[v].y, 0.99999988f, 1e-6f);
                ++checked;
            }
        }
        EXPECT_EQ(checked, 2);
    }
}

TEST(LoadStructure, ObjUvsAreFlippedToTheFirstRowOrigin) {
    const auto dir = test::temp_dir("io-structure-uv");
    const auto path = write_fixture(dir, "uv.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                    "vt 0.25 0.1\nvt 0.5 0.0\nvt 1.0 1.0\nf 1/1 2/2 3/3\n");
    const Scene scene = load_scene(path);
    const Mesh& mesh = scene.meshes.at(0);
    ASSERT_EQ(mesh.uvs.size(), 3u);
    // OBJ's v points up from the image's last row.
    EXPECT_NEAR(mesh.uvs[0].x, 0.25f, 1e-6f);
    EXPECT_NEAR(mesh.uvs[0].y, 0.9f, 1e-6f);
    EXPECT_EQ(mesh.uvs[1], glm::vec2(0.5f, 1.0f));
    EXPECT_EQ(mesh.uvs[2], glm::vec2(1.0f, 0.0f));
}

const char* kCubeVertices =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n";

TEST(LoadStructure, ComputedNormalsOfAQuadCubeAreItsDiagonals) {
    const auto dir = test::temp_dir("io-structure-cube");
    const auto path =
        write_fixture(dir, "cube.obj",
                      std::string(kCubeVertices) +
                          "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    const Scene scene = load_scene(path);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    EXPECT_EQ(mesh.triangle_count(), 12u);
    // Assimp splits OBJ faces into per-corner vertices; welding gives the file's 8 back.
    EXPECT_EQ(mesh.vertex_count(), 8u);
    // Angle weighting: each face meets a corner at 90 degrees in total however it is split,
    // so every corner normal is exactly the outward diagonal.
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
        expect_vec3_near(mesh.normals[v], glm::normalize(mesh.positions[v]));
}

TEST(LoadStructure, UvSeamsDoNotSplitComputedNormals) {
    const auto dir = test::temp_dir("io-structure-seams");
    // Each face has its own four uvs: 24 distinct corners at 8 positions.
    std::string obj = kCubeVertices;
    const int faces[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5},
                             {2, 3, 7, 6}, {3, 4, 8, 7}, {4, 1, 5, 8}};
    for (int f = 0; f < 6; ++f)
        for (int k = 0; k < 4; ++k)
            obj += "vt " + std::to_string(f) + " " + std::to_string(k) + "\n";
    for (int f = 0; f < 6; ++f) {
        obj += "f";
        for (int k = 0; k < 4; ++k)
            obj += " " + std::to_string(faces[f][k]) + "/" + std::to_string(4 * f + k + 1);
        obj += "\n";
    }
    const Scene scene = load_scene(write_fixture(dir, "cube.obj", obj));
    const Mesh& mesh = scene.meshes.at(0);
    EXPECT_EQ(mesh.vertex_count(), 24u);
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
        expect_vec3_near(mesh.normals[v], glm::normalize(mesh.positions[v]));
}

TEST(LoadStructure, FileNormalsAreKeptAndNormalised) {
    const auto dir = test::temp_dir("io-structure-normals");
    const auto path = write_fixture(dir, "n.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 3 4 0\n"
                                    "f 1//1 2//1 3//2\n");
    const Scene scene = load_scene(path);
    const Mesh& mesh = scene.meshes.at(0);
    ASSERT_EQ(mesh.normals.size(), 3u);
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(mesh.normals[1], glm::vec3(0, 0, 1));
    expect_vec3_near(mesh.normals[2], {0.6f, 0.8f, 0.0f});
}

TEST(LoadStructure, ZeroFileNormalsAreReplacedByComputedOnes) {
    const auto dir = test::temp_dir("io-structure-zero-normals");
    const auto path = write_fixture(dir, "z.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nvn 0 0 -1\n"
                                    "f 1//1 2//2 3//2\n");
    const Scene scene = load_scene(path);
    const Mesh& mesh = scene.meshes.at(0);
    ASSERT_EQ(mesh.normals.size(), 3u);
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));   // computed: the triangle faces +z
    EXPECT_EQ(mesh.normals[1], glm::vec3(0, 0, -1));  // the file's, even if odd
}

TEST(LoadStructure, DegenerateTrianglesAreKept) {
    const auto dir = test::temp_dir("io-structure-degenerate");
    const auto path = write_fixture(dir, "d.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\n"
                                    "f 1 2 3\nf 1 2 4\nf 1 1 2\n");  // collinear, repeated
    const Scene scene = load_scene(path);
    EXPECT_EQ(scene.triangle_count(), 3u);
    for (const glm::vec3& n : scene.meshes.at(0).normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

TEST(LoadStructure, PointsAndLinesBesideTrianglesAreDropped) {
    const auto dir = test::temp_dir("io-structure-lines");
    const auto path = write_fixture(dir, "mixed.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 100 100 100\n"
                                    "f 1 2 3\nl 3 4\np 4\n");
    const Scene scene = load_scene(path);
    EXPECT_EQ(scene.triangle_count(), 1u);
    const Bounds3f b = scene.bounds();
    EXPECT_EQ(b.lo, glm::vec3(0, 0, 0));
    EXPECT_EQ(b.hi, glm::vec3(1, 1, 0));  // the line's far end is not part of the scene
}

TEST(LoadStructure, MultipleObjectsBecomeMeshesWithIdentityInstances) {
    const auto dir = test::temp_dir("io-structure-objects");
    const auto path = write_fixture(dir, "two.obj",
                                    "o first\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                                    "o second\nv 0 0 5\nv 1 0 5\nv 0 1 5\nf 4 5 6\n");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(path, {}, &warnings);
    ASSERT_EQ(scene.meshes.size(), 2u);
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.meshes[0].name, "first");
    EXPECT_EQ(scene.meshes[1].name, "second");
    EXPECT_EQ(scene.meshes[1].bounds.lo.z, 5.0f);
    for (const Instance& i : scene.instances) EXPECT_EQ(i.transform, glm::mat4(1.0f));
    EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace zraster
