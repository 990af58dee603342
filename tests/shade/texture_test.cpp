#include <zraster/texture.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace zraster {
namespace {

Texture random_texture(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> byte(0, 255);
    std::vector<std::uint8_t> rgba(std::size_t(w) * std::size_t(h) * 4);
    for (auto& b : rgba) b = std::uint8_t(byte(rng));
    return Texture(w, h, rgba);
}

void expect_vec_near(const glm::vec4& a, const glm::vec4& b, float tolerance) {
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[k], b[k], tolerance) << "component " << k;
}

TEST(Texture, MipChainSizes) {
    const Texture big = random_texture(256, 256, 1);
    ASSERT_EQ(big.levels(), 9);  // 256, 128, ..., 1
    for (int l = 0; l < 9; ++l) {
        EXPECT_EQ(big.level_width(l), 256 >> l);
        EXPECT_EQ(big.level_height(l), 256 >> l);
    }
    const Texture odd = random_texture(5, 3, 2);  // 5x3, 2x1, 1x1
    ASSERT_EQ(odd.levels(), 3);
    EXPECT_EQ(odd.width(), 5);
    EXPECT_EQ(odd.height(), 3);
    EXPECT_EQ(std::pair(odd.level_width(1), odd.level_height(1)), std::pair(2, 1));
    EXPECT_EQ(std::pair(odd.level_width(2), odd.level_height(2)), std::pair(1, 1));
    const Texture one = random_texture(1, 1, 3);
    EXPECT_EQ(one.levels(), 1);
    const Texture wide = random_texture(8, 2, 4);  // 8x2, 4x1, 2x1, 1x1
    ASSERT_EQ(wide.levels(), 4);
    EXPECT_EQ(std::pair(wide.level_width(2), wide.level_height(2)), std::pair(2, 1));
}

TEST(Texture, RejectsBadSizesAndShortBuffers) {
    const std::vector<std::uint8_t> bytes(4 * 4 * 4, 0);
    EXPECT_THROW(Texture(0, 4, bytes), std::invalid_argument);
    EXPECT_THROW(Texture(4, -1, bytes), std::invalid_argument);
    EXPECT_THROW(Texture(4, 5, bytes), std::invalid_argument);
    EXPECT_NO_THROW(Texture(4, 4, bytes));
}

TEST(Texture, MipLevelsAreBoxFilterAverages) {
    // One-texel black and white cells average to mid gray at level 1 and at every level below.
    const Texture checker = make_checkerboard_texture(64, 1, {0, 0, 0, 255}, {255, 255, 255, 255});
    EXPECT_EQ(checker.texel(0, 0, 0), glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(checker.texel(0, 1, 0), glm::vec4(1, 1, 1, 1));
    for (int level = 1; level < checker.levels(); ++level)
        for (int y = 0; y < checker.level_height(level); ++y)
            for (int x = 0; x < checker.level_width(level); ++x)
                expect_vec_near(checker.texel(level, x, y), {0.5f, 0.5f, 0.5f, 1.0f},
                                0.5f / 255 + 1e-6f);
    // Two-texel cells stay a (one-texel) checkerboard at level 1.
    const Texture coarse = make_checkerboard_texture(8, 2, {0, 0, 0, 255}, {255, 255, 255, 255});
    EXPECT_EQ(coarse.texel(1, 0, 0), glm::vec4(0, 0, 0, 1));
    EXPECT_EQ(coarse.texel(1, 1, 0), glm::vec4(1, 1, 1, 1));
    // Each texel of level 1 is the mean of its 2x2 block.
    const Texture t = random_texture(16, 8, 5);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            const glm::vec4 mean =
                (t.texel(0, 2 * x, 2 * y) + t.texel(0, 2 * x + 1, 2 * y) +
                 t.texel(0, 2 * x, 2 * y + 1) + t.texel(0, 2 * x + 1, 2 * y + 1)) /
                4.0f;
            expect_vec_near(t.texel(1, x, y), mean, 0.5f / 255 + 1e-6f);
        }
}

