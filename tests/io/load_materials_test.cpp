// Materials and base-color textures: MTL values, embedded and external textures, Windows paths,
// sharing, and the warnings (not errors) for missing libraries and images.
#include <zraster/image_io.hpp>
#include <zraster/load.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <cmath>
#include <map>
#include <set>

namespace zraster {
namespace {

const char* kQuadObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

// A 4 x 2 RGB image whose texels are all different.
void write_texture(const std::filesystem::path& path) {
    std::vector<std::uint8_t> rgb(4 * 2 * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>(i * 10);
    write_png8(path, 4, 2, 3, rgb);
}

const Material& material_of(const Scene& scene, const std::string& mesh_name) {
    for (const Mesh& m : scene.meshes)
        if (m.name == mesh_name) return scene.materials.at(m.material);
    ADD_FAILURE() << "no mesh " << mesh_name;
    return scene.materials.at(0);
}

TEST(LoadMaterials, MtlValuesAndASharedTexture) {
    const auto dir = test::temp_dir("io-materials-mtl");
    std::filesystem::create_directory(dir / "maps");
    write_texture(dir / "maps" / "bricks.png");
    test::write_bytes(dir / "scene.mtl",
                      "newmtl red\nKd 0.9 0.1 0.2\nKs 0.5 0.5 0.5\nNs 5000\nd 0.5\n"
                      "map_Kd maps\\bricks.png\n"  // a Windows path, relative to the model
                      "newmtl blue\nKd 0.1 0.2 0.9\nNs 0.25\nmap_Kd ./maps/bricks.png\n");
    test::write_bytes(dir / "scene.obj", std::string("mtllib scene.mtl\n") + kQuadObj +
                                             "o a\nusemtl red\nf 1/1 2/2 3/3\n"
                                             "o b\nusemtl blue\nf 1/1 3/3 4/4\n");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(dir / "scene.obj", {}, &warnings);
    // Ns past 1024 is used as 1024, below 1 as 1, and said so (docs/limits.md).
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0], (dir / "scene.obj").string() +
                               ": material 'red': shininess 5000 is past 1024, using 1024");
    EXPECT_EQ(warnings[1], (dir / "scene.obj").string() +
                               ": material 'blue': shininess 0.25 is below 1, using 1");
    ASSERT_EQ(scene.materials.size(), 3u);  // the default, red, blue
    const Material& red = material_of(scene, "a");
    const Material& blue = material_of(scene, "b");
    EXPECT_EQ(red.name, "red");
    EXPECT_EQ(red.base_color, glm::vec3(0.9f, 0.1f, 0.2f));
    EXPECT_EQ(red.specular, glm::vec3(0.5f));
    EXPECT_EQ(red.shininess, 1024.0f);  // clamped
    EXPECT_EQ(red.opacity, 0.5f);
    EXPECT_EQ(blue.shininess, 1.0f);  // clamped
    EXPECT_EQ(blue.opacity, 1.0f);
    ASSERT_TRUE(red.base_color_texture);
    EXPECT_EQ(red.base_color_texture, blue.base_color_texture);  // one image, decoded once
    EXPECT_EQ(red.base_color_texture->width(), 4);
    EXPECT_EQ(red.base_color_texture->height(), 2);
    // Texel (1, 0) is bytes 3..5 of the first row: 30, 40, 50.
    const glm::vec4 texel = red.base_color_texture->texel(0, 1, 0);
    EXPECT_NEAR(texel.x, 30 / 255.0f, 1e-6f);
    EXPECT_NEAR(texel.y, 40 / 255.0f, 1e-6f);
    EXPECT_NEAR(texel.z, 50 / 255.0f, 1e-6f);
    EXPECT_EQ(texel.w, 1.0f);
}

// MTL values outside their ranges (docs/limits.md): each replaced, with one warning naming the
// material, the value read and the value used; NaN never reaches shading.
TEST(LoadMaterials, MtlValuesOutsideTheirRangesAreReplacedWithAWarningEach) {
    const auto dir = test::temp_dir("io-materials-ranges");
    struct Case {
        const char* statements;
        const char* warning;
    };
    const Case cases[] = {
        {"Kd 2 -1 0.5", "base color (2, -1, 0.5) is outside 0..1, using (1, 0, 0.5)"},
        {"Kd nan 0 0", "base color (nan, 0, 0) is not finite, using the default (0.8, 0.75, 0.7)"},
        {"Ks -1 0.5 0.5", "specular color (-1, 0.5, 0.5) is negative, using (0, 0.5, 0.5)"},
        {"Ks 0 nan 0", "specular color (0, nan, 0) is not finite, using (0.25, 0.25, 0.25)"},
        {"Ns -5", "shininess -5 is not in 1..1024, using the default 32"},
        {"Ns nan", "shininess nan is not in 1..1024, using the default 32"},
        {"Ns 0.5", "shininess 0.5 is below 1, using 1"},
        {"d nan", "opacity nan is outside 0..1, using 1"},
        {"d -1", "opacity -1 is outside 0..1, using 0"},
        {"d 5\nTr 0.5", "opacity (d) 5 is outside 0..1, using 1"},
    };
    std::string mtl, obj = "mtllib ranges.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (std::size_t i = 0; i < std::size(cases); ++i) {
        mtl += "newmtl m" + std::to_string(i) + "\n" + cases[i].statements + "\n";
        obj += "o o" + std::to_string(i) + "\nusemtl m" + std::to_string(i) + "\nf 1 2 3\n";
    }
    test::write_bytes(dir / "ranges.mtl", mtl);
    test::write_bytes(dir / "ranges.obj", obj);
    for (const LoadIsolation isolation : {LoadIsolation::InProcess, LoadIsolation::WorkerProcess}) {
        LoadOptions options;
        options.isolation = isolation;
        std::vector<std::string> warnings;
        const Scene scene = load_scene(dir / "ranges.obj", options, &warnings);
        ASSERT_EQ(warnings.size(), std::size(cases));
        for (std::size_t i = 0; i < std::size(cases); ++i)
            EXPECT_EQ(warnings[i], (dir / "ranges.obj").string() + ": material 'm" +
                                       std::to_string(i) + "': " + cases[i].warning);
        for (const Material& m : scene.materials) {
            SCOPED_TRACE(m.name);
            for (const float v : {m.base_color.x, m.base_color.y, m.base_color.z, m.specular.x,
                                  m.specular.y, m.specular.z, m.shininess, m.opacity}) {
                EXPECT_TRUE(std::isfinite(v));
            }
            EXPECT_TRUE(m.opacity >= 0.0f && m.opacity <= 1.0f);
            EXPECT_TRUE(m.shininess >= 1.0f && m.shininess <= 1024.0f);
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(m.base_color, glm::vec3(0.0f))) &&
                        glm::all(glm::lessThanEqual(m.base_color, glm::vec3(1.0f))));
        }
        EXPECT_EQ(material_of(scene, "o0").base_color, glm::vec3(1.0f, 0.0f, 0.5f));
        EXPECT_EQ(material_of(scene, "o6").shininess, 1.0f);
        EXPECT_EQ(material_of(scene, "o8").opacity, 0.0f);
    }
}

