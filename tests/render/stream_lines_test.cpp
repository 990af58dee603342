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

}  // namespace
}  // namespace zraster::detail