TEST(Texture, OddSizesKeepTheMean) {
    // A 3x1 row halves to one texel holding the mean of all three.
    const std::vector<std::uint8_t> row = {0, 30, 255, 255, 90, 60, 0, 255, 255, 0, 45, 255};
    const Texture t(3, 1, row);
    ASSERT_EQ(t.levels(), 2);
    expect_vec_near(t.texel(1, 0, 0), glm::vec4(115, 30, 100, 255) / 255.0f, 1e-6f);
    // Every level of an odd-sized texture keeps the image mean (up to the rounding to bytes).
    for (const auto& [w, h] : {std::pair{5, 3}, {7, 7}, {9, 2}, {13, 6}}) {
        const Texture r = random_texture(w, h, unsigned(w * 31 + h));
        auto mean = [&r](int level) {
            glm::vec4 sum(0.0f);
            for (int y = 0; y < r.level_height(level); ++y)
                for (int x = 0; x < r.level_width(level); ++x) sum += r.texel(level, x, y);
            return sum / float(r.level_width(level) * r.level_height(level));
        };
        for (int level = 1; level < r.levels(); ++level)
            expect_vec_near(mean(level), mean(0), float(level) * 0.5f / 255 + 1e-5f);
    }
}

TEST(Texture, VZeroIsTheFirstRow) {
    std::vector<std::uint8_t> rgba(4 * 4 * 4, 0);
    for (int x = 0; x < 4; ++x) rgba[std::size_t(x) * 4] = 255;  // first row red
    const Texture t(4, 4, rgba);
    EXPECT_EQ(t.sample_nearest({0.6f, 0.1f}), glm::vec4(1, 0, 0, 0));
    EXPECT_EQ(t.sample_nearest({0.6f, 0.9f}), glm::vec4(0, 0, 0, 0));
}

TEST(Texture, NearestPicksTheTexelContainingUv) {
    const Texture t = random_texture(8, 4, 6);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            const glm::vec4 expected = t.texel(0, x, y);
            EXPECT_EQ(t.sample_nearest({(x + 0.1f) / 8, (y + 0.9f) / 4}), expected);
            EXPECT_EQ(t.sample_nearest({(x + 0.5f) / 8 - 3.0f, (y + 0.5f) / 4 + 2.0f}), expected);
        }
}

TEST(Texture, BilinearReproducesTexelsAtTheirCenters) {
    const Texture t = random_texture(8, 4, 7);
    for (int level = 0; level < t.levels(); ++level) {
        const int w = t.level_width(level), h = t.level_height(level);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const glm::vec2 center((x + 0.5f) / float(w), (y + 0.5f) / float(h));
                EXPECT_EQ(t.sample_bilinear(center, level), t.texel(level, x, y));
            }
    }
}

TEST(Texture, BilinearMidpointIsTheAverageOfTwoTexels) {
    const Texture t = random_texture(8, 4, 8);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 7; ++x) {
            const glm::vec4 a = t.texel(0, x, y), b = t.texel(0, x + 1, y),
                            c = t.texel(0, x, y + 1);
            expect_vec_near(t.sample_bilinear({(x + 1.0f) / 8, (y + 0.5f) / 4}), (a + b) / 2.0f,
                            1e-6f);
            if (y < 3)
                expect_vec_near(t.sample_bilinear({(x + 0.5f) / 8, (y + 1.0f) / 4}), (a + c) / 2.0f,
                                1e-6f);
            // A quarter of the way: weights 3/4 and 1/4.
            expect_vec_near(t.sample_bilinear({(x + 0.75f) / 8, (y + 0.5f) / 4}),
                            0.75f * a + 0.25f * b, 1e-6f);
        }
}

TEST(Texture, WrapsByRepetition) {
    const Texture t = random_texture(8, 4, 9);
    // Binary fractions: u + k is exact, so the wrapped samples are bit-identical.
    for (const glm::vec2 uv : {glm::vec2(0.375f, 0.625f), glm::vec2(0.03125f, 0.9375f)})
        for (const glm::vec2 shift : {glm::vec2(1, 0), glm::vec2(-3, 2), glm::vec2(5, -7)}) {
            EXPECT_EQ(t.sample_bilinear(uv + shift), t.sample_bilinear(uv));
            EXPECT_EQ(t.sample_nearest(uv + shift), t.sample_nearest(uv));
            EXPECT_EQ(t.sample_trilinear(uv + shift, 1.5f), t.sample_trilinear(uv, 1.5f));
        }
    // At the edge u = 0 the filter straddles the last and the first column.
    const glm::vec4 last = t.texel(0, 7, 1), first = t.texel(0, 0, 1);
    expect_vec_near(t.sample_bilinear({0.0f, 1.5f / 4}), (last + first) / 2.0f, 1e-6f);
    expect_vec_near(t.sample_bilinear({1.0f, 1.5f / 4}), (last + first) / 2.0f, 1e-6f);
    EXPECT_EQ(t.texel(0, -1, 5), t.texel(0, 7, 1));
    EXPECT_EQ(t.texel(0, 17, -9), t.texel(0, 1, 3));
}

