// The few compiler-specific spellings the public headers use, each with a portable fallback.
#pragma once
#include <cmath>

// Forces inlining where a call would cost more than the work (results returned through memory
// in a per-triangle loop). Falls back to plain `inline`.
#if defined(__GNUC__) || defined(__clang__)
#define ZRASTER_FORCE_INLINE [[gnu::always_inline]] inline
#elif defined(_MSC_VER)
#define ZRASTER_FORCE_INLINE __forceinline
#else
#define ZRASTER_FORCE_INLINE inline
#endif

namespace zraster {

// Rounds to the nearest integer, ties to even (the current rounding mode, which zraster never
// changes): one cvtsd2si on x86-64. The builtin lets GCC and Clang inline it whatever
// -fmath-errno says; std::lrint is the same function elsewhere.
inline long round_to_long(double x) {
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_lrint(x);
#else
    return std::lrint(x);
#endif
}

}  // namespace zraster
