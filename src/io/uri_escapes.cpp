#include "io/uri_escapes.hpp"

#include <system_error>

namespace zraster::io {

namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

bool exists_as_named(const std::filesystem::path& file) {
    std::error_code ec;
    return std::filesystem::symlink_status(file, ec).type() !=
           std::filesystem::file_type::not_found;
}

}  // namespace

std::optional<std::string> percent_decoded(std::string_view uri) {
    if (uri.find('%') == std::string_view::npos) return std::nullopt;
    std::string out;
    bool decoded = false;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex_digit(uri[i + 1]) >= 0 &&
            hex_digit(uri[i + 2]) >= 0) {
            const char c = static_cast<char>(hex_digit(uri[i + 1]) * 16 + hex_digit(uri[i + 2]));
            // A NUL would end the name where the file system reads it ("ok.png%00../x" opened
            // ok.png): such a URI is taken as written.
            if (c == '\0') return std::nullopt;
            out += c;
            i += 2;
            decoded = true;
        } else {
            out += uri[i];
        }
    }
    if (!decoded) return std::nullopt;
    return out;
}

std::filesystem::path uri_file(const std::filesystem::path& folder, const std::string& uri) {
    const std::filesystem::path literal = folder / uri;
    if (exists_as_named(literal)) return literal;
    if (const std::optional<std::string> decoded = percent_decoded(uri)) return folder / *decoded;
    return literal;
}

}  // namespace zraster::io
