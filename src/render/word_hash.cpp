// See word_hash.hpp. Highway's foreach_target re-includes this file once per instruction set;
// the scalar reference and the dispatcher are compiled once (HWY_ONCE).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/word_hash.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <cstring>

#include "render/word_hash.hpp"

HWY_BEFORE_NAMESPACE();
namespace zraster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

std::uint64_t HashWords(const void* data, std::size_t count, std::uint64_t first_index) {
    const auto* words = static_cast<const std::uint32_t*>(data);
    const hn::ScalableTag<std::uint32_t> du;
    const std::size_t lanes = hn::Lanes(du);
    // Multipliers 2k + 1 of the lanes and their products with kHighMultiplier, both linear in
    // k: stepped by additions (wrapping modulo 2^32 as k does).
    auto odd = hn::Add(hn::Set(du, static_cast<std::uint32_t>(2 * first_index + 1)),
                       hn::ShiftLeft<1>(hn::Iota(du, 0)));
    auto odd_high = hn::Mul(odd, hn::Set(du, kHighMultiplier));
    const auto step = hn::Set(du, static_cast<std::uint32_t>(2 * lanes));
    const auto step_high = hn::Set(du, static_cast<std::uint32_t>(2 * lanes) * kHighMultiplier);
    auto low = hn::Zero(du), high = hn::Zero(du);
    std::size_t i = 0;
    for (; i + lanes <= count; i += lanes) {
        const auto w = hn::LoadU(du, words + i);
        low = hn::Add(low, hn::Mul(w, odd));
        high = hn::Add(high, hn::Mul(hn::Xor(w, hn::ShiftRight<15>(w)), odd_high));
        odd = hn::Add(odd, step);
        odd_high = hn::Add(odd_high, step_high);
    }
    const std::uint64_t head = (std::uint64_t{hn::GetLane(hn::SumOfLanes(du, high))} << 32) |
                               std::uint64_t{hn::GetLane(hn::SumOfLanes(du, low))};
    return combine_word_hashes(head, hash_words_scalar(words + i, count - i, first_index + i));
}

}  // namespace zraster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace zraster::detail {

HWY_EXPORT(HashWords);

std::uint64_t hash_words(const void* words, std::size_t count, std::uint64_t first_index) {
    return HWY_DYNAMIC_DISPATCH(HashWords)(words, count, first_index);
}

std::uint64_t hash_words_scalar(const void* words, std::size_t count, std::uint64_t first_index) {
    std::uint32_t low = 0, high = 0;
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t w;
        std::memcpy(&w, static_cast<const unsigned char*>(words) + 4 * i, 4);
        const auto odd = static_cast<std::uint32_t>(2 * (first_index + i) + 1);
        low += w * odd;
        high += (w ^ (w >> 15)) * (odd * kHighMultiplier);
    }
    return (std::uint64_t{high} << 32) | low;
}

}  // namespace zraster::detail
#endif  // HWY_ONCE
