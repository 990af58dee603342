// PNG writers: 8-bit images round-trip through stb_image; 16-bit grayscale is checked with an
// independent decoder (chunk layout, CRCs, zlib via stb, all five PNG filters) and with stb's.
#include <zraster/image_io.hpp>

#include "io/io_test_util.hpp"
#include "support/test_support.hpp"

#include <stb/stb_image.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace zraster {
namespace {

std::uint32_t be32(const std::string& s, std::size_t at) {
    return std::uint32_t{static_cast<std::uint8_t>(s[at])} << 24 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 1])} << 16 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 2])} << 8 |
           std::uint32_t{static_cast<std::uint8_t>(s[at + 3])};
}

std::uint32_t reference_crc32(std::string_view bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (char ch : bytes) {
        crc ^= static_cast<std::uint8_t>(ch);
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

int paeth(int a, int b, int c) {
    const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

struct Gray16 {
    int width = 0, height = 0;
    std::vector<std::uint16_t> pixels;
};

// A minimal decoder for 16-bit grayscale, non-interlaced PNG.
Gray16 decode_gray16(const std::string& png) {
    Gray16 out;
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    std::string idat;
    std::size_t at = 8;
    std::vector<std::string> chunk_types;
    while (at + 12 <= png.size()) {
        const std::uint32_t length = be32(png, at);
        const std::string type = png.substr(at + 4, 4);
        const std::string data = png.substr(at + 8, length);
        EXPECT_EQ(be32(png, at + 8 + length), reference_crc32(png.substr(at + 4, 4 + length)))
            << "bad CRC in " << type;
        chunk_types.push_back(type);
        if (type == "IHDR") {
            out.width = static_cast<int>(be32(data, 0));
            out.height = static_cast<int>(be32(data, 4));
            EXPECT_EQ(data[8], 16);  // bit depth
            EXPECT_EQ(data[9], 0);   // grayscale
            EXPECT_EQ(data[12], 0);  // no interlace
        } else if (type == "IDAT") {
            idat += data;
        }
        at += 12 + length;
    }
    EXPECT_EQ(at, png.size());
    EXPECT_EQ(chunk_types.front(), "IHDR");
    EXPECT_EQ(chunk_types.back(), "IEND");

    int raw_size = 0;
    std::unique_ptr<char, decltype(&std::free)> raw(
        stbi_zlib_decode_malloc(idat.data(), static_cast<int>(idat.size()), &raw_size), &std::free);
    const std::size_t stride = static_cast<std::size_t>(out.width) * 2;
    EXPECT_TRUE(raw);
    EXPECT_EQ(static_cast<std::size_t>(raw_size), (stride + 1) * out.height);
    if (!raw || static_cast<std::size_t>(raw_size) != (stride + 1) * out.height) return out;

    std::vector<std::uint8_t> previous(stride, 0), row(stride);
    for (int y = 0; y < out.height; ++y) {
        const auto* line = reinterpret_cast<const std::uint8_t*>(raw.get()) + y * (stride + 1);
        const int filter = line[0];
        for (std::size_t i = 0; i < stride; ++i) {
            const int a = i >= 2 ? row[i - 2] : 0, b = previous[i],
                      c = i >= 2 ? previous[i - 2] : 0;
            const int predictors[5] = {0, a, b, (a + b) / 2, paeth(a, b, c)};
            EXPECT_LT(filter, 5);
            row[i] = static_cast<std::uint8_t>(line[1 + i] + predictors[filter % 5]);
        }
        for (int x = 0; x < out.width; ++x)
            out.pixels.push_back(static_cast<std::uint16_t>(row[2 * x] << 8 | row[2 * x + 1]));
        previous = row;
    }
    return out;
}

TEST(WritePng8, RoundTripsEveryChannelCount) {
    const auto dir = test::temp_dir("io-png8");
    const int w = 7, h = 5;  // odd sizes catch stride mistakes
    for (int channels = 1; channels <= 4; ++channels) {
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w) * h * channels);
        for (std::size_t i = 0; i < pixels.size(); ++i)
            pixels[i] = static_cast<std::uint8_t>(i * 37 + channels);
        const auto path = dir / ("image" + std::to_string(channels) + ".png");
        write_png8(path, w, h, channels, pixels);

        const std::string file = test::read_bytes(path);
        int rw = 0, rh = 0, rc = 0;
        std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> decoded(
            stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.data()),
                                  static_cast<int>(file.size()), &rw, &rh, &rc, 0),
            &stbi_image_free);
        ASSERT_TRUE(decoded) << stbi_failure_reason();
        EXPECT_EQ(rw, w);
        EXPECT_EQ(rh, h);
        EXPECT_EQ(rc, channels);
        EXPECT_EQ(std::memcmp(decoded.get(), pixels.data(), pixels.size()), 0) << channels;
    }
}

