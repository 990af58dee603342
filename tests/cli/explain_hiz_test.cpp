// `zraster explain hiz`: its first picture starts with the renderer's hiz view, the picture
// `zraster render --view hiz` writes, pixel for pixel.
#include <gtest/gtest.h>
#include <zraster/image_io.hpp>

#include <string>

#include "support/test_support.hpp"

namespace zraster::test {
namespace {

TEST(ExplainHiz, LeftPictureIsTheRenderersHizView) {
    const auto dir = temp_dir("explain-hiz-view");
    const CommandResult r = run_zraster("explain hiz city:200 --size 160x120 -o out", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("explain hiz: 3 files in out"), std::string::npos) << r.output;
    const std::string index = read_bytes(dir / "out" / "index.html");
    EXPECT_NE(index.find("<code>hiz.png</code>"), std::string::npos);
    EXPECT_NE(index.find("Hierarchical z"), std::string::npos);
    const CommandResult view =
        run_zraster("render city:200 --size 160x120 --view hiz -o view.png", dir);
    ASSERT_EQ(view.exit_code, 0) << view.output;
    const ImageRGBA8 picture = read_image_rgba8(dir / "out" / "hiz.png");
    const ImageRGBA8 render = read_image_rgba8(dir / "view.png");
    ASSERT_GE(picture.width, 3 * render.width);
    for (int y = 0; y < render.height; ++y)
        for (int x = 0; x < render.width; ++x)
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(
                    picture
                        .rgba[(std::size_t(y) * std::size_t(picture.width) + std::size_t(x)) * 4 +
                              std::size_t(k)],
                    render.rgba[(std::size_t(y) * std::size_t(render.width) + std::size_t(x)) * 4 +
                                std::size_t(k)])
                    << x << "," << y;
}

}  // namespace
}  // namespace zraster::test
