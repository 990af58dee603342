// `zraster render --view NAME`: a picture other than the shaded one with its legend printed, and
// a bad name refused with the list of names.
#include <gtest/gtest.h>

#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

TEST(DebugViewCommand, OverdrawWritesAnotherPictureAndItsLegend) {
    const auto dir = temp_dir("debug_view_overdraw");
    const std::string common = "render sphere:2000 --size 160x120 --threads 2";
    const CommandResult plain = run_zraster(common + " -o plain.png", dir);
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    const CommandResult view = run_zraster(common + " --view overdraw -o view.png", dir);
    ASSERT_EQ(view.exit_code, 0) << view.output;
    EXPECT_NE(view.output.find("overdraw: fragments per pixel"), std::string::npos) << view.output;
    const std::string a = read_bytes(dir / "plain.png"), b = read_bytes(dir / "view.png");
    ASSERT_FALSE(a.empty());
    ASSERT_FALSE(b.empty());
    EXPECT_NE(a, b);
    // The same name through "lod", the alias of mip.
    const CommandResult lod = run_zraster(common + " --view lod -o lod.png", dir);
    EXPECT_EQ(lod.exit_code, 0) << lod.output;
}

// Every view on a shared, textured mesh (the Duck): a picture unlike the shaded one, with its
// legend.
TEST(DebugViewCommand, EveryViewOnASharedMesh) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const auto dir = temp_dir("debug_view_shared");
    const std::string common =
        "render '" + shared_data("meshes/gltf/Duck.glb").string() + "' --size 120x90 --threads 2";
    const CommandResult plain = run_zraster(common + " -o plain.png", dir);
    ASSERT_EQ(plain.exit_code, 0) << plain.output;
    const std::string shaded = read_bytes(dir / "plain.png");
    for (const std::string view : {"depth", "normals", "overdraw", "hiz", "tiles", "ids",
                                   "backfaces", "clipped", "zfight", "mip"}) {
        const CommandResult r = run_zraster(
            common + " --view " + view + " --depth-format d16 -o " + view + ".png", dir);
        ASSERT_EQ(r.exit_code, 0) << view << ": " << r.output;
        EXPECT_NE(r.output.find(view + ": "), std::string::npos)
            << view << ": no legend in " << r.output;
        const std::string picture = read_bytes(dir / (view + ".png"));
        ASSERT_FALSE(picture.empty()) << view;
        EXPECT_NE(picture, shaded) << view;
    }
}

TEST(DebugViewCommand, BadNameExitsTwoListingTheNames) {
    const auto dir = temp_dir("debug_view_bad");
    const CommandResult r =
        run_zraster("render sphere:200 --size 64x48 --view heat -o out.png", dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_NE(r.output.find("--view"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'heat'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("none, depth, normals, overdraw, hiz, tiles, ids, backfaces, "
                            "clipped, zfight, mip"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(DebugViewCommand, NeedsThePipeline) {
    const auto dir = temp_dir("debug_view_pipeline");
    const CommandResult r = run_zraster(
        "render sphere:200 --size 64x48 --view depth --visibility painter -o out.png", dir);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(single_line(r.output)) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

}  // namespace
}  // namespace zraster::test
