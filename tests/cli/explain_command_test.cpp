// `zraster explain`: every algorithm writes its pictures and an index.html naming each of them;
// the pictures that are frames of zraster show zraster's own images.
#include <gtest/gtest.h>
#include <zraster/image_io.hpp>

#include <fstream>
#include <set>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

std::set<std::string> explain_folder_files(const std::filesystem::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        names.insert(entry.path().filename().string());
    return names;
}

// The number of frames an APNG declares (acTL), 0 when it has none.
unsigned apng_frames(const std::filesystem::path& path) {
    const std::string bytes = read_bytes(path);
    const std::size_t at = bytes.find("acTL");
    if (at == std::string::npos || at + 8 > bytes.size()) return 0;
    unsigned n = 0;
    for (int i = 0; i < 4; ++i)
        n = (n << 8) | static_cast<unsigned char>(bytes[at + 4 + std::size_t(i)]);
    return n;
}

struct ExplainCase {
    const char* algorithm;
    const char* scene;
    std::vector<std::string> required;
};

TEST(ExplainCommand, EveryAlgorithmWritesItsPicturesAndAnIndexNamingThem) {
    const std::vector<ExplainCase> cases = {
        {"zbuffer", "sphere:200", {"zbuffer-01.png", "zbuffer-animation.png"}},
        {"painter",
         "builtin:default",
         {"painter-01.png", "painter-animation.png", "painter-tests.svg"}},
        {"bsp",
         "sphere:200",
         {"bsp-level-00.png", "bsp-levels.png", "bsp-order.png", "bsp-tree.svg"}},
        {"warnock",
         "sphere:200",
         {"warnock-level-00.png", "warnock-animation.png", "warnock-result.png"}},
        {"abuffer",
         "sphere:200",
         {"abuffer-pixel.png", "abuffer-fragments.svg", "abuffer-fragments.png"}},
        {"sutherland-hodgman",
         "",
         {"sutherland-hodgman-2d-4.svg", "sutherland-hodgman-homogeneous.svg",
          "sutherland-hodgman-ndc.png"}},
        {"cohen-sutherland", "", {"cohen-sutherland.svg", "cohen-sutherland.png"}},
        {"liang-barsky", "", {"liang-barsky.svg", "liang-barsky.png"}},
        {"cyrus-beck", "", {"cyrus-beck.svg", "cyrus-beck.png"}},
        {"bresenham", "", {"bresenham.svg", "bresenham.png"}},
        {"dda", "", {"dda.svg", "dda.png"}},
        {"frustum-culling", "sphere:200", {"frustum-culling.png"}},
        {"backface-culling", "sphere:200", {"backface-culling.png"}},
        {"occlusion-culling", "building:4x4", {"occlusion-culling.png"}},
        {"hiz", "city:40", {"hiz.png", "hiz-front-to-back.png"}},
    };
    for (const ExplainCase& c : cases) {
        const auto dir = temp_dir(std::string("explain-") + c.algorithm);
        // (The 2D algorithms draw their own figures: no scene, no size.)
        const std::string scene = *c.scene ? std::string(c.scene) + " --size 160x120" : "";
        const CommandResult r =
            run_zraster(std::string("explain ") + c.algorithm + " " + scene + " -o out", dir);
        ASSERT_EQ(r.exit_code, 0) << c.algorithm << ": " << r.output;
        const std::set<std::string> files = explain_folder_files(dir / "out");
        EXPECT_NE(r.output.find(std::to_string(files.size()) + " files in out"), std::string::npos)
            << r.output;
        ASSERT_TRUE(files.count("index.html")) << c.algorithm;
        const std::string index = read_bytes(dir / "out" / "index.html");
        for (const std::string& name : c.required)
            EXPECT_TRUE(files.count(name)) << c.algorithm << ": no " << name;
        // Every picture is named in the index with its caption (PNGs beside an SVG are its
        // rasterization and go with it).
        for (const std::string& name : files) {
            if (name == "index.html") continue;
            const std::string stem = name.substr(0, name.rfind('.'));
            EXPECT_TRUE(index.find("<code>" + name + "</code>") != std::string::npos ||
                        (name.ends_with(".png") && files.count(stem + ".svg")))
                << c.algorithm << ": " << name << " is not in index.html";
        }
    }
}

