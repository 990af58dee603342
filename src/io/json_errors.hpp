// nlohmann::json's exceptions as one line in a user's terms, for the messages of every JSON file
// zraster reads (glTF, cells files, PVS files, --views-json): where, and what is wrong, without
// the library's "[json.exception...]" prefix or the raw bytes it quotes.
#pragma once
#include <nlohmann/json.hpp>

#include <string>

namespace zraster::io {

// "line 1, column 31: unexpected end of input; expected ..." for a syntax error; "a number too
// large for a double ('1e400')" for a number that overflows; the library's text, cleaned, for
// anything else.
std::string json_error_text(const nlohmann::json::exception& e);

}  // namespace zraster::io
