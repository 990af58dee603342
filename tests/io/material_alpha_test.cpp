// Material alpha as each loader fills it (docs/materials.md): glTF's alphaMode, alphaCutoff and
// baseColorFactor alpha, base-color texture alpha, MTL d / Tr / map_d, and Assimp's opacity for
// the other formats; the same through the worker process.
#include <zraster/image_io.hpp>
#include <zraster/load.hpp>

#include <cstring>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

LoadOptions alpha_load_options(LoadIsolation isolation) {
    LoadOptions o;
    o.isolation = isolation;
    return o;
}

// Two RGBA8 textures hold the same level-0 bytes (both null counts as the same).
void expect_same_texels(const Texture* a, const Texture* b) {
    ASSERT_EQ(a == nullptr, b == nullptr);
    if (a == nullptr) return;
    ASSERT_EQ(a->width(), b->width());
    ASSERT_EQ(a->height(), b->height());
    const auto x = a->level_rgba(0), y = b->level_rgba(0);
    EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end()));
}

// The file loaded in process and through the worker: the materials' alpha must agree field by
// field, and so must the warnings. Returns the in-process scene and its warnings.
Scene load_alpha_both_ways(const std::filesystem::path& path,
                           std::vector<std::string>* warnings = nullptr) {
    SCOPED_TRACE(path.string());
    std::vector<std::string> in_process_warnings;
    Scene in_process =
        load_scene(path, alpha_load_options(LoadIsolation::InProcess), &in_process_warnings);
    std::vector<std::string> worker_warnings;
    const Scene worker =
        load_scene(path, alpha_load_options(LoadIsolation::WorkerProcess), &worker_warnings);
    EXPECT_EQ(in_process_warnings, worker_warnings);
    EXPECT_EQ(in_process.materials.size(), worker.materials.size());
    for (std::size_t i = 0; i < std::min(in_process.materials.size(), worker.materials.size());
         ++i) {
        const Material &a = in_process.materials[i], &b = worker.materials[i];
        SCOPED_TRACE("material " + a.name);
        EXPECT_EQ(a.opacity, b.opacity);
        EXPECT_EQ(a.alpha_mode, b.alpha_mode);
        EXPECT_EQ(a.alpha_cutoff, b.alpha_cutoff);
        EXPECT_EQ(a.double_sided, b.double_sided);
        expect_same_texels(a.base_color_texture.get(), b.base_color_texture.get());
        expect_same_texels(a.opacity_texture.get(), b.opacity_texture.get());
    }
    if (warnings != nullptr) *warnings = in_process_warnings;
    return in_process;
}

// The material of the file's one mesh.
const Material& only_material(const Scene& scene) {
    EXPECT_EQ(scene.meshes.size(), 1u);
    return scene.materials.at(scene.meshes.at(0).material);
}

// One textured triangle (buffer as a data URI) whose material is `material` (a JSON object);
// `images` is the glTF images array or empty.
std::string alpha_gltf(const std::string& material, const std::string& images = "") {
    const float data[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};  // positions, uvs
    const std::string bin(reinterpret_cast<const char*>(data), sizeof data);
    std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
        R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5126,"count":3,)"
        R"("type":"VEC2"}],"bufferViews":[{"buffer":0,"byteLength":36},)"
        R"({"buffer":0,"byteOffset":36,"byteLength":24}],)"
        R"("buffers":[{"byteLength":60,"uri":"data:application/octet-stream;base64,)" +
        test::base64(bin) + R"("}],"materials":[)" + material + "]";
    if (!images.empty()) json += R"(,"textures":[{"source":0}],"images":)" + images;
    return json + "}";
}

std::filesystem::path write_alpha_gltf(const std::string& test, const std::string& material) {
    return test::write_fixture("io-alpha-" + test, "m.gltf", alpha_gltf(material));
}

