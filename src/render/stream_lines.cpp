// See stream_lines.hpp. Highway's foreach_target re-includes this file once per instruction
// set; the dispatcher is compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/stream_lines.cpp"
#include <hwy/cache_control.h>
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cstdint>

#include "render/stream_lines.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void StreamLines(std::byte* to, const std::byte* from, std::size_t lines) {
    const hn::CappedTag<std::uint8_t, kCacheLine> d;
    const std::size_t lanes = hn::Lanes(d);
    auto* out = reinterpret_cast<std::uint8_t*>(to);
    const auto* in = reinterpret_cast<const std::uint8_t*>(from);
    for (std::size_t i = 0; i < lines * kCacheLine; i += lanes)
        hn::Stream(hn::Load(d, in + i), d, out + i);
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(StreamLines);

void stream_lines(std::byte* to, const std::byte* from, std::size_t lines) {
    HWY_DYNAMIC_DISPATCH(StreamLines)(to, from, lines);
}

void stream_fence() {
    hwy::FlushStream();
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
