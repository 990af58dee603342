// `zraster render --visibility ... --aa ... --msaa`: the classic algorithms from the command line,
// and what it says about transparent materials.
#include <zraster/image_io.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

// Two overlapping quads facing +z: an opaque red one behind a half-transparent blue one.
void write_transparent_scene(const std::filesystem::path& dir) {
    std::ofstream mtl(dir / "layers.mtl");
    mtl << "newmtl red\nKd 1 0 0\nd 1\nnewmtl glass\nKd 0 0 1\nd 0.5\n";
    std::ofstream obj(dir / "layers.obj");
    obj << "mtllib layers.mtl\n"
           "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
           "v -0.5 -0.5 0.5\nv 1.5 -0.5 0.5\nv 1.5 1.5 0.5\nv -0.5 1.5 0.5\n"
           "o back\nusemtl red\nf 1 2 3\nf 1 3 4\n"
           "o front\nusemtl glass\nf 5 6 7\nf 5 7 8\n";
}

TEST(VisibilityCommand, TransparentMaterialsAreBlendedByTheZBufferAndTheABuffer) {
    const auto dir = temp_dir("visibility-transparent");
    write_transparent_scene(dir);
    const std::string common =
        "render layers.obj --size 64x64 --shading unlit --eye 0.25,0.25,6 --target 0.25,0.25,0 ";
    for (const char* visibility : {"painter", "bsp", "warnock"}) {
        const CommandResult r =
            run_zraster(common + "--visibility " + visibility + " -o opaque.png", dir);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find("draws them opaque"), std::string::npos) << visibility << r.output;
        EXPECT_NE(r.output.find("--visibility abuffer"), std::string::npos) << r.output;
    }
    const CommandResult z = run_zraster(common + "-o zbuffer.png --stats", dir);
    ASSERT_EQ(z.exit_code, 0) << z.output;
    EXPECT_EQ(z.output.find("opaque"), std::string::npos) << z.output;
    EXPECT_NE(z.output.find("blended"), std::string::npos) << z.output;
    const CommandResult ssaa = run_zraster(common + "--aa 2 -o ssaa.png", dir);
    ASSERT_EQ(ssaa.exit_code, 0) << ssaa.output;
    EXPECT_EQ(ssaa.output.find("opaque"), std::string::npos) << ssaa.output;
    const CommandResult msaa = run_zraster(common + "--aa 2 --msaa -o msaa.png", dir);
    ASSERT_EQ(msaa.exit_code, 0) << msaa.output;
    EXPECT_NE(msaa.output.find("--msaa draws them opaque"), std::string::npos) << msaa.output;
    const CommandResult a = run_zraster(common + "--visibility abuffer -o blended.png", dir);
    ASSERT_EQ(a.exit_code, 0) << a.output;
    EXPECT_EQ(a.output.find("opaque"), std::string::npos) << a.output;
    const CommandResult off =
        run_zraster(common + "--alpha-mode opaque -o opaque_zbuffer.png", dir);
    ASSERT_EQ(off.exit_code, 0) << off.output;
    EXPECT_EQ(off.output.find("opaque"), std::string::npos) << off.output;
    // Where the two overlap (the image center): half blue over red, in both ways that blend.
    const ImageRGBA8 opaque = read_image_rgba8(dir / "opaque.png");
    const ImageRGBA8 opaque_zbuffer = read_image_rgba8(dir / "opaque_zbuffer.png");
    const ImageRGBA8 blended = read_image_rgba8(dir / "blended.png");
    const ImageRGBA8 zbuffer = read_image_rgba8(dir / "zbuffer.png");
    const ImageRGBA8 supersampled = read_image_rgba8(dir / "ssaa.png");
    const std::size_t center = (32 * 64 + 32) * 4;
    for (const ImageRGBA8* image : {&opaque, &opaque_zbuffer}) {
        EXPECT_EQ(image->rgba[center + 0], 0);  // the front quad, opaque blue
        EXPECT_EQ(image->rgba[center + 2], 255);
    }
    for (const ImageRGBA8* image : {&blended, &zbuffer, &supersampled}) {
        EXPECT_NEAR(image->rgba[center + 0], 128, 1);
        EXPECT_NEAR(image->rgba[center + 2], 128, 1);
    }
    const CommandResult svg = run_zraster("svg layers.obj --size 64x64 -o out.svg", dir);
    ASSERT_EQ(svg.exit_code, 0) << svg.output;
    EXPECT_NE(svg.output.find("zraster svg draws them opaque"), std::string::npos) << svg.output;
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