// Every algorithm that takes a scene, on a shared mesh: its pictures, each named in the index.
TEST(ExplainCommand, EveryAlgorithmOnASharedMesh) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const std::string mesh = "'" + shared_data("meshes/obj/bunny-small.obj").string() + "'";
    for (const std::string algorithm :
         {"zbuffer", "painter", "bsp", "warnock", "abuffer", "frustum-culling", "backface-culling",
          "occlusion-culling", "hiz"}) {
        const auto dir = temp_dir("explain-shared-" + algorithm);
        const CommandResult r =
            run_zraster("explain " + algorithm + " " + mesh + " --size 96x72 -o out", dir);
        ASSERT_EQ(r.exit_code, 0) << algorithm << ": " << r.output;
        const std::set<std::string> files = explain_folder_files(dir / "out");
        ASSERT_TRUE(files.count("index.html")) << algorithm;
        std::size_t pictures = 0;
        const std::string index = read_bytes(dir / "out" / "index.html");
        for (const std::string& name : files) {
            if (name == "index.html") continue;
            ++pictures;
            EXPECT_FALSE(read_bytes(dir / "out" / name).empty()) << algorithm << ": " << name;
        }
        EXPECT_GE(pictures, 1u) << algorithm;
        EXPECT_NE(index.find(".png"), std::string::npos) << algorithm;
    }
}

TEST(ExplainCommand, ZbufferFramesEndWithTheRenderersImage) {
    const auto dir = temp_dir("explain-zbuffer-frames");
    const CommandResult r =
        run_zraster("explain zbuffer sphere:200 --size 80x60 --step 100 -o out", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // sphere:200's triangles in steps of 100: one frame per step, the last with all of them.
    std::size_t stills = 0;
    for (const std::string& name : explain_folder_files(dir / "out"))
        stills += name.starts_with("zbuffer-0") || name.starts_with("zbuffer-1");
    EXPECT_GE(stills, 2u);
    EXPECT_EQ(apng_frames(dir / "out" / "zbuffer-animation.png"), stills);
    ASSERT_EQ(run_zraster("render sphere:200 --size 80x60 -o r.png", dir).exit_code, 0);
    const ImageRGBA8 frame = read_image_rgba8(
        dir / "out" /
        ("zbuffer-" + std::string(stills < 10 ? "0" : "") + std::to_string(stills) + ".png"));
    const ImageRGBA8 render = read_image_rgba8(dir / "r.png");
    // The last frame's left part is the color buffer: the command's image, pixel for pixel.
    ASSERT_GE(frame.width, 2 * render.width);
    for (int y = 0; y < render.height; ++y)
        for (int x = 0; x < render.width; ++x)
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(
                    frame.rgba[(std::size_t(y) * std::size_t(frame.width) + std::size_t(x)) * 4 +
                               std::size_t(k)],
                    render.rgba[(std::size_t(y) * std::size_t(render.width) + std::size_t(x)) * 4 +
                                std::size_t(k)])
                    << x << "," << y;
}

TEST(ExplainCommand, WarnockResultIsTheVisibilityFlagsImage) {
    const auto dir = temp_dir("explain-warnock-result");
    ASSERT_EQ(run_zraster("explain warnock sphere:200 --size 96x64 -o out", dir).exit_code, 0);
    ASSERT_EQ(
        run_zraster("render sphere:200 --size 96x64 --visibility warnock -o r.png", dir).exit_code,
        0);
    const ImageRGBA8 a = read_image_rgba8(dir / "out" / "warnock-result.png");
    const ImageRGBA8 b = read_image_rgba8(dir / "r.png");
    EXPECT_EQ(a.rgba, b.rgba);
}

// building:RxC carries a cell graph for all its instances: the frames short of some draw
// without it.
TEST(ExplainCommand, ZbufferFramesOfABuildingWithCells) {
    const auto dir = temp_dir("explain-zbuffer-cells");
    const CommandResult r = run_zraster("explain zbuffer building:3x3 --size 80x60 -o out", dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / "zbuffer-animation.png"));
}

TEST(ExplainCommand, BadInputIsExitTwoWithOneLine) {
    const auto dir = temp_dir("explain-bad");
    const CommandResult unknown = run_zraster("explain quadtree sphere:20 -o out", dir);
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_TRUE(single_line(unknown.output)) << unknown.output;
    EXPECT_TRUE(
        unknown.output.starts_with("zraster: explain: unknown algorithm 'quadtree' (zbuffer, "))
        << unknown.output;
    const CommandResult missing = run_zraster("explain zbuffer /nonexistent/x.obj -o out", dir);
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_TRUE(single_line(missing.output)) << missing.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "index.html"));
    std::ofstream(dir / "file") << "x";
    // A scene or a frame option given to an algorithm that draws its own figures.
    for (const char* run :
         {"explain cohen-sutherland builtin:cube -o out", "explain dda -o out --size 100x100",
          "explain bresenham -o out --step 2"})
        EXPECT_EQ(run_zraster(run, dir).exit_code, 2) << run;
    EXPECT_EQ(run_zraster("explain cohen-sutherland city:20 -o out", dir).output,
              "zraster: city:20: cohen-sutherland draws its own figures: it takes no scene, and no "
              "size, camera, shading or --step (only -o and the --max- budgets)\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "out"));
    const CommandResult not_folder = run_zraster("explain dda -o file", dir);
    EXPECT_EQ(not_folder.exit_code, 2);
    EXPECT_EQ(not_folder.output, "zraster: -o: file exists and is not a folder\n");
}

}  // namespace
}  // namespace zraster::test
