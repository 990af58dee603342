// Copies whole cache lines with non-temporal stores: they write memory without reading each
// line in first, as ordinary stores that miss the cache must (the bin writer: see
// Frame::bin_run_offsets). Highway picks the instruction set at run time.
#pragma once
#include <cstddef>

namespace zraster::detail {

inline constexpr std::size_t kCacheLine = 64;

// Copies `lines` cache lines from `from` to `to`, both aligned to kCacheLine.
void stream_lines(std::byte* to, const std::byte* from, std::size_t lines);

// Copies `bytes` bytes, any alignment: the cache lines of `to` it fills whole with
// non-temporal stores, the others (at most one at each end) as memcpy does.
void stream_copy(void* to, const void* from, std::size_t bytes);

// Orders the streamed stores before later stores (and before another thread, synchronized
// after this, reads them).
void stream_fence();

}  // namespace zraster::detail
