// The blend pass's kernels (render/blend_kernels.hpp) against their scalar twins, bit for bit
// on every instruction set: reading fragments out of the visibility kernel's buffers into
// per-pixel slots (full slots spilling to the list), and compositing the slots (depth ties
// ordered by content and ids, pixels past the slots left to the list). Then whole frames with
// more blended layers than a pixel has slots: any submission order, SIMD or not, one image,
// equal to the analytic "over".
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

#include "raster/visibility_kernel.hpp"
#include "render/blend_kernels.hpp"
#include "render/every_simd_target.hpp"

namespace zraster::detail {
namespace {

constexpr int kTile = 64;
constexpr std::size_t kPixels = std::size_t(kTile) * kTile;

void expect_same_slots(const BlendSlots& a, const BlendSlots& b) {
    ASSERT_EQ(a.count, b.count);
    for (std::size_t p = 0; p < kPixels; ++p)
        for (std::uint32_t k = 0; k < std::min(a.count[p], kBlendSlots); ++k) {
            const BlendFragment fa = a.slot(p, k), fb = b.slot(p, k);
            ASSERT_EQ(fa.depth_key, fb.depth_key) << p << " " << k;
            ASSERT_EQ(fa.rgba, fb.rgba);
            ASSERT_EQ(fa.source, fb.source);
            ASSERT_EQ(std::bit_cast<std::uint32_t>(fa.alpha),
                      std::bit_cast<std::uint32_t>(fb.alpha));
        }
    ASSERT_EQ(a.more.size(), b.more.size());
    for (std::size_t i = 0; i < a.more.size(); ++i) {
        EXPECT_EQ(a.more[i].first, b.more[i].first);
        EXPECT_EQ(a.more[i].second.depth_key, b.more[i].second.depth_key);
        EXPECT_EQ(a.more[i].second.rgba, b.more[i].second.rgba);
    }
}

void AppendMatchesScalar() {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto simd = std::make_unique<TileBuffers>(), scalar = std::make_unique<TileBuffers>();
    std::vector<float> opaque(TileBuffers::kPixels);
    BlendSlots simd_slots, scalar_slots;
    simd_slots.start(kPixels);
    std::size_t spilled = 0, appended = 0;
    for (int round = 0; round < 60; ++round) {
        const std::uint32_t id = 1000 + std::uint32_t(round);
        for (std::size_t i = 0; i < TileBuffers::kPixels; ++i) {
            const float r = unit(rng);
            simd->ref[i] = r < 0.6f ? id : r < 0.8f ? id + 1 : kNoTriangle;
            simd->depth[i] = unit(rng);
            simd->color[i] = std::uint32_t(rng());
            opaque[i] = unit(rng);
        }
        if (round % 20 == 0) simd_slots.start(kPixels);  // (slots fill up in between)
        *scalar = *simd;
        scalar_slots = simd_slots;
        for (int y = 0; y < kTile; ++y) {
            // Rows of every width and offset, the whole row most often.
            const int x0 = round % 3 == 0 ? int(rng() % 40) : 0;
            const int width = round % 3 == 0 ? 1 + int(rng() % std::uint32_t(kTile - x0)) : kTile;
            const BlendRow row{tile_index(x0, y), std::size_t(y * kTile + x0), width,         id,
                               unit(rng),         std::uint32_t(round),        round % 2 == 0};
            append_blend_row(row, *simd, opaque.data(), simd_slots);
            append_blend_row_scalar(row, *scalar, opaque.data(), scalar_slots);
        }
        ASSERT_TRUE(std::equal(simd->ref, simd->ref + TileBuffers::kPixels, scalar->ref));
        ASSERT_EQ(0, std::memcmp(simd->depth, scalar->depth, sizeof(simd->depth)));
        expect_same_slots(simd_slots, scalar_slots);
        // Whole rows read out: no pixel of the triangle left.
        if (round % 3 != 0) {
            for (int y = 0; y < kTile; ++y)
                for (int x = 0; x < kTile; ++x) ASSERT_NE(simd->ref[tile_index(x, y)], id);
        }
        spilled = std::max(spilled, simd_slots.more.size());
        appended += std::accumulate(simd_slots.count.begin(), simd_slots.count.end(), 0u);
    }
    EXPECT_GT(spilled, 1000u);  // full slots were met
    EXPECT_GT(appended, 100000u);
}

void CompositeMatchesScalar() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<std::uint32_t> instance(16), primitive(16);
    for (std::uint32_t s = 0; s < 16; ++s) {
        instance[s] = s % 5;
        primitive[s] = 15 - s;
    }
    const CompositingOrder order{instance.data(), primitive.data()};
    BlendSlots slots;
    for (int round = 0; round < 40; ++round) {
        slots.start(kPixels);
        // Few distinct depths in some rounds: ties, ordered by content and ids.
        const std::uint32_t depths = round % 2 == 0 ? 3 : 1u << 30;
        for (std::size_t p = 0; p < kPixels; ++p) {
            const std::uint32_t n = std::uint32_t(rng() % 7);  // up to 6: past the slots too
            for (std::uint32_t k = 0; k < n; ++k)
                slots.add(p,
                          {std::uint32_t(rng() % depths), round % 4 == 0 ? 0.5f : 1e-3f + unit(rng),
                           std::uint32_t(rng()) | 0xff000000u, std::uint32_t(rng() % 16)});
        }
        std::vector<std::uint8_t> simd(kPixels * 4), scalar;
        for (std::uint8_t& b : simd) b = std::uint8_t(rng());
        scalar = simd;
        const std::vector<std::uint8_t> before = simd;
        for (int y = 0; y < kTile; ++y) {
            const int width = round % 3 == 0 ? 1 + int(rng() % kTile) : kTile;
            composite_blend_row(slots, std::size_t(y * kTile), width, order,
                                simd.data() + std::size_t(y * kTile) * 4);
            composite_blend_row_scalar(slots, std::size_t(y * kTile), width, order,
                                       scalar.data() + std::size_t(y * kTile) * 4);
        }
        ASSERT_EQ(simd, scalar) << "round " << round;
        // Alpha bytes and pixels without fragments or past the slots are untouched.
        for (std::size_t p = 0; p < kPixels; ++p) {
            EXPECT_EQ(simd[p * 4 + 3], before[p * 4 + 3]);
            if (slots.count[p] == 0 || slots.count[p] > kBlendSlots) {
                EXPECT_TRUE(std::equal(&simd[p * 4], &simd[p * 4 + 4], &before[p * 4]));
            }
        }
    }
}

TEST(BlendKernels, AppendMatchesScalar) {
    test::on_every_simd_target(AppendMatchesScalar);
}

TEST(BlendKernels, CompositeMatchesScalar) {
    test::on_every_simd_target(CompositeMatchesScalar);
}

}  // namespace
}  // namespace zraster::detail
