// The slow path of float parsing (see obj_numbers.hpp): what the inline fast path cannot decide.
#include "io/obj_numbers.hpp"

#include <charconv>
#include <cstdlib>
#include <optional>
#include <system_error>

namespace zraster::io::obj {

namespace {

// A number too large or too small for a float: strtof rounds it to infinity or to zero (or a
// denormal) correctly, as from_chars would if it returned a value.
std::optional<float> out_of_range_value(const char* s, const char* end) {
    char buffer[128];
    const std::size_t n = static_cast<std::size_t>(end - s);
    if (n >= sizeof buffer) return std::nullopt;
    std::memcpy(buffer, s, n);
    buffer[n] = '\0';
    return std::strtof(buffer, nullptr);
}

}  // namespace

bool parse_float_slowly(const char*& q, const char* e, float& out) {
    const char* s = q;
    bool negative = false;
    if (*s == '-' || *s == '+') {
        negative = *s == '-';
        if (++s == e) return false;
    }
    const char c = *s;
    if (!((c >= '0' && c <= '9') || c == '.' || c == 'n' || c == 'N' || c == 'i' || c == 'I'))
        return false;
    float value = 0.0f;
    const auto [ptr, ec] = std::from_chars(s, e, value);
    if (ec == std::errc::result_out_of_range) {
        const std::optional<float> v = out_of_range_value(s, ptr);
        if (!v) return false;
        value = *v;
    } else if (ec != std::errc()) {
        return false;
    }
    if (ptr != e && !is_blank(*ptr)) return false;
    out = negative ? -value : value;
    q = ptr;
    return true;
}

}  // namespace zraster::io::obj
