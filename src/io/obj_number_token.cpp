// See obj_number_token.hpp.
#include "io/obj_number_token.hpp"

#include "io/text_util.hpp"

#include <algorithm>
#include <cctype>

namespace zraster::io {

namespace {

bool digit(char c) {
    return c >= '0' && c <= '9';
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == y;
           });
}

}  // namespace

bool is_number_word(std::string_view w) {
    if (!w.empty() && (w.front() == '+' || w.front() == '-')) w.remove_prefix(1);
    if (equals_ignoring_case(w, "nan") || equals_ignoring_case(w, "inf") ||
        equals_ignoring_case(w, "infinity"))
        return true;
    std::size_t at = 0, digits = 0;
    for (; at < w.size() && digit(w[at]); ++at) ++digits;
    if (at < w.size() && w[at] == '.')
        for (++at; at < w.size() && digit(w[at]); ++at) ++digits;
    if (digits == 0) return false;
    if (at < w.size() && (w[at] == 'e' || w[at] == 'E')) {
        ++at;
        if (at < w.size() && (w[at] == '+' || w[at] == '-')) ++at;
        if (at == w.size() || !digit(w[at])) return false;
        while (at < w.size() && digit(w[at])) ++at;
    }
    return at == w.size();
}

bool is_index_word(std::string_view w) {
    if (!w.empty() && (w.front() == '+' || w.front() == '-')) w.remove_prefix(1);
    return !w.empty() && std::all_of(w.begin(), w.end(), digit);
}

std::string quoted_word(std::string_view word) {
    std::string shown = one_line(word.substr(0, 40));
    if (word.size() > 40) shown += "...";
    return shown;
}

std::string not_a_number(std::string_view word) {
    return "'" + quoted_word(word) + "' is not a number";
}

}  // namespace zraster::io