TEST(Texture, TrilinearBlendsTheTwoNearestLevels) {
    const Texture t = random_texture(32, 32, 10);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
    for (int trial = 0; trial < 100; ++trial) {
        const glm::vec2 uv(coordinate(rng), coordinate(rng));
        for (int level = 0; level < t.levels(); ++level)
            EXPECT_EQ(t.sample_trilinear(uv, float(level)), t.sample_bilinear(uv, level));
        for (int level = 0; level + 1 < t.levels(); ++level)
            expect_vec_near(
                t.sample_trilinear(uv, level + 0.5f),
                (t.sample_bilinear(uv, level) + t.sample_bilinear(uv, level + 1)) / 2.0f, 1e-6f);
        // Outside the chain the level of detail is clamped.
        EXPECT_EQ(t.sample_trilinear(uv, -3.0f), t.sample_bilinear(uv, 0));
        EXPECT_EQ(t.sample_trilinear(uv, -INFINITY), t.sample_bilinear(uv, 0));
        EXPECT_EQ(t.sample_trilinear(uv, 40.0f), t.sample_bilinear(uv, t.levels() - 1));
    }
}

TEST(Texture, LevelOfDetailIsLog2OfTheLongerFootprint) {
    const Texture t = random_texture(256, 64, 12);
    // One texel per pixel in both directions: level 0.
    EXPECT_FLOAT_EQ(t.level_of_detail({1.0f / 256, 0.0f}, {0.0f, 1.0f / 64}), 0.0f);
    // Four texels per pixel: level 2.
    EXPECT_FLOAT_EQ(t.level_of_detail({4.0f / 256, 0.0f}, {0.0f, 4.0f / 64}), 2.0f);
    // Anisotropic: the longer footprint decides (OpenGL's rho = max of the two lengths).
    EXPECT_FLOAT_EQ(t.level_of_detail({1.0f / 256, 0.0f}, {0.0f, 8.0f / 64}), 3.0f);
    // A diagonal footprint of length 2 texels: level 1.
    EXPECT_NEAR(t.level_of_detail({std::sqrt(2.0f) / 256, std::sqrt(2.0f) / 64}, {0.0f, 0.0f}),
                1.0f, 1e-6f);
    // Magnification: negative level of detail.
    EXPECT_FLOAT_EQ(t.level_of_detail({0.5f / 256, 0.0f}, {0.0f, 0.5f / 64}), -1.0f);
}

TEST(Texture, SampleDispatchesOnTheFilter) {
    const Texture t = random_texture(64, 64, 13);
    const glm::vec2 uv(0.3f, 0.7f), dx(4.0f / 64, 0.0f), dy(0.0f, 4.0f / 64);
    EXPECT_EQ(t.sample(uv, dx, dy, TextureFilter::Nearest), t.sample_nearest(uv, 0));
    EXPECT_EQ(t.sample(uv, dx, dy, TextureFilter::Bilinear), t.sample_bilinear(uv, 0));
    EXPECT_EQ(t.sample(uv, dx, dy, TextureFilter::Trilinear), t.sample_trilinear(uv, 2.0f));
    EXPECT_EQ(t.sample(uv, dx * 0.5f, dy * 0.5f, TextureFilter::Trilinear),
              t.sample_bilinear(uv, 1));
}

TEST(Texture, CheckerboardLayout) {
    const glm::u8vec4 a(10, 20, 30, 255), b(200, 100, 50, 128);
    const Texture t = make_checkerboard_texture(4, 3, a, b);
    EXPECT_EQ(t.width(), 12);
    EXPECT_EQ(t.height(), 12);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) {
            const glm::u8vec4 expected = ((x / 3 + y / 3) % 2 == 0) ? a : b;
            expect_vec_near(t.texel(0, x, y), glm::vec4(expected) / 255.0f, 1e-7f);
        }
    EXPECT_THROW(make_checkerboard_texture(0, 4, a, b), std::invalid_argument);
}

}  // namespace
}  // namespace zraster
