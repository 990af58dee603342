// stream_lines (non-temporal copies of whole cache lines) on every instruction set: the lines
// arrive exactly, and nothing outside them is written.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>
#include <vector>

#include "render/frame.hpp"
#include "render/stream_lines.hpp"

namespace zraster::detail {
namespace {

TEST(StreamLines, CopiesWholeLinesExactlyOnEveryTarget) {
    int targets = 0;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        SCOPED_TRACE(hwy::TargetName(target));
        for (const std::size_t lines : {std::size_t{1}, std::size_t{2}, std::size_t{7}}) {
            std::vector<std::byte> from_storage(lines * kCacheLine + kCacheLine);
            std::vector<std::byte> to_storage((lines + 2) * kCacheLine + kCacheLine);
            std::byte* from = align_to_cache_line(from_storage.data());
            std::byte* to = align_to_cache_line(to_storage.data()) + kCacheLine;
            for (std::size_t i = 0; i < lines * kCacheLine; ++i)
                from[i] = std::byte(std::uint8_t(i * 7 + lines));
            for (std::size_t i = 0; i < (lines + 2) * kCacheLine; ++i)
                (to - kCacheLine)[i] = std::byte{0xee};
            stream_lines(to, from, lines);
            stream_fence();
            for (std::size_t i = 0; i < lines * kCacheLine; ++i) ASSERT_EQ(to[i], from[i]) << i;
            for (std::size_t i = 0; i < kCacheLine; ++i) {
                EXPECT_EQ((to - kCacheLine)[i], std::byte{0xee});        // the line before
                EXPECT_EQ(to[lines * kCacheLine + i], std::byte{0xee});  // and after
            }
        }
        ++targets;
    }
    hwy::SetSupportedTargetsForTest(0);
    EXPECT_GE(targets, 2);  // at least a SIMD target and the scalar one
}

// stream_copy at every alignment of source and destination and lengths around whole lines:
// the bytes arrive exactly, and the bytes just before and after are untouched.
TEST(StreamLines, CopiesAnyRangeExactlyOnEveryTarget) {
    int targets = 0;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        SCOPED_TRACE(hwy::TargetName(target));
        std::vector<std::byte> from_storage(8 * kCacheLine), to_storage(8 * kCacheLine);
        std::byte* const from_line = align_to_cache_line(from_storage.data());
        std::byte* const to_line = align_to_cache_line(to_storage.data());
        for (const std::size_t to_offset : {0, 1, 4, 16, 60, 63}) {
            for (const std::size_t from_offset : {0, 3, 32}) {
                for (const std::size_t bytes : {0, 1, 5, 63, 64, 65, 128, 200, 256, 300}) {
                    std::byte* to = to_line + kCacheLine + to_offset;
                    const std::byte* from = from_line + from_offset;
                    for (std::size_t i = 0; i < 7 * kCacheLine; ++i) {
                        from_line[i] = std::byte(std::uint8_t(i * 7 + bytes));
                        to_line[i] = std::byte{0xee};
                    }
                    stream_copy(to, from, bytes);
                    stream_fence();
                    SCOPED_TRACE(testing::Message() << "to +" << to_offset << ", from +"
                                                    << from_offset << ", " << bytes << " bytes");
                    for (std::size_t i = 0; i < bytes; ++i) ASSERT_EQ(to[i], from[i]) << i;
                    for (std::byte* b = to_line; b < to; ++b) ASSERT_EQ(*b, std::byte{0xee});
                    for (std::byte* b = to + bytes; b < to_line + 7 * kCacheLine; ++b)
                        ASSERT_EQ(*b, std::byte{0xee});
                }
            }
        }
        ++targets;
    }
    hwy::SetSupportedTargetsForTest(0);
    EXPECT_GE(targets, 2);
}

}  // namespace
}  // namespace zraster::detail