// A full-HD frame like `zraster render` writes: flat background, smooth gradients and noise, so
// that both long matches and literals are exercised across many deflate blocks.
TEST(WritePng8, FullHdImageRoundTripsExactly) {
    const int w = 1920, h = 1080, channels = 3;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w) * h * channels);
    std::uint32_t noise = 12345;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &pixels[(static_cast<std::size_t>(y) * w + x) * channels];
            noise = noise * 1664525u + 1013904223u;
            const bool inside = (x - 960) * (x - 960) + (y - 540) * (y - 540) < 400 * 400;
            p[0] = inside ? static_cast<std::uint8_t>(x / 8) : 32;
            p[1] = inside ? static_cast<std::uint8_t>(y / 5) : 40;
            p[2] = inside && x % 7 == 0 ? static_cast<std::uint8_t>(noise >> 24) : 48;
        }
    }
    const auto path = test::temp_dir("io-png8-hd") / "frame.png";
    write_png8(path, w, h, channels, pixels);

    const std::string file = test::read_bytes(path);
    EXPECT_LT(file.size(), pixels.size() / 4);
    int rw = 0, rh = 0, rc = 0;
    std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> decoded(
        stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(file.data()),
                              static_cast<int>(file.size()), &rw, &rh, &rc, 0),
        &stbi_image_free);
    ASSERT_TRUE(decoded) << stbi_failure_reason();
    ASSERT_EQ(rw, w);
    ASSERT_EQ(rh, h);
    ASSERT_EQ(rc, channels);
    EXPECT_EQ(std::memcmp(decoded.get(), pixels.data(), pixels.size()), 0);
}

TEST(WritePng16Gray, FullHdDepthRoundTripsExactly) {
    const int w = 1920, h = 1080;
    std::vector<std::uint16_t> pixels(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            pixels[static_cast<std::size_t>(y) * w + x] =
                x > 300 && x < 1500 ? static_cast<std::uint16_t>(20000 + x * 13 + y * 7) : 0xFFFF;
    const auto path = test::temp_dir("io-png16-hd") / "depth.png";
    write_png16_gray(path, w, h, pixels);
    const Gray16 decoded = decode_gray16(test::read_bytes(path));
    EXPECT_EQ(decoded.width, w);
    EXPECT_EQ(decoded.height, h);
    EXPECT_TRUE(decoded.pixels == pixels);
}

TEST(WritePng8, RejectsBadSizes) {
    const auto path = test::temp_dir("io-png8-bad") / "x.png";
    std::vector<std::uint8_t> pixels(12);
    EXPECT_THROW(write_png8(path, 0, 4, 3, pixels), std::invalid_argument);
    EXPECT_THROW(write_png8(path, 2, -2, 3, pixels), std::invalid_argument);
    EXPECT_THROW(write_png8(path, 2, 2, 5, pixels), std::invalid_argument);
    EXPECT_THROW(write_png8(path, 2, 2, 0, pixels), std::invalid_argument);
    EXPECT_THROW(write_png8(path, 2, 2, 4, pixels), std::invalid_argument);  // needs 16
    EXPECT_NO_THROW(write_png8(path, 2, 2, 3, pixels));
}

TEST(WritePng16Gray, DecodesToTheSameSamples) {
    const auto dir = test::temp_dir("io-png16");
    const int w = 13, h = 9;
    std::vector<std::uint16_t> pixels(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)  // both bytes vary, extremes included
            pixels[y * w + x] = static_cast<std::uint16_t>((x * 5171 + y * 40009) & 0xFFFF);
    pixels[0] = 0;
    pixels[1] = 0xFFFF;
    pixels[2] = 0x0100;  // high byte only: catches byte-order mistakes
    const auto path = dir / "depth.png";
    write_png16_gray(path, w, h, pixels);
    const std::string png = test::read_bytes(path);

    const Gray16 decoded = decode_gray16(png);
    EXPECT_EQ(decoded.width, w);
    EXPECT_EQ(decoded.height, h);
    EXPECT_EQ(decoded.pixels, pixels);

    // stb's own PNG decoder agrees.
    int rw = 0, rh = 0, rc = 0;
    std::unique_ptr<stbi_us, decltype(&stbi_image_free)> stb(
        stbi_load_16_from_memory(reinterpret_cast<const stbi_uc*>(png.data()),
                                 static_cast<int>(png.size()), &rw, &rh, &rc, 1),
        &stbi_image_free);
    ASSERT_TRUE(stb) << stbi_failure_reason();
    EXPECT_EQ(rc, 1);
    EXPECT_EQ(std::vector<std::uint16_t>(stb.get(), stb.get() + w * h), pixels);
}

TEST(WritePng16Gray, CompressesSmoothImages) {
    const auto path = test::temp_dir("io-png16-size") / "ramp.png";
    const int w = 256, h = 256;
    std::vector<std::uint16_t> pixels(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) pixels[y * w + x] = static_cast<std::uint16_t>(x * 256 + y);
    write_png16_gray(path, w, h, pixels);
    EXPECT_LT(std::filesystem::file_size(path), pixels.size() * 2 / 4);
    EXPECT_EQ(decode_gray16(test::read_bytes(path)).pixels, pixels);
}

TEST(WritePng16Gray, RejectsBadSizes) {
    const auto path = test::temp_dir("io-png16-bad") / "x.png";
    std::vector<std::uint16_t> pixels(6);
    EXPECT_THROW(write_png16_gray(path, 0, 6, pixels), std::invalid_argument);
    EXPECT_THROW(write_png16_gray(path, 2, 2, pixels), std::invalid_argument);
    EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace zraster
