// glTF doubleSided from the command line: `zraster info` reports it, `--cull auto` (the default)
// draws a double-sided triangle seen from behind and culls a single-sided one, `--cull back`
// culls both, `--cull none` draws both.
#include <zraster/image_io.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

// One triangle, counter-clockwise seen from +z, with a material that is double-sided or not.
void write_sided_gltf(const std::filesystem::path& dir, const std::string& name,
                      bool double_sided) {
    const float positions[9] = {-1, -1, 0, 1, -1, 0, -1, 1, 0};
    std::ofstream(dir / (name + ".bin"), std::ios::binary)
        .write(reinterpret_cast<const char*>(positions), sizeof positions);
    std::ofstream(dir / (name + ".gltf"))
        << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
           R"("nodes":[{"mesh":0}],"meshes":[)"
           R"({"primitives":[{"attributes":{"POSITION":0},"material":0}]}],)"
           R"("materials":[{"name":"leaf","doubleSided":)"
        << (double_sided ? "true" : "false")
        << R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[-1,-1,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("buffers":[{"uri":")"
        << name << R"(.bin","byteLength":36}]})";
}

TEST(MaterialSidesCommand, InfoAndCullFollowDoubleSided) {
    const auto dir = temp_dir("cli-material-sides");
    write_sided_gltf(dir, "double", true);
    write_sided_gltf(dir, "single", false);
    const CommandResult info = run_zraster("info double.gltf", dir);
    ASSERT_EQ(info.exit_code, 0) << info.output;
    EXPECT_NE(info.output.find("alpha opaque, double-sided\n"), std::string::npos) << info.output;
    const CommandResult single_info = run_zraster("info single.gltf", dir);
    EXPECT_EQ(single_info.output.find("double-sided"), std::string::npos) << single_info.output;

    // From behind: how many pixels the triangle lights (unlit white on black).
    const std::string behind =
        " --size 64x64 --shading unlit --background 0,0,0 --eye 0,0,-4 "
        "--target 0,0,0 --fovy 60 -o out.png";
    const auto drawn = [&](const std::string& file, const std::string& cull) {
        const CommandResult r = run_zraster("render " + file + behind + cull, dir);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        const ImageRGBA8 image = read_image_rgba8(dir / "out.png");
        int lit = 0;
        for (std::size_t i = 0; i < image.rgba.size(); i += 4) lit += image.rgba[i] != 0;
        return lit;
    };
    EXPECT_GT(drawn("double.gltf", ""), 100);
    EXPECT_GT(drawn("double.gltf", " --cull auto"), 100);
    EXPECT_EQ(drawn("single.gltf", ""), 0);
    EXPECT_EQ(drawn("double.gltf", " --cull back"), 0);
    EXPECT_EQ(drawn("double.gltf", " --cull front"), drawn("double.gltf", " --cull none"));
    EXPECT_GT(drawn("single.gltf", " --cull none"), 100);
    EXPECT_EQ(drawn("single.gltf", " --cull none"), drawn("double.gltf", ""));
}

}  // namespace
}  // namespace zraster::test