TEST(MaterialAlpha, GltfMaskKeepsItsCutoff) {
    std::vector<std::string> warnings;
    const Scene scene = load_alpha_both_ways(
        write_alpha_gltf("mask", R"({"name":"leaf","alphaMode":"MASK","alphaCutoff":0.3,)"
                                 R"("pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.8]}})"),
        &warnings);
    EXPECT_TRUE(warnings.empty());
    const Material& m = only_material(scene);
    EXPECT_EQ(m.name, "leaf");
    EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
    EXPECT_EQ(m.alpha_cutoff, 0.3f);
    EXPECT_EQ(m.opacity, 0.8f);  // tested against the cutoff with the texture's alpha
}

// Assimp gives baseColorFactor's alpha twice (as the base color's alpha and as its opacity):
// it must count once.
TEST(MaterialAlpha, GltfBlendTakesBaseColorAlphaOnce) {
    const Scene scene = load_alpha_both_ways(write_alpha_gltf(
        "blend", R"({"name":"glass","alphaMode":"BLEND",)"
                 R"("pbrMetallicRoughness":{"baseColorFactor":[0.2,0.4,0.6,0.25]}})"));
    const Material& m = only_material(scene);
    EXPECT_EQ(m.alpha_mode, AlphaMode::Blend);
    EXPECT_EQ(m.opacity, 0.25f);
    EXPECT_EQ(m.base_color, glm::vec3(0.2f, 0.4f, 0.6f));
    EXPECT_FALSE(m.opacity_texture);
}

TEST(MaterialAlpha, GltfOpaqueIgnoresBaseColorAlpha) {
    const Scene scene = load_alpha_both_ways(
        write_alpha_gltf("opaque", R"({"name":"wall","alphaMode":"OPAQUE",)"
                                   R"("pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.5]}})"));
    const Material& m = only_material(scene);
    EXPECT_EQ(m.alpha_mode, AlphaMode::Opaque);
    EXPECT_EQ(m.opacity, 1.0f);  // ignored: kept at 1 for readers that do not look at the mode
    EXPECT_EQ(m.alpha_cutoff, 0.5f);
}

TEST(MaterialAlpha, GltfWithoutAlphaModeIsOpaque) {
    const Scene scene = load_alpha_both_ways(write_alpha_gltf(
        "default", R"({"name":"plain","pbrMetallicRoughness":{"baseColorFactor":[1,0,0,0.5]}})"));
    const Material& m = only_material(scene);
    EXPECT_EQ(m.name, "plain");
    EXPECT_EQ(m.alpha_mode, AlphaMode::Opaque);
    EXPECT_EQ(m.opacity, 1.0f);
    EXPECT_EQ(m.alpha_cutoff, 0.5f);
}

// An alphaCutoff outside [0, 1] is clamped into it with a warning naming the material, not
// refused: the rest of the file is fine. 1e39 is infinite as a float.
TEST(MaterialAlpha, GltfCutoffOutsideZeroToOneIsClampedWithAWarning) {
    struct Case {
        const char* cutoff;
        float kept;
        const char* warning;
    };
    for (const Case& c : {Case{"-0.5", 0.0f, "alphaCutoff -0.5 is outside [0, 1], using 0"},
                          Case{"1.5", 1.0f, "alphaCutoff 1.5 is outside [0, 1], using 1"},
                          Case{"1e39", 1.0f, "alphaCutoff inf is outside [0, 1], using 1"}}) {
        SCOPED_TRACE(c.cutoff);
        const auto path = write_alpha_gltf(
            "cutoff",
            std::string(R"({"name":"m","alphaMode":"MASK","alphaCutoff":)") + c.cutoff + "}");
        std::vector<std::string> warnings;
        const Scene scene = load_alpha_both_ways(path, &warnings);
        EXPECT_EQ(only_material(scene).alpha_mode, AlphaMode::Mask);
        EXPECT_EQ(only_material(scene).alpha_cutoff, c.kept);
        ASSERT_EQ(warnings.size(), 1u);
        EXPECT_EQ(warnings[0], path.string() + ": material 'm': " + c.warning);
    }
    // Outside MASK the cutoff means nothing: clamped without a warning.
    std::vector<std::string> blend_warnings;
    const Scene blend = load_alpha_both_ways(
        write_alpha_gltf("cutoff-blend", R"({"alphaMode":"BLEND","alphaCutoff":-1})"),
        &blend_warnings);
    EXPECT_TRUE(blend_warnings.empty());
    EXPECT_EQ(only_material(blend).alpha_cutoff, 0.0f);
}

