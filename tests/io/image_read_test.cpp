// Reading images as RGBA8.
#include <zraster/image_io.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

namespace zraster {
namespace {

TEST(ReadImage, ExpandsGrayToRgbaTopRowFirst) {
    const auto path = test::temp_dir("io-read-gray") / "gray.png";
    const std::vector<std::uint8_t> gray = {10, 20, 30, 40, 50, 60};  // 3 x 2
    write_png8(path, 3, 2, 1, gray);
    const ImageRGBA8 image = read_image_rgba8(path);
    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.height, 2);
    ASSERT_EQ(image.rgba.size(), 24u);
    for (std::size_t i = 0; i < gray.size(); ++i) {
        EXPECT_EQ(image.rgba[4 * i], gray[i]);
        EXPECT_EQ(image.rgba[4 * i + 1], gray[i]);
        EXPECT_EQ(image.rgba[4 * i + 2], gray[i]);
        EXPECT_EQ(image.rgba[4 * i + 3], 255);
    }
}

TEST(ReadImage, ReadsSharedPngAndJpeg) {
    ZRASTER_REQUIRE_SHARED_DATA();
    const ImageRGBA8 png =
        read_image_rgba8(test::shared_data("meshes/gltf/BoxTextured/CesiumLogoFlat.png"));
    EXPECT_EQ(png.width, 211);
    EXPECT_EQ(png.height, 211);
    EXPECT_EQ(png.rgba.size(), 211u * 211u * 4u);
    const ImageRGBA8 jpg = read_image_rgba8(test::shared_data("meshes/obj/spider/SpiderTex.jpg"));
    EXPECT_EQ(jpg.width, 249);
    EXPECT_EQ(jpg.height, 250);
}

TEST(ReadImage, ErrorsNameTheFile) {
    const auto dir = test::temp_dir("io-read-bad");
    test::expect_input_error([&] { read_image_rgba8(dir / "none.png"); }, dir / "none.png",
                             "file not found");
    test::expect_input_error([&] { read_image_rgba8(dir); }, dir, "not a regular file");
    test::write_bytes(dir / "empty.png", "");
    test::expect_input_error([&] { read_image_rgba8(dir / "empty.png"); }, dir / "empty.png",
                             "empty file");
    test::write_bytes(dir / "junk.png", "this is not an image at all");
    test::expect_input_error([&] { read_image_rgba8(dir / "junk.png"); }, dir / "junk.png",
                             "cannot decode image: ");
}

}  // namespace
}  // namespace zraster
