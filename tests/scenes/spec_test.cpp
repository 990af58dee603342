#include <zraster/error.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <string>

namespace zraster {
namespace {

std::string error_of(std::string_view spec) {
    try {
        make_procedural_scene(spec);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), spec);
        return e.cause();
    }
    ADD_FAILURE() << spec << " did not throw";
    return {};
}

const std::string malformed =
    "malformed scene spec: expected sphere:N, city:N[:SEED] or soup:N[:SEED]";

TEST(ProceduralSpec, Recognized) {
    for (const char* spec : {"sphere:100", "city:5", "city:5:9", "soup:3:1", "builtin:default",
                             "builtin:cube", "sphere:oops"})
        EXPECT_TRUE(is_procedural_spec(spec)) << spec;
    for (const char* spec :
         {"bunny.obj", "sphere", "spheres:1", "", "meshes/city:1.obj", "Sphere:1"})
        EXPECT_FALSE(is_procedural_spec(spec)) << spec;
}

TEST(ProceduralSpec, BenchScenesAreOneMeshOneIdentityInstanceDefaultMaterial) {
    const Scene s = make_procedural_scene("city:50:3");
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.instances.size(), 1u);
    EXPECT_EQ(s.instances[0].transform, glm::mat4(1.0f));
    EXPECT_FALSE(s.instances[0].shading.has_value());
    ASSERT_EQ(s.materials.size(), 1u);
    const Material reference;
    EXPECT_EQ(s.materials[0].base_color, reference.base_color);
    EXPECT_EQ(s.materials[0].shininess, 32.0f);
    EXPECT_EQ(s.meshes[0].material, 0u);
    EXPECT_EQ(s.name, "city:50:3");
    EXPECT_EQ(geometry_hash(s.meshes[0]), geometry_hash(make_bench_city(50, 3)));
    EXPECT_EQ(s.triangle_count(), 502u);

    EXPECT_EQ(geometry_hash(make_procedural_scene("sphere:400").meshes[0]),
              geometry_hash(make_bench_sphere(400)));
    EXPECT_EQ(geometry_hash(make_procedural_scene("soup:20").meshes[0]),
              geometry_hash(make_bench_soup(20, 1)));
    EXPECT_EQ(geometry_hash(make_procedural_scene("soup:20:18446744073709551615").meshes[0]),
              geometry_hash(make_bench_soup(20, 18446744073709551615ull)));
}

TEST(ProceduralSpec, MalformedSpecs) {
    for (const char* spec : {"sphere:", "sphere:abc", "sphere:10:2", "sphere:1e6", "sphere:-5",
                             "sphere: 5", "sphere:5 ", "sphere:+5", "city:5:", "city:5:x",
                             "city:5:1:2", "soup::1", "cube:5", "soup:0x10"})
        EXPECT_EQ(error_of(spec), malformed) << spec;
}

TEST(ProceduralSpec, OutOfRange) {
    EXPECT_EQ(error_of("sphere:0"), "N out of range (1..20000000)");
    EXPECT_EQ(error_of("soup:20000001"), "N out of range (1..20000000)");
    EXPECT_EQ(error_of("sphere:99999999999999999999999"), "N out of range (1..20000000)");
    EXPECT_EQ(error_of("city:2000001"), "N out of range (1..2000000)");
    EXPECT_EQ(error_of("city:0:4"), "N out of range (1..2000000)");
    EXPECT_EQ(error_of("soup:5:18446744073709551616"),
              "SEED out of range (0..18446744073709551615)");
    // The full message names the spec like a file.
    try {
        make_procedural_scene("city:0");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "city:0: N out of range (1..2000000)");
    }
}

// Buildings take any 64-bit seed, as city: and soup: do (20 digits were "malformed").
TEST(ProceduralSpec, BuildingSeeds) {
    EXPECT_EQ(make_procedural_scene("building:2x2:18446744073709551615").name,
              "building:2x2:18446744073709551615");
    EXPECT_EQ(error_of("building:2x2:18446744073709551616"),
              "SEED out of range (0..18446744073709551615)");
    EXPECT_EQ(error_of("building:2x2:x"), "malformed scene spec: expected building:RxC[:SEED]");
    EXPECT_EQ(error_of("building:99999999999999999999x2"),
              "R x C out of range (at least 1 x 1, at most 16384 a side and 65536 rooms)");
}

TEST(ProceduralSpec, UnknownBuiltin) {
    EXPECT_THROW(make_procedural_scene("builtin:teapot"), InputError);
    EXPECT_THROW(make_procedural_scene("builtin:"), InputError);
}

TEST(ProceduralSpec, BuiltinSphereAndCube) {
    const Scene sphere = make_procedural_scene("builtin:sphere");
    ASSERT_EQ(sphere.meshes.size(), 1u);
    ASSERT_EQ(sphere.instances.size(), 1u);
    EXPECT_EQ(sphere.meshes[0].vertex_count(), 65u * 129u);
    EXPECT_EQ(sphere.meshes[0].normals.size(), sphere.meshes[0].vertex_count());
    EXPECT_EQ(sphere.name, "builtin:sphere");

    const Scene cube = make_procedural_scene("builtin:cube");
    ASSERT_EQ(cube.meshes.size(), 1u);
    EXPECT_EQ(cube.meshes[0].vertex_count(), 24u);
    EXPECT_FALSE(builtin_camera("builtin:cube").has_value());
    EXPECT_FALSE(builtin_camera("sphere:100").has_value());
}

}  // namespace
}  // namespace zraster