// Members of the wrong JSON type, which Assimp skips for the default: a warning each saying the
// value used, as for an alphaMode string outside OPAQUE, MASK and BLEND.
TEST(MaterialAlpha, GltfMembersOfTheWrongTypeWarnWithTheDefaultUsed) {
    const auto path = write_alpha_gltf(
        "types", R"({"name":"m","alphaMode":7,"alphaCutoff":"x","doubleSided":1,)"
                 R"("pbrMetallicRoughness":{"baseColorFactor":[1,0,0],"roughnessFactor":"r"}})");
    std::vector<std::string> warnings;
    const Scene scene = load_alpha_both_ways(path, &warnings);
    const Material& m = only_material(scene);
    EXPECT_EQ(m.alpha_mode, AlphaMode::Opaque);
    EXPECT_EQ(m.alpha_cutoff, 0.5f);
    EXPECT_FALSE(m.double_sided);
    EXPECT_EQ(m.base_color, glm::vec3(1.0f));
    const std::string prefix = path.string() + ": material 'm': ";
    EXPECT_EQ(
        warnings,
        (std::vector<std::string>{
            prefix + "alphaMode 7 is not a string (OPAQUE, MASK or BLEND), drawn opaque (glTF's "
                     "default)",
            prefix + "alphaCutoff \"x\" is not a number, using 0.5 (glTF's default)",
            prefix + "doubleSided 1 is not true or false, using false (glTF's default)",
            prefix + "baseColorFactor [1,0,0] is not 4 numbers, using 1, 1, 1, 1 (glTF's "
                     "default)",
            prefix + "roughnessFactor \"r\" is not a number, using 1 (glTF's default)"}));
    // Members of the right types: no warning.
    std::vector<std::string> none;
    load_alpha_both_ways(write_alpha_gltf("types-ok", R"({"alphaMode":"MASK","alphaCutoff":0.2,)"
                                                      R"("doubleSided":true})"),
                         &none);
    EXPECT_TRUE(none.empty()) << none.front();
}

// Numbers outside their glTF ranges that zraster does not shade with (metallic, emission, index
// of refraction) were accepted without a word: one warning each, naming the material and value.
TEST(MaterialAlpha, GltfUnusedNumbersOutsideTheirRangesWarn) {
    const auto path =
        write_alpha_gltf("unused", R"({"name":"m","pbrMetallicRoughness":{"metallicFactor":-5},)"
                                   R"("emissiveFactor":[1e30,0,0],"extensions":{)"
                                   R"("KHR_materials_emissive_strength":{"emissiveStrength":-1},)"
                                   R"("KHR_materials_ior":{"ior":-3}}})");
    std::vector<std::string> warnings;
    load_alpha_both_ways(path, &warnings);
    const std::string prefix = path.string() + ": material 'm': ";
    const std::string unused = "; not used (zraster does not shade with it)";
    EXPECT_EQ(warnings,
              (std::vector<std::string>{
                  prefix + "metallicFactor -5 is outside glTF's range [0, 1]" + unused,
                  prefix + "emissiveFactor [1e+30,0,0] is outside glTF's range [0, 1]" + unused,
                  prefix +
                      "KHR_materials_emissive_strength emissiveStrength -1 is negative (glTF's "
                      "range: 0 or more)" +
                      unused,
                  prefix + "KHR_materials_ior ior -3 is outside glTF's range (1 or more, or 0)" +
                      unused}));
    // Their ranges' ends: no warning (emissiveStrength has no upper bound; ior 0 is allowed).
    std::vector<std::string> none;
    load_alpha_both_ways(
        write_alpha_gltf("unused-ok",
                         R"({"pbrMetallicRoughness":{"metallicFactor":1},"emissiveFactor":[0,1,0],)"
                         R"("extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":)"
                         R"(1e38},"KHR_materials_ior":{"ior":0}}})"),
        &none);
    EXPECT_TRUE(none.empty()) << none.front();
}

