// A fingerprint of an array of 32-bit words, to notice that data cached from an earlier frame
// (clusters of a mesh: cluster_cache.hpp) no longer matches what the user passes now.
//
// Two sums modulo 2^32 of every word times an odd multiplier that depends on the word's index:
//   low  = sum w_i * (2 k_i + 1),   high = sum (w_i ^ (w_i >> 15)) * ((2 k_i + 1) * 0x9E3779B9)
// with k_i = first_index + i. A change to one word always changes both sums (the multipliers are
// odd, so invertible modulo 2^32); changes that cancel in both are as unlikely as a random 64-bit
// match. It guards against edits, not against an adversary.
//
// Sums do not depend on the order of addition, so hashes of pieces combine into the hash of the
// whole (combine_word_hashes) whatever the pieces: the vertex stage hashes a mesh's positions in
// parallel blocks. Two implementations with identical output: scalar and SIMD (Highway).
#pragma once
#include <cstddef>
#include <cstdint>

namespace zraster::detail {

inline constexpr std::uint32_t kHighMultiplier = 0x9E3779B9u;  // see above

// The hash of `count` 32-bit words at `words` (any type's bytes: indices, float positions), the
// first of which has index first_index.
std::uint64_t hash_words(const void* words, std::size_t count, std::uint64_t first_index);
std::uint64_t hash_words_scalar(const void* words, std::size_t count, std::uint64_t first_index);

// The hash of two disjoint pieces together: each 32-bit sum added on its own.
inline std::uint64_t combine_word_hashes(std::uint64_t a, std::uint64_t b) {
    const auto low = static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(b);
    const auto high = static_cast<std::uint32_t>(a >> 32) + static_cast<std::uint32_t>(b >> 32);
    return (std::uint64_t{high} << 32) | low;
}

}  // namespace zraster::detail