TEST(LoadMaterials, MissingTextureIsAWarning) {
    const auto dir = test::temp_dir("io-materials-missing-texture");
    test::write_bytes(dir / "m.mtl", "newmtl skin\nKd 0.3 0.6 0.9\nmap_Kd nothere.png\n");
    test::write_bytes(dir / "m.obj",
                      std::string("mtllib m.mtl\n") + kQuadObj + "usemtl skin\nf 1/1 2/2 3/3\n");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(dir / "m.obj", {}, &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], (dir / "m.obj").string() +
                               ": texture 'nothere.png' not found, using the material color");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[1].base_color, glm::vec3(0.3f, 0.6f, 0.9f));
    EXPECT_FALSE(scene.materials[1].base_color_texture);
}

TEST(LoadMaterials, UnreadableTextureIsAWarning) {
    const auto dir = test::temp_dir("io-materials-bad-texture");
    test::write_bytes(dir / "broken.png", "not a png");
    test::write_bytes(dir / "m.mtl", "newmtl skin\nmap_Kd broken.png\n");
    test::write_bytes(dir / "m.obj",
                      std::string("mtllib m.mtl\n") + kQuadObj + "usemtl skin\nf 1/1 2/2 3/3\n");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(dir / "m.obj", {}, &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("texture 'broken.png' cannot be read (cannot decode image"),
              std::string::npos)
        << warnings[0];
    EXPECT_FALSE(scene.materials.at(1).base_color_texture);
}

