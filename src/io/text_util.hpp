// Small string helpers for messages and line-based formats.
#pragma once
#include <zraster/error.hpp>

#include <string>
#include <string_view>

namespace zraster::io {

inline std::string_view trim(std::string_view s) {
    const auto space = [](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
    };
    while (!s.empty() && space(s.front())) s.remove_prefix(1);
    while (!s.empty() && space(s.back())) s.remove_suffix(1);
    return s;
}

// Messages are one line ("FILE: cause"): Assimp's may span several, and stb_image's can quote
// bytes of the file ("\x89\n\x1a\n PNG chunk not known"): other control characters become '?'.
inline std::string one_line(std::string_view s) {
    // (Warnings quote the input too: a name of megabytes is cut as InputError cuts a cause.)
    constexpr std::size_t kMaxBytes = 4096;
    if (s.size() > kMaxBytes) return one_line(InputError("", std::string(s)).cause());
    std::string out;
    bool space = false;
    for (char c : trim(s)) {
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
        if ((c >= 0 && c < ' ') || c == 0x7f) c = '?';
        if (c == ' ' && space) continue;
        space = c == ' ';
        out.push_back(c);
    }
    return out;
}

// Text whose first non-blank character opens a JSON object. Assimp asks every importer about a
// file whose extension it does not know, and its glTF importers read any such text as glTF: a
// glTF named x.json is loaded, so the glTF checks apply to it as to x.gltf.
inline bool starts_json_object(std::string_view bytes) {
    const std::string_view t = trim(bytes);
    return !t.empty() && t.front() == '{';
}

}  // namespace zraster::io
