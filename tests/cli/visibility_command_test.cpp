// `zraster render --visibility ... --aa ... --msaa`: the classic algorithms from the command line,
// and what it says about transparent materials.
#include <zraster/image_io.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

// Two overlapping quads facing +z: an opaque red one behind a half-transparent blue one, in
// layers.obj the red one first, in layers-swapped.obj the blue one first.
void write_transparent_scene(const std::filesystem::path& dir) {
    std::ofstream mtl(dir / "layers.mtl");
    mtl << "newmtl red\nKd 1 0 0\nd 1\nnewmtl glass\nKd 0 0 1\nd 0.5\n";
    const char* const vertices =
        "mtllib layers.mtl\n"
        "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
        "v -0.5 -0.5 0.5\nv 1.5 -0.5 0.5\nv 1.5 1.5 0.5\nv -0.5 1.5 0.5\n";
    const char* const back = "o back\nusemtl red\nf 1 2 3\nf 1 3 4\n";
    const char* const front = "o front\nusemtl glass\nf 5 6 7\nf 5 7 8\n";
    std::ofstream(dir / "layers.obj") << vertices << back << front;
    std::ofstream(dir / "layers-swapped.obj") << vertices << front << back;
}

// Every way of drawing blends the glass over the red quad whichever is submitted first, and
// says nothing about drawing anything opaque; --alpha-mode opaque draws the glass opaque.
TEST(VisibilityCommand, TransparentMaterialsAreBlendedOnEveryPath) {
    const auto dir = temp_dir("visibility-transparent");
    write_transparent_scene(dir);
    const std::string view =
        " --size 64x64 --shading unlit --eye 0.25,0.25,6 --target 0.25,0.25,0 ";
    const std::size_t center = (32 * 64 + 32) * 4;
    for (const char* way : {"", "--aa 2", "--aa 2 --msaa", "--visibility painter",
                            "--visibility bsp", "--visibility warnock", "--visibility abuffer"}) {
        SCOPED_TRACE(way);
        ImageRGBA8 first;
        for (const char* file : {"layers.obj", "layers-swapped.obj"}) {
            const CommandResult r =
                run_zraster(std::string("render ") + file + view + way + " -o out.png", dir);
            ASSERT_EQ(r.exit_code, 0) << r.output;
            EXPECT_EQ(r.output.find("opaque"), std::string::npos) << r.output;
            const ImageRGBA8 image = read_image_rgba8(dir / "out.png");
            EXPECT_NEAR(image.rgba[center + 0], 128, 1) << file;  // half blue over red
            EXPECT_EQ(image.rgba[center + 1], 0) << file;
            EXPECT_NEAR(image.rgba[center + 2], 128, 1) << file;
            if (first.rgba.empty())
                first = image;
            else
                EXPECT_EQ(image.rgba, first.rgba) << "the submission order changed the image";
        }
        const CommandResult off = run_zraster(
            std::string("render layers.obj") + view + way + " --alpha-mode opaque -o opaque.png",
            dir);
        ASSERT_EQ(off.exit_code, 0) << off.output;
        const ImageRGBA8 opaque = read_image_rgba8(dir / "opaque.png");
        EXPECT_EQ(opaque.rgba[center + 0], 0);  // the front quad, opaque blue
        EXPECT_EQ(opaque.rgba[center + 2], 255);
    }
    // SVG: the glass with fill-opacity, the red quad behind it still in the drawing.
    for (const char* file : {"layers.obj", "layers-swapped.obj"}) {
        const CommandResult svg = run_zraster(
            std::string("svg ") + file + " --size 64x64 --shading unlit -o out.svg", dir);
        ASSERT_EQ(svg.exit_code, 0) << svg.output;
        EXPECT_EQ(svg.output.find("note"), std::string::npos) << svg.output;
        std::ifstream in(dir / "out.svg");
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        EXPECT_NE(text.find("fill-opacity=\"0.5\""), std::string::npos) << text;
        EXPECT_NE(text.find("fill=\"#ff0000\""), std::string::npos) << text;
    }
}

TEST(VisibilityCommand, AntialiasingModes) {
    const auto dir = temp_dir("visibility-aa");
    for (const char* options : {"--aa 2", "--aa 4 --msaa", "--visibility abuffer --aa 8",
                                "--visibility abuffer --aa 2 --shading phong"}) {
        const CommandResult r = run_zraster(
            std::string("render builtin:default --size 48x32 -o aa.png ") + options, dir);
        EXPECT_EQ(r.exit_code, 0) << options << ": " << r.output;
    }
    for (const char* options :
         {"--aa 3 --msaa", "--aa 4 --msaa --visibility painter", "--aa 2 --visibility bsp",
          "--aa 0", "--visibility abuffer --aa 3"}) {
        const CommandResult r = run_zraster(
            std::string("render builtin:default --size 48x32 -o bad.png ") + options, dir);
        EXPECT_EQ(r.exit_code, 2) << options << ": " << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "bad.png")) << options;
    }
}

}  // namespace
}  // namespace zraster::test
