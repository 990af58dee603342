// See json_errors.hpp.
#include "io/json_errors.hpp"

namespace zraster::io {
namespace {

// The library quotes the input ("last read: '...'"), which may be any bytes: one printable line.
std::string printable(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) >= 0x80 || static_cast<unsigned char>(c) < 0x20) c = '?';
    return text;
}

// The text after nlohmann's "[json.exception.KIND.ID] " prefix.
std::string without_prefix(const std::string& what) {
    const std::size_t end = what.find("] ");
    return what.starts_with("[json.exception.") && end != std::string::npos ? what.substr(end + 2)
                                                                            : what;
}

}  // namespace

std::string json_error_text(const nlohmann::json::exception& e) {
    const std::string what = e.what();
    if (const auto* parse = dynamic_cast<const nlohmann::json::parse_error*>(&e)) {
        // "[json.exception.parse_error.101] parse error at line 1, column 31: syntax error while
        // parsing value - unexpected end of input; expected ..." as "line 1, column 31:
        // unexpected end of input; expected ...".
        const std::size_t at = what.find(" at line ");
        const std::size_t colon = at == std::string::npos ? at : what.find(": ", at);
        const std::size_t dash = what.find(" - ");
        const std::string where = at != std::string::npos && colon != std::string::npos
                                      ? what.substr(at + 4, colon - at - 4)
                                      : "byte " + std::to_string(parse->byte);
        return printable(where + ": " + (dash != std::string::npos ? what.substr(dash + 3) : what));
    }
    // out_of_range.406: "number overflow parsing '1e400'".
    const std::size_t overflow = what.find("number overflow parsing ");
    if (e.id == 406 && overflow != std::string::npos)
        return printable("a number too large for a double (" +
                         what.substr(overflow + std::string("number overflow parsing ").size()) +
                         ")");
    return printable(without_prefix(what));
}

}  // namespace zraster::io