// glTF factors outside their ranges (docs/limits.md): clamped, one warning each naming the
// material, the value and what is used; a factor too large for a float is infinite and the
// default color is used. roughnessFactor is checked itself (Assimp turns it into a shininess).
TEST(MaterialAlpha, GltfFactorsOutsideTheirRangesAreClampedWithAWarningEach) {
    const auto path = write_alpha_gltf(
        "factors", R"({"name":"m","alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorFactor":)"
                   R"([2,-1,0.5,1.5],"roughnessFactor":-1}})");
    std::vector<std::string> warnings;
    const Scene scene = load_alpha_both_ways(path, &warnings);
    const Material& m = only_material(scene);
    EXPECT_EQ(m.base_color, glm::vec3(1.0f, 0.0f, 0.5f));
    EXPECT_EQ(m.opacity, 1.0f);
    EXPECT_EQ(m.shininess, 1000.0f);  // roughness 0
    const std::string prefix = path.string() + ": material 'm': ";
    EXPECT_EQ(warnings, (std::vector<std::string>{
                            prefix + "base color (2, -1, 0.5) is outside 0..1, using (1, 0, 0.5)",
                            prefix + "roughnessFactor -1 is outside 0..1, using 0",
                            prefix + "baseColorFactor alpha 1.5 is outside 0..1, using 1"}));

    std::vector<std::string> infinite_warnings;
    const auto infinite = write_alpha_gltf(
        "factors-infinite", R"({"name":"m","pbrMetallicRoughness":{"baseColorFactor":)"
                            R"([1e39,0,0,1],"roughnessFactor":0.99}})");
    const Scene infinite_scene = load_alpha_both_ways(infinite, &infinite_warnings);
    const Material& i = only_material(infinite_scene);
    EXPECT_EQ(i.base_color, Material{}.base_color);
    EXPECT_EQ(i.shininess, 1.0f);  // 1000 x 0.01^2 = 0.1, from a valid roughness: no warning
    EXPECT_EQ(infinite_warnings,
              std::vector<std::string>{infinite.string() +
                                       ": material 'm': base color (inf, 0, 0) is not finite, "
                                       "using the default (0.8, 0.75, 0.7)"});
}

TEST(MaterialAlpha, GltfUnknownAlphaModeIsOpaqueWithAWarning) {
    const auto path = write_alpha_gltf("mode", R"({"name":"odd","alphaMode":"blend"})");
    std::vector<std::string> warnings;
    const Scene scene = load_alpha_both_ways(path, &warnings);
    EXPECT_EQ(only_material(scene).alpha_mode, AlphaMode::Opaque);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], path.string() +
                               ": material 'odd': alphaMode 'blend' is not OPAQUE, MASK or BLEND, "
                               "drawn opaque (glTF's default)");
}

// A 2 x 2 image of color 200: RGBA (`channels` 4) with alpha 255 but 64 at texel (1, 1), or RGB.
void write_alpha_png(const std::filesystem::path& path, int channels) {
    std::vector<std::uint8_t> pixels(std::size_t(2 * 2 * channels), 200);
    if (channels == 4)
        for (int i = 0; i < 4; ++i) pixels[std::size_t(4 * i + 3)] = i == 3 ? 64 : 255;
    write_png8(path, 2, 2, channels, pixels);
}

