// glTF's KHR_texture_transform (issue 27, hostile run 6's M9 and M12): malformed members are
// refused before the importer reads them (a "scale" of one number aborted it), and the base
// color texture's transform is applied to the mesh's texture coordinates as the extension's
// reference computes it (it was ignored, even when required).
#include <zraster/load.hpp>

#include <cmath>
#include <string>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

// A triangle with texture coordinates (0,0), (1,0), (0,1) and a textured material whose base
// color texture has `transform` (a JSON object, or empty for none).
std::string transformed_gltf(const std::string& transform) {
    // Positions (0,0,0), (1,0,0), (0,1,0), then the coordinates: 60 bytes.
    const float data[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};
    const std::string bytes(reinterpret_cast<const char*>(data), sizeof data);
    const std::string extension =
        transform.empty() ? "" : R"(,"extensions":{"KHR_texture_transform":)" + transform + "}";
    return R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_texture_transform"],"scene":0,)"
           R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{)"
           R"("attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],)"
           R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0)" +
           extension +
           R"(}}}],"textures":[{"source":0}],"images":[{"uri":"t.png"}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":0,"byteOffset":36,"componentType":5126,)"
           R"("count":3,"type":"VEC2"}],"bufferViews":[{"buffer":0,"byteLength":60}],)"
           R"("buffers":[{"uri":"data:application/octet-stream;base64,)" +
           test::base64(bytes) + R"(","byteLength":60}]})";
}

TEST(GltfTextureTransform, TheBaseColorTransformMovesTheTextureCoordinates) {
    const auto dir = test::temp_dir("gltf-texture-transform");
    // (t.png is missing: a warning; the coordinates are what is checked.)
    struct Case {
        const char* transform;
        glm::vec2 corner[3];  // the coordinates of (0,0), (1,0), (0,1) after it
    };
    const Case cases[] = {
        {"", {{0, 0}, {1, 0}, {0, 1}}},
        {R"({"offset":[0.5,0.25]})", {{0.5f, 0.25f}, {1.5f, 0.25f}, {0.5f, 1.25f}}},
        {R"({"scale":[2,3]})", {{0, 0}, {2, 0}, {0, 3}}},
        // The reference's rotation: (u, v) -> (cos u - sin v, sin u + cos v).
        {R"({"rotation":1.5707963267948966})", {{0, 0}, {0, 1}, {-1, 0}}},
        {R"({"offset":[1,0],"rotation":1.5707963267948966,"scale":[2,2]})",
         {{1, 0}, {1, 2}, {-1, 0}}},
    };
    int k = 0;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.transform);
        const auto path = dir / ("m" + std::to_string(k++) + ".gltf");
        test::write_bytes(path, transformed_gltf(c.transform));
        for (const LoadIsolation isolation : test::kBothIsolations) {
            LoadOptions o;
            o.isolation = isolation;
            std::vector<std::string> warnings;
            const Scene scene = load_scene(path, o, &warnings);
            const Mesh& mesh = scene.meshes.at(0);
            ASSERT_EQ(mesh.uvs.size(), 3u);
            for (int i = 0; i < 3; ++i) {
                // Each corner is where its position says (the importer may reorder vertices).
                const glm::vec3 p = mesh.positions[i];
                const int corner = p.x > 0.5f ? 1 : p.y > 0.5f ? 2 : 0;
                EXPECT_NEAR(mesh.uvs[i].x, c.corner[corner].x, 1e-6) << i;
                EXPECT_NEAR(mesh.uvs[i].y, c.corner[corner].y, 1e-6) << i;
            }
        }
    }
}

TEST(GltfTextureTransform, MalformedMembersAreRefusedBeforeTheImport) {
    const auto dir = test::temp_dir("gltf-texture-transform-bad");
    const std::string where =
        "malformed glTF file: /materials/0/pbrMetallicRoughness/"
        "baseColorTexture/extensions/KHR_texture_transform ";
    const std::pair<const char*, std::string> cases[] = {
        {R"({"scale":[1]})", where + "'scale' is not 2 numbers"},
        {R"({"offset":[null,null]})", where + "'offset' is not 2 numbers"},
        {R"({"scale":["a","b"]})", where + "'scale' is not 2 numbers"},
        {R"({"rotation":"x"})", where + "'rotation' is not a number"},
        {R"({"texCoord":-1})", where + "'texCoord' is not a whole number of 0 or more"},
        {"[]",
         "malformed glTF file: /materials/0/pbrMetallicRoughness/baseColorTexture/"
         "extensions/KHR_texture_transform is not an object"},
    };
    int k = 0;
    for (const auto& [transform, cause] : cases) {
        SCOPED_TRACE(transform);
        const auto path = dir / ("m" + std::to_string(k++) + ".gltf");
        test::write_bytes(path, transformed_gltf(transform));
        test::expect_refused_both_ways(path, cause);
    }
}

}  // namespace
}  // namespace zraster
