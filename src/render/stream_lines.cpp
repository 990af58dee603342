// See stream_lines.hpp. Highway's foreach_target re-includes this file once per instruction
// set; the dispatcher is compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/stream_lines.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "render/stream_lines.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void StreamCopy(std::byte* to, const std::byte* from, std::size_t bytes) {
    const hn::CappedTag<std::uint8_t, kCacheLine> d;
    const std::size_t lanes = hn::Lanes(d);
    // Lines `to` covers only in part are copied as usual: streaming part of a line costs more.
    const auto address = reinterpret_cast<std::uintptr_t>(to);
    const std::size_t head = std::min(bytes, (kCacheLine - address % kCacheLine) % kCacheLine);
    const std::size_t body = (bytes - head) / kCacheLine * kCacheLine;
    std::memcpy(to, from, head);
    auto* out = reinterpret_cast<std::uint8_t*>(to + head);
    const auto* in = reinterpret_cast<const std::uint8_t*>(from + head);
    for (std::size_t i = 0; i < body; i += lanes) hn::Stream(hn::LoadU(d, in + i), d, out + i);
    std::memcpy(to + head + body, from + head + body, bytes - head - body);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(StreamCopy);

void stream_copy(void* to, const void* from, std::size_t bytes) {
    HWY_DYNAMIC_DISPATCH(StreamCopy)
    (static_cast<std::byte*>(to), static_cast<const std::byte*>(from), bytes);
}

void stream_lines(std::byte* to, const std::byte* from, std::size_t lines) {
    stream_copy(to, from, lines * kCacheLine);  // (aligned: no partial lines)
}

void stream_fence() {
    hwy::FlushStream();
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
