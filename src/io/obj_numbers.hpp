// The numbers of an OBJ file: coordinates (floats, correctly rounded) and face indices (positive,
// or negative: relative to the values read so far).
//
// These run for every number of the file, so they are inline, and the common cases are read
// eight digits at a time (SWAR: the eight bytes as one little-endian integer), which needs the
// zero padding after the file (obj_scan.hpp). A float the fast path cannot decide is handed to
// std::from_chars, out of line (obj_numbers.cpp). Floats are correctly rounded, where Assimp's
// fast_atof is sometimes one unit in the last place off.
//
// A token ends at a blank or the end of the line: the byte at the line's end is its '\n', the
// '\r' before it, or the zero padding, never part of a token. A '#' starts a comment only at the
// start of a word: "1.#INF" and "3#c" are not numbers (Assimp would read 1 and 3).
#pragma once
#include "io/obj_scan.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>

namespace zraster::io::obj {

inline bool is_digit(char c) {
    return static_cast<unsigned>(static_cast<unsigned char>(c) - '0') <= 9;
}

[[gnu::always_inline]] inline std::uint64_t load8(const char* p) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
}

// How many of the eight bytes are digits, counting from the first. (A byte's additions and
// subtractions only carry into the bytes after it, which are not looked at once it is a
// non-digit.)
[[gnu::always_inline]] inline unsigned leading_digits(std::uint64_t v) {
    const std::uint64_t outside =
        ((v + 0x4646464646464646ull) | (v - 0x3030303030303030ull)) & 0x8080808080808080ull;
    return outside == 0 ? 8 : static_cast<unsigned>(std::countr_zero(outside)) / 8;
}

// The value of the first n (1 to 8) digits: the others are shifted out and zeros (leading
// digits of the number) shifted in, then the usual three multiply-and-shift steps.
[[gnu::always_inline]] inline std::uint32_t digits_value(std::uint64_t v, unsigned n) {
    std::uint64_t d = (v - 0x3030303030303030ull) << (8 * (8 - n));
    d = d * 10 + (d >> 8);
    d = ((d & 0x000000FF000000FFull) * 0x000F424000000064ull +
         ((d >> 16) & 0x000000FF000000FFull) * 0x0000271000000001ull) >>
        32;
    return static_cast<std::uint32_t>(d);
}

inline constexpr std::uint64_t kPowersOf10[] = {1,      10,      100,      1000,     10000,
                                                100000, 1000000, 10000000, 100000000};

// Appends the digits at s to `value`, moving s past them; returns how many there were. The
// value is only meaningful for at most 19 digits.
[[gnu::always_inline]] inline int read_digits(const char*& s, std::uint64_t& value) {
    int count = 0;
    while (true) {
        const std::uint64_t v = load8(s);
        const unsigned n = leading_digits(v);
        if (n == 0) return count;
        value = value * kPowersOf10[n] + digits_value(v, n);
        s += n;
        count += static_cast<int>(n);
        if (n < 8) return count;
    }
}

