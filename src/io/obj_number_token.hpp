// Whether a word of an OBJ or MTL line is a number at all. Assimp reads the numeric prefix of a
// word ("1e5x" as 1e5, "0x10" as 0, "1,5" as 1, "1.#INF" as 1) and drops the rest without a word;
// zraster refuses such a word, in its own reader and before Assimp reads a file it is left, with
// the same message.
#pragma once
#include <string>
#include <string_view>

namespace zraster::io {

// A coordinate or material value: an optional sign, digits with an optional point (at least one
// digit), an optional exponent; or nan, inf, infinity in any case. (".5" is one; Assimp's OBJ
// reader does not read it, so the Assimp path's scan refuses it: obj_index_scan.cpp.)
bool is_number_word(std::string_view word);

// A face index: an optional sign and digits, however many (range is checked separately).
bool is_index_word(std::string_view word);

// A word of a file as a message quotes it: cut to 40 characters ("..." after) and made printable.
std::string quoted_word(std::string_view word);

// "'WORD' is not a number", the word as quoted_word shows it.
std::string not_a_number(std::string_view word);

}  // namespace zraster::io
