// `zraster svg`: writes an SVG and reports its counts; bad options are exit 2 with no file.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(SvgCommand, WritesAnSvgAndReportsCounts) {
    const auto dir = temp_dir("svg-command");
    const CommandResult r = run_zraster("svg builtin:default --size 200x150 -o out.svg", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string svg = read_text(dir / "out.svg");
    EXPECT_TRUE(svg.starts_with("<?xml")) << svg.substr(0, 40);
    EXPECT_NE(svg.find("viewBox=\"0 0 200 150\""), std::string::npos);
    EXPECT_NE(r.output.find("wrote out.svg: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(" after merging"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(std::to_string(svg.size()) + " bytes"), std::string::npos) << r.output;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), "out.svg");  // no temporary left behind
}

// Nothing in view, or every triangle facing away: the SVG is written, with a warning (as render
// warns for the same frame); a drawing says nothing.
TEST(SvgCommand, AnSvgOfTheBackgroundAloneWarns) {
    const auto dir = temp_dir("svg-command-empty");
    for (const char* arguments :
         {"svg builtin:cube --size 16x16 -o out.svg --clip-plane 0,0,1,-100",
          "svg sphere:500 --size 16x16 -o out.svg --eye 0,0,0.1 --target "
          "0,0,-1 --order painter"}) {
        SCOPED_TRACE(arguments);
        const CommandResult r = run_zraster(arguments, dir);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find("triangles is drawn (outside the view or the clip planes, or "
                                "facing away): the SVG shows only the background\n"),
                  std::string::npos)
            << r.output;
        EXPECT_NE(r.output.find("wrote out.svg: 0 polygons"), std::string::npos) << r.output;
    }
    const CommandResult drawn = run_zraster("svg builtin:cube --size 16x16 -o out.svg", dir);
    EXPECT_EQ(drawn.output.find("warning"), std::string::npos) << drawn.output;
}

TEST(SvgCommand, PainterOrderWithEdgesAndCameraOptions) {
    const auto dir = temp_dir("svg-command-painter");
    const CommandResult r = run_zraster(
        "svg builtin:cube --size 120x90 --orbit 30,20,3 --shading unlit --order painter --edges "
        "--edge-color 255,0,0 --precision 1 -o cube.svg",
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string svg = read_text(dir / "cube.svg");
    EXPECT_NE(svg.find("stroke=\"#ff0000\""), std::string::npos);
    EXPECT_NE(svg.find("painter's order"), std::string::npos);
}

TEST(SvgCommand, BadOptionsAreExitTwoAndLeaveNoFile) {
    const auto dir = temp_dir("svg-command-bad");
    for (const char* options :
         {"--precision 9", "--precision -1", "--order zbuffer", "--edge-color 1,2",
          "--edge-color 300,0,0", "--edge-width -2", "--size 0x10", "--shading weird"}) {
        const CommandResult r =
            run_zraster(std::string("svg builtin:cube --size 64x48 -o out.svg ") + options, dir);
        EXPECT_EQ(r.exit_code, 2) << options << ": " << r.output;
        EXPECT_NE(r.output.find("zraster: "), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.svg")) << options;
    }
    const CommandResult png = run_zraster("svg builtin:cube -o out.png", dir);
    EXPECT_EQ(png.exit_code, 2) << png.output;
    EXPECT_NE(png.output.find(".svg"), std::string::npos) << png.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    const CommandResult missing = run_zraster("svg builtin:cube -o nodir/out.svg", dir);
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    const CommandResult no_scene = run_zraster("svg /nonexistent/x.obj -o out.svg", dir);
    EXPECT_EQ(no_scene.exit_code, 2) << no_scene.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.svg"));
}

TEST(SvgCommand, Help) {
    const CommandResult r = run_zraster("svg --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("--edges"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--orbit"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace zraster::test