// Powers of ten that float and double represent exactly.
inline constexpr float kFloatPowers[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                         1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
inline constexpr double kDoublePowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                           1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                           1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// The common case of parse_float, several times faster than from_chars: a plain decimal of at
// most 19 digits whose value is one exact integer times or divided by one exact power of ten.
// In float (integer below 2^24, power at most 10^10) that one operation rounds correctly; in
// double (below 2^53, 10^22) too, and converting that double to float rounds correctly unless
// it lies exactly halfway between two floats, which is left to from_chars. Returns false when
// from_chars has to decide.
[[gnu::always_inline]] inline bool parse_plain_float(const char*& q, const char* e, float& out) {
    const char* s = q;
    bool negative = false;
    if (*s == '-' || *s == '+') {
        negative = *s == '-';
        ++s;
    }
    std::uint64_t digits = 0;
    int count = read_digits(s, digits), exponent = 0;
    if (*s == '.') {
        ++s;
        exponent = -read_digits(s, digits);
        count -= exponent;
    }
    if (count == 0 || count > 19) return false;
    if (*s == 'e' || *s == 'E') {
        ++s;
        bool negative_exponent = false;
        if (*s == '+' || *s == '-') negative_exponent = *s++ == '-';
        if (!is_digit(*s)) return false;
        int written = 0;
        for (; is_digit(*s); ++s) written = std::min(written * 10 + (*s - '0'), 100000);
        exponent += negative_exponent ? -written : written;
    }
    if (s != e && !is_blank(*s)) return false;
    float value = 0.0f;
    if (digits == 0) {
        value = 0.0f;
    } else if (digits <= (std::uint64_t{1} << 24) && exponent >= -10 && exponent <= 10) {
        const auto w = static_cast<float>(digits);
        value = exponent < 0 ? w / kFloatPowers[-exponent] : w * kFloatPowers[exponent];
    } else if (digits <= (std::uint64_t{1} << 53) && exponent >= -22 && exponent <= 22) {
        const auto w = static_cast<double>(digits);
        const double d = exponent < 0 ? w / kDoublePowers[-exponent] : w * kDoublePowers[exponent];
        if (!(d >= 1.1754943508222875e-38 && d <= 3.4028234663852886e+38)) return false;
        if ((std::bit_cast<std::uint64_t>(d) & 0x1FFFFFFF) == 0x10000000) return false;
        value = static_cast<float>(d);
    } else {
        return false;
    }
    out = negative ? -value : value;
    q = s;
    return true;
}

// parse_float when parse_plain_float cannot decide: std::from_chars, and strtof for a value out
// of float's range (rounded to infinity, zero or a denormal).
[[gnu::noinline]] bool parse_float_slowly(const char*& q, const char* e, float& out);

// One number: an optional sign, then what std::from_chars reads (decimal, exponent, nan, inf),
// correctly rounded (".5" included). The token must end at a blank or the end of the line.
[[gnu::always_inline]] inline bool parse_float(const char*& q, const char* e, float& out) {
    return parse_plain_float(q, e, out) || parse_float_slowly(q, e, out);
}

enum class IndexParse { Ok, Zero, Bad };

// A face index: an optional '-', then 1 to 9 digits without a leading zero. (Assimp reads
// indices with atoi and skips as many characters as the value has digits: "+1" or "01" would
// be read twice.)
[[gnu::always_inline]] inline IndexParse parse_index(const char*& q, std::int32_t& out) {
    const bool negative = *q == '-';
    q += negative;
    if (!is_digit(*q)) return IndexParse::Bad;
    if (*q == '0') {
        ++q;
        return is_digit(*q) ? IndexParse::Bad : IndexParse::Zero;
    }
    const std::uint64_t v = load8(q);
    const unsigned n = leading_digits(v);
    std::uint32_t value = digits_value(v, n);
    q += n;
    if (n == 8 && is_digit(*q)) {
        value = value * 10 + static_cast<unsigned>(*q++ - '0');
        if (is_digit(*q)) return IndexParse::Bad;
    }
    out = negative ? -static_cast<std::int32_t>(value) : static_cast<std::int32_t>(value);
    return IndexParse::Ok;
}

// A chunk stores the indices of its faces before it knows how many values the chunks before it
// read. A positive index is stored 0-based (written index - 1, at most 999'999'998); a negative
// (relative) one as -1 - (count before the line in this chunk + index + kRelativeBias), below
// every absolute one, and resolved once the counts are known.
constexpr std::int64_t kRelativeBias = 1'000'000'000;

inline std::int32_t encode_index(std::int32_t written, std::size_t count_before) {
    if (written > 0) return written - 1;
    const std::int64_t relative = static_cast<std::int64_t>(count_before) + written;
    return static_cast<std::int32_t>(-1 - (relative + kRelativeBias));
}

// The global 0-based index of an encoded one, given how many values the chunks before read
// (`prefix`) and the file (`total`); -1 when it is outside [0, total).
inline std::int64_t resolve_index(std::int32_t raw, std::size_t prefix, std::size_t total) {
    std::int64_t index = raw;
    if (raw < 0)
        index = static_cast<std::int64_t>(prefix) + (-1 - std::int64_t{raw}) - kRelativeBias;
    return index >= 0 && index < static_cast<std::int64_t>(total) ? index : -1;
}

}  // namespace zraster::io::obj
