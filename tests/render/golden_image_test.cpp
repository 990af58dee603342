// Golden image of the built-in default scene. Tolerance: at most 0.1% of the pixels may differ
// by more than 2/255 in any channel (room for another compiler's libm in pow/sin), and none by
// more than 64/255. Set ZRASTER_UPDATE_GOLDEN=1 to rewrite the golden file after an intended
// change, and look at it before committing.
#include <zraster/image_io.hpp>
#include <zraster/scenes.hpp>

#include <gtest/gtest.h>

#include <cstdlib>

#include "render/render_test_util.hpp"

namespace zraster::test {
namespace {

TEST(GoldenImage, DefaultSceneMatchesWithinTolerance) {
    constexpr int W = 480, H = 270;
    const std::filesystem::path golden =
        std::filesystem::path(ZRASTER_SOURCE_DIR) / "tests/golden/default-480x270.png";
    RenderOptions o;
    o.width = W;
    o.height = H;
    o.camera = builtin_camera("builtin:default");
    const RenderResult r = render(make_procedural_scene("builtin:default"), o);
    std::vector<std::uint8_t> rgb(std::size_t(W * H * 3));
    for (std::size_t i = 0; i < std::size_t(W * H); ++i)
        for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = r.targets.color[i * 4 + c];
    if (std::getenv("ZRASTER_UPDATE_GOLDEN")) write_png8(golden, W, H, 3, rgb);

    const ImageRGBA8 expected = read_image_rgba8(golden);
    ASSERT_EQ(expected.width, W);
    ASSERT_EQ(expected.height, H);
    int beyond_two = 0, worst = 0;
    for (std::size_t i = 0; i < std::size_t(W * H); ++i) {
        int d = 0;
        for (std::size_t c = 0; c < 3; ++c)
            d = std::max(d, std::abs(int(rgb[i * 3 + c]) - int(expected.rgba[i * 4 + c])));
        beyond_two += d > 2;
        worst = std::max(worst, d);
    }
    EXPECT_LE(beyond_two, W * H / 1000);
    EXPECT_LE(worst, 64);
}

}  // namespace
}  // namespace zraster::test
