// See mtl_for_assimp.hpp.
#include "io/mtl_for_assimp.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace zraster::io {

namespace {

bool mtl_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// The line's words up to a comment.
std::vector<std::string_view> mtl_words(std::string_view line) {
    std::vector<std::string_view> words;
    for (std::size_t at = 0; at < line.size();) {
        while (at < line.size() && mtl_blank(line[at])) ++at;
        std::size_t end = at;
        while (end < line.size() && !mtl_blank(line[end])) ++end;
        if (end == at) break;
        if (line[at] == '#') break;
        words.push_back(line.substr(at, end - at));
        at = end;
    }
    return words;
}

constexpr std::array<std::string_view, 5> kColors = {"Ka", "Kd", "Ks", "Ke", "Tf"};

}  // namespace

bool is_decal_statement(std::string_view line) {
    const std::vector<std::string_view> words = mtl_words(line);
    return !words.empty() && words[0] == "decal";
}

std::optional<std::string> mtl_for_assimp(std::string_view text) {
    std::string out;
    bool changed = false;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        const bool last = end == std::string_view::npos;
        if (last) end = text.size();
        const std::string_view line = text.substr(at, end - at);
        const std::vector<std::string_view> words = mtl_words(line);
        if (!words.empty() && words[0] == "decal") {
            changed = true;  // an empty line in its place
        } else if (words.size() == 2 &&
                   std::find(kColors.begin(), kColors.end(), words[0]) != kColors.end()) {
            changed = true;
            // The line as written (indentation, a comment), the number given twice more.
            const std::size_t after = std::size_t(words[1].data() - line.data()) + words[1].size();
            out.append(line.substr(0, after));
            out.append(" ").append(words[1]).append(" ").append(words[1]);
            out.append(line.substr(after));
        } else {
            out.append(line);
        }
        if (!last) out += '\n';
        at = end + 1;
    }
    if (!changed) return std::nullopt;
    return out;
}

}  // namespace zraster::io