TEST(LoadMaterials, MissingMaterialLibraryIsAWarningAndTheDefaultMaterial) {
    const auto dir = test::temp_dir("io-materials-missing-mtl");
    test::write_bytes(dir / "m.obj",
                      std::string("mtllib gone.mtl\n") + kQuadObj + "usemtl skin\nf 1/1 2/2 3/3\n");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(dir / "m.obj", {}, &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], (dir / "m.obj").string() +
                               ": material library 'gone.mtl' not found, using the default "
                               "material");
    EXPECT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.meshes.at(0).material, 0u);
    EXPECT_EQ(scene.materials[0].base_color, Material{}.base_color);
}

// A library named thousands of times, under two names, is read as if named once: the same
// materials and warnings (its names were copied, and Assimp re-read it, for every repetition: a
// 6 MB library named 3,000 times ran out of memory).
TEST(LoadMaterials, ALibraryNamedManyTimesIsReadOnce) {
    const auto dir = test::temp_dir("io-materials-repeated-mtl");
    test::write_bytes(dir / "m.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
    std::string repeated;
    for (int i = 0; i < 3000; ++i) repeated += i % 2 == 0 ? "mtllib m.mtl\n" : "mtllib ./m.mtl\n";
    const std::string body =
        std::string(kQuadObj) + "o a\nusemtl blue\nf 1/1 2/2 3/3\no b\nusemtl red\nf 1/1 3/3 4/4\n";
    test::write_bytes(dir / "many.obj", repeated + body);
    test::write_bytes(dir / "once.obj", "mtllib m.mtl\n" + body);
    for (const bool pentagon : {false, true}) {  // (pentagons: the files left to Assimp)
        SCOPED_TRACE(pentagon);
        const std::string extra = pentagon ? "v 2 2 0\nf 1 2 5 3 4\n" : "";
        test::write_bytes(dir / "many.obj", repeated + body + extra);
        test::write_bytes(dir / "once.obj", "mtllib m.mtl\n" + body + extra);
        std::vector<std::string> many_warnings, once_warnings;
        const Scene many = load_scene(dir / "many.obj", {}, &many_warnings);
        const Scene once = load_scene(dir / "once.obj", {}, &once_warnings);
        ASSERT_EQ(many.materials.size(), once.materials.size());
        EXPECT_EQ(material_of(many, "a").base_color, glm::vec3(0, 0, 1));
        EXPECT_EQ(material_of(many, "b").base_color, glm::vec3(1, 0, 0));
        EXPECT_EQ(many_warnings.size(), once_warnings.size());
    }
}

TEST(LoadMaterials, UndefinedMaterialNameIsAWarning) {
    const auto dir = test::temp_dir("io-materials-undefined");
    test::write_bytes(dir / "m.mtl", "newmtl known\nKd 1 0 0\n");
    test::write_bytes(dir / "m.obj",
                      std::string("mtllib m.mtl\n") + kQuadObj +
                          "o a\nusemtl ghost\nf 1 2 3\no b\nusemtl known\nf 1 3 4\n");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(dir / "m.obj", {}, &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("material 'ghost' is not defined, using the default material"),
              std::string::npos);
    EXPECT_EQ(material_of(scene, "a").name, Material{}.name);
    EXPECT_EQ(material_of(scene, "b").base_color, glm::vec3(1, 0, 0));
}

TEST(LoadMaterials, SpiderFindsItsWindowsPathTextures) {
    ZRASTER_REQUIRE_SHARED_DATA();
    std::vector<std::string> warnings;
    const auto spider = test::shared_data("meshes/obj/spider/spider.obj");
    const Scene scene = load_scene(spider, {}, &warnings);
    // Its one warning: a `vn 0 0 0`, replaced by a computed normal (no texture is missed).
    EXPECT_EQ(warnings, std::vector<std::string>{spider.string() +
                                                 ": normals that are missing, not finite or of "
                                                 "zero length (first in mesh Zahn) recomputed "
                                                 "from the faces"});
    // spider.mtl defines five materials (map_Kd .\X.jpg); its meshes use four of them
    // (Brusttex is unused, so it is not loaded). Sizes are those of the JPEG files.
    const std::map<std::string, std::pair<int, int>> expected = {{"HLeibTex", {249, 250}},
                                                                 {"Skin", {250, 250}},
                                                                 {"BeinTex", {768, 768}},
                                                                 {"Augentex", {128, 128}}};
    ASSERT_EQ(scene.materials.size(), 1 + expected.size());
    for (std::size_t i = 1; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        SCOPED_TRACE(m.name);
        ASSERT_TRUE(expected.contains(m.name));
        ASSERT_TRUE(m.base_color_texture);
        EXPECT_EQ(m.base_color_texture->width(), expected.at(m.name).first);
        EXPECT_EQ(m.base_color_texture->height(), expected.at(m.name).second);
    }
    EXPECT_EQ(material_of(scene, "HLeib01").name, "HLeibTex");
    EXPECT_EQ(material_of(scene, "HLeib01").base_color, glm::vec3(0.690196f, 0.639216f, 0.615686f));
    for (const Mesh& m : scene.meshes) EXPECT_EQ(m.uvs.size(), m.positions.size()) << m.name;
}

TEST(LoadMaterials, SpotHasUvsButNoMaterialLibrary) {
    ZRASTER_REQUIRE_SHARED_DATA();
    std::vector<std::string> warnings;
    const Scene scene =
        load_scene(test::shared_data("meshes/obj/spot/spot_triangulated.obj"), {}, &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(scene.materials.size(), 1u);
    EXPECT_FALSE(scene.materials[0].base_color_texture);
    EXPECT_EQ(scene.meshes.at(0).uvs.size(), scene.meshes.at(0).positions.size());
}

TEST(LoadMaterials, EmbeddedAndExternalGltfTextures) {
    ZRASTER_REQUIRE_SHARED_DATA();
    struct Expectation {
        const char* embedded;
        const char* external;
        int size;
    };
    for (const Expectation& e :
         {Expectation{"meshes/gltf/Duck.glb", "meshes/gltf/Duck/Duck.gltf", 512},
          Expectation{"meshes/gltf/BoxTextured.glb", "meshes/gltf/BoxTextured/BoxTextured.gltf",
                      211}}) {
        SCOPED_TRACE(e.embedded);
        std::vector<std::string> warnings;
        const Scene glb = load_scene(test::shared_data(e.embedded), {}, &warnings);
        const Scene gltf = load_scene(test::shared_data(e.external), {}, &warnings);
        EXPECT_TRUE(warnings.empty());
        for (const Scene* s : {&glb, &gltf}) {
            ASSERT_EQ(s->meshes.size(), 1u);
            const Material& m = s->materials.at(s->meshes[0].material);
            ASSERT_TRUE(m.base_color_texture);
            EXPECT_EQ(m.base_color_texture->width(), e.size);
            EXPECT_EQ(m.base_color_texture->height(), e.size);
            EXPECT_EQ(m.base_color, glm::vec3(1.0f));
        }
        // The .glb embeds the same image the .gltf references.
        const Texture& a = *glb.materials.at(glb.meshes[0].material).base_color_texture;
        const Texture& b = *gltf.materials.at(gltf.meshes[0].material).base_color_texture;
        for (int y = 0; y < e.size; y += 17)
            for (int x = 0; x < e.size; x += 13) ASSERT_EQ(a.texel(0, x, y), b.texel(0, x, y));
    }
}

TEST(LoadMaterials, PlyHeaderTextureThatIsNotShippedIsAWarning) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const auto path = test::shared_data("meshes/ply/fuze.ply");
    std::vector<std::string> warnings;
    const Scene scene = load_scene(path, {}, &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0],
              path.string() + ": texture 'fuze uv.jpg' not found, using the material color");
}

}  // namespace
}  // namespace zraster