// The base-color texture keeps its alpha channel: RGBA texels with alpha below 255 stay so, an
// RGB image is opaque everywhere. Both as an external file and as a data URI.
TEST(MaterialAlpha, GltfBaseColorTextureAlpha) {
    const auto dir = test::temp_dir("io-alpha-texture");
    write_alpha_png(dir / "rgba.png", 4);
    write_alpha_png(dir / "rgb.png", 3);
    const std::string material =
        R"({"alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})";
    const std::string data_uri =
        "data:image/png;base64," + test::base64(test::read_bytes(dir / "rgba.png"));
    test::write_bytes(dir / "rgba.gltf", alpha_gltf(material, R"([{"uri":"rgba.png"}])"));
    test::write_bytes(dir / "rgb.gltf", alpha_gltf(material, R"([{"uri":"rgb.png"}])"));
    test::write_bytes(dir / "embedded.gltf",
                      alpha_gltf(material, R"([{"uri":")" + data_uri + R"("}])"));
    for (const char* name : {"rgba.gltf", "embedded.gltf"}) {
        const Scene scene = load_alpha_both_ways(dir / name);
        const Material& m = only_material(scene);
        ASSERT_TRUE(m.base_color_texture) << name;
        EXPECT_TRUE(m.base_color_texture->has_translucent_texels()) << name;
        EXPECT_EQ(m.base_color_texture->level_rgba(0)[3 * 4 + 3], 64) << name;
        EXPECT_EQ(m.opacity, 1.0f);
    }
    const Scene rgb = load_alpha_both_ways(dir / "rgb.gltf");
    ASSERT_TRUE(only_material(rgb).base_color_texture);
    EXPECT_FALSE(only_material(rgb).base_color_texture->has_translucent_texels());
}

// --- OBJ and MTL: both OBJ readers (obj_parser_test.cpp compares them on these files too).

const char* kAlphaObjBody = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";

// An OBJ with one triangle per material of `mtl`, named after them.
std::filesystem::path write_alpha_obj(const std::filesystem::path& dir, const std::string& mtl,
                                      const std::vector<std::string>& materials) {
    test::write_bytes(dir / "m.mtl", mtl);
    std::string obj = std::string("mtllib m.mtl\n") + kAlphaObjBody;
    for (const std::string& name : materials)
        obj += "o " + name + "\nusemtl " + name + "\nf 1/1 2/2 3/3\n";
    test::write_bytes(dir / "m.obj", obj);
    return dir / "m.obj";
}

const Material& alpha_material_of(const Scene& scene, const std::string& mesh) {
    for (const Mesh& m : scene.meshes)
        if (m.name == mesh) return scene.materials.at(m.material);
    ADD_FAILURE() << "no mesh " << mesh;
    return scene.materials.at(0);
}

