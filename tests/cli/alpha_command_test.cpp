// `zraster render` of a glTF file with the four alpha modes (docs/images/alpha-modes.gltf: panels
// whose texture's alpha falls from 1 at the top to 0 at the bottom, in front of a gray
// checkerboard wall): what shows through each panel, with --alpha-mode auto and opaque.
#include <zraster/image_io.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

// The camera of the README's picture: the panels' centers land on these columns, their top
// and bottom edges on rows 56 and 224.
const char* const kView =
    " --size 640x280 --shading unlit --eye 0,0,3.2 --target 0,0,0 --fovy 40 --stats";
constexpr int kOpaqueColumn = 122, kBlendColumn = 254, kMask25Column = 386, kMask75Column = 518;

// The wall is gray (220 or 60-70 in each channel); the panels' stripes are green and yellow.
bool wall_shows(const ImageRGBA8& image, int px, int py) {
    const std::uint8_t* p = &image.rgba[(std::size_t(py) * std::size_t(image.width) + px) * 4];
    const int spread =
        std::max({std::abs(p[0] - p[1]), std::abs(p[1] - p[2]), std::abs(p[0] - p[2])});
    return spread <= 14;
}

TEST(AlphaCommand, TheFourGltfAlphaModes) {
    const auto dir = temp_dir("alpha-command");
    const std::string file = std::string(ZRASTER_SOURCE_DIR) + "/docs/images/alpha-modes.gltf";
    const CommandResult automatic = run_zraster("render " + file + " -o auto.png" + kView, dir);
    ASSERT_EQ(automatic.exit_code, 0) << automatic.output;
    EXPECT_NE(automatic.output.find("alpha: fragments discarded by the alpha test"),
              std::string::npos)
        << automatic.output;
    const CommandResult opaque =
        run_zraster("render " + file + " -o opaque.png --alpha-mode opaque" + kView, dir);
    ASSERT_EQ(opaque.exit_code, 0) << opaque.output;
    EXPECT_EQ(opaque.output.find("alpha:"), std::string::npos) << opaque.output;

    const ImageRGBA8 a = read_image_rgba8(dir / "auto.png");
    const ImageRGBA8 o = read_image_rgba8(dir / "opaque.png");
    ASSERT_EQ(a.width, 640);
    // Rows where the texture's alpha is about 0.9, 0.45 and 0.07.
    const int top = 70, middle = 150, bottom = 215;
    for (const int column : {kOpaqueColumn, kBlendColumn, kMask25Column, kMask75Column})
        for (const int row : {top, middle, bottom})
            EXPECT_FALSE(wall_shows(o, column, row)) << "opaque mode, " << column << "," << row;
    // OPAQUE: alpha ignored.
    for (const int row : {top, middle, bottom}) EXPECT_FALSE(wall_shows(a, kOpaqueColumn, row));
    // BLEND: the panel where alpha is high, nearly the wall where it is low.
    EXPECT_FALSE(wall_shows(a, kBlendColumn, top));
    EXPECT_TRUE(wall_shows(a, kBlendColumn, bottom));
    // MASK 0.25: cut below alpha 0.25 only; MASK 0.75: below 0.75.
    EXPECT_FALSE(wall_shows(a, kMask25Column, top));
    EXPECT_FALSE(wall_shows(a, kMask25Column, middle));
    EXPECT_TRUE(wall_shows(a, kMask25Column, bottom));
    EXPECT_FALSE(wall_shows(a, kMask75Column, top));
    EXPECT_TRUE(wall_shows(a, kMask75Column, middle));
    EXPECT_TRUE(wall_shows(a, kMask75Column, bottom));
}

}  // namespace
}  // namespace zraster::test