TEST(MaterialAlpha, MtlDissolveAndTransparency) {
    const auto dir = test::temp_dir("io-alpha-mtl");
    const auto path =
        write_alpha_obj(dir,
                        "newmtl half\nd 0.5\n"
                        "newmtl tr\nTr 0.25\n"
                        "newmtl d_then_tr\nd 0.5\nTr 0.25\n"
                        "newmtl tr_then_d\nTr 0.25\nd 0.5\n"
                        "newmtl both_opaque\nd 1\nTr 1\n"
                        "newmtl plain\nKd 1 0 0\n",
                        {"half", "tr", "d_then_tr", "tr_then_d", "both_opaque", "plain"});
    std::vector<std::string> warnings;
    const Scene scene = load_alpha_both_ways(path, &warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(alpha_material_of(scene, "half").opacity, 0.5f);
    EXPECT_EQ(alpha_material_of(scene, "tr").opacity, 0.75f);
    // d wins over Tr in either order (Assimp alone keeps the last of the two).
    EXPECT_EQ(alpha_material_of(scene, "d_then_tr").opacity, 0.5f);
    EXPECT_EQ(alpha_material_of(scene, "tr_then_d").opacity, 0.5f);
    EXPECT_EQ(alpha_material_of(scene, "both_opaque").opacity, 1.0f);
    EXPECT_EQ(alpha_material_of(scene, "plain").opacity, 1.0f);
    for (const Material& m : scene.materials) {
        EXPECT_EQ(m.alpha_mode, AlphaMode::Blend) << m.name;
        EXPECT_EQ(m.alpha_cutoff, 0.5f) << m.name;
        EXPECT_FALSE(m.opacity_texture) << m.name;
    }
}

// map_d: a grey image's grey, an image with an alpha channel its alpha, in the red channel the
// renderer reads; the base-color image again adds nothing (its alpha counts already).
TEST(MaterialAlpha, MtlOpacityTextures) {
    const auto dir = test::temp_dir("io-alpha-map-d");
    std::vector<std::uint8_t> grey = {0, 64, 128, 255};
    write_png8(dir / "grey.png", 2, 2, 1, grey);
    write_alpha_png(dir / "leaf.png", 4);
    const auto path = write_alpha_obj(dir,
                                      "newmtl grey\nd 0.5\nmap_d grey.png\n"
                                      "newmtl cutout\nmap_d -imfchan m leaf.png\n"
                                      "newmtl leaf\nmap_Kd leaf.png\nmap_d leaf.png\n",
                                      {"grey", "cutout", "leaf"});
    std::vector<std::string> warnings;
    const Scene scene = load_alpha_both_ways(path, &warnings);
    EXPECT_TRUE(warnings.empty());

    const Material& g = alpha_material_of(scene, "grey");
    EXPECT_EQ(g.opacity, 0.5f);
    ASSERT_TRUE(g.opacity_texture);
    EXPECT_FALSE(g.base_color_texture);
    ASSERT_EQ(g.opacity_texture->width(), 2);
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(g.opacity_texture->level_rgba(0)[std::size_t(4 * i)], grey[std::size_t(i)]);

    const Material& c = alpha_material_of(scene, "cutout");
    ASSERT_TRUE(c.opacity_texture);
    const auto texels = c.opacity_texture->level_rgba(0);
    EXPECT_EQ(texels[3 * 4], 64);  // the alpha of texel (1, 1)
    EXPECT_EQ(texels[0], 255);     // opaque texels: red 255, not the image's red (200)
    EXPECT_FALSE(c.opacity_texture->has_translucent_texels());

    const Material& l = alpha_material_of(scene, "leaf");
    ASSERT_TRUE(l.base_color_texture);
    EXPECT_TRUE(l.base_color_texture->has_translucent_texels());
    EXPECT_FALSE(l.opacity_texture);
}

// map_d images have the budgets of map_Kd images: too large to decode is a warning and no
// texture, and images past max_texture_side are reduced.
TEST(MaterialAlpha, MtlOpacityTextureBudgets) {
    const auto dir = test::temp_dir("io-alpha-map-d-budget");
    std::vector<std::uint8_t> grey(std::size_t(64 * 64), 100);
    write_png8(dir / "big.png", 64, 64, 1, grey);
    const auto path = write_alpha_obj(dir, "newmtl m\nmap_d big.png\n", {"m"});
    LoadOptions small_side;
    small_side.max_texture_side = 16;
    std::vector<std::string> reduced_warnings;
    const Scene reduced = load_scene(path, small_side, &reduced_warnings);
    ASSERT_TRUE(alpha_material_of(reduced, "m").opacity_texture);
    EXPECT_EQ(alpha_material_of(reduced, "m").opacity_texture->width(), 16);
    ASSERT_EQ(reduced_warnings.size(), 1u);
    EXPECT_NE(reduced_warnings[0].find("texture 'big.png' is 64x64, reduced to 16x16"),
              std::string::npos)
        << reduced_warnings[0];
    LoadOptions small_budget;
    small_budget.max_texture_bytes = 1000;
    std::vector<std::string> refused_warnings;
    const Scene refused = load_scene(path, small_budget, &refused_warnings);
    EXPECT_FALSE(alpha_material_of(refused, "m").opacity_texture);
    ASSERT_EQ(refused_warnings.size(), 1u);
    EXPECT_NE(refused_warnings[0].find("more than the textures' budget"), std::string::npos)
        << refused_warnings[0];
}

// A DirectX .x material: Assimp gives its diffuse color's alpha (0.4), no opacity of its own.
TEST(MaterialAlpha, OtherFormatsBlendWithAssimpsAlpha) {
    const auto path = test::write_fixture("io-alpha-x", "tri.x",
                                          "xof 0303txt 0032\n"
                                          "Mesh tri {\n 3;\n 0.0;0.0;0.0;,\n 1.0;0.0;0.0;,\n"
                                          " 0.0;1.0;0.0;;\n 1;\n 3;0,1,2;;\n"
                                          " MeshMaterialList {\n  1;\n  1;\n  0;;\n"
                                          "  Material glass {\n   1.0;0.0;0.0;0.4;;\n   10.0;\n"
                                          "   0.0;0.0;0.0;;\n   0.0;0.0;0.0;;\n  }\n }\n}\n");
    const Scene scene = load_alpha_both_ways(path);
    const Material& m = only_material(scene);
    EXPECT_EQ(m.name, "glass");
    EXPECT_EQ(m.base_color, glm::vec3(1, 0, 0));
    EXPECT_EQ(m.alpha_mode, AlphaMode::Blend);
    EXPECT_EQ(m.opacity, 0.4f);
    EXPECT_EQ(m.alpha_cutoff, 0.5f);
}

// The shared meshes say nothing about transparency: none may load with alpha that can be
// below 1. (Computed here from the fields, independently of `zraster info`.)
TEST(MaterialAlpha, SharedMeshesAreOpaque) {
    ZRASTER_REQUIRE_SHARED_DATA();
    int loaded = 0;
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(test::shared_data("meshes"))) {
        if (!entry.is_regular_file() || !has_mesh_file_extension(entry.path())) continue;
        Scene scene;
        try {
            scene = load_scene(entry.path());
        } catch (const InputError&) {
            continue;  // the broken ones (BoxWithInfinites.glb)
        }
        ++loaded;
        for (const Material& m : scene.materials) {
            SCOPED_TRACE(entry.path().string() + " material " + m.name);
            if (m.alpha_mode == AlphaMode::Opaque) continue;
            EXPECT_EQ(m.opacity, 1.0f);
            EXPECT_FALSE(m.base_color_texture && m.base_color_texture->has_translucent_texels());
            EXPECT_FALSE(m.opacity_texture);
        }
    }
    EXPECT_GE(loaded, 20);
}

// doubleSided (glTF's default: false) reaches Material::double_sided, through the worker too;
// formats without the flag are single-sided.
TEST(MaterialAlpha, GltfDoubleSided) {
    EXPECT_TRUE(only_material(load_alpha_both_ways(write_alpha_gltf(
                                  "double", R"({"name":"leaf","doubleSided":true})")))
                    .double_sided);
    EXPECT_FALSE(only_material(load_alpha_both_ways(write_alpha_gltf(
                                   "single", R"({"name":"wall","doubleSided":false})")))
                     .double_sided);
    EXPECT_FALSE(
        only_material(load_alpha_both_ways(write_alpha_gltf("unsaid", R"({"name":"plain"})")))
            .double_sided);
    const auto dir = test::temp_dir("io-alpha-sides-obj");
    const Scene obj = load_alpha_both_ways(write_alpha_obj(dir, "newmtl a\nKd 1 0 0\n", {"a"}));
    for (const Material& m : obj.materials) EXPECT_FALSE(m.double_sided) << m.name;
}

}  // namespace
}  // namespace zraster
