// See obj_index_scan.hpp.
#include "io/obj_index_scan.hpp"

#include <zraster/error.hpp>

#include "io/obj_number_token.hpp"
#include "io/triangulation_budget.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace zraster::io {

namespace {

enum Kind { kVertex = 0, kUv = 1, kNormal = 2 };

constexpr std::array<const char*, 3> kWhat = {"vertex", "texture coordinate", "normal"};
constexpr std::array<const char*, 3> kValues = {"vertices", "texture coordinates", "normals"};

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// The blank-separated words of `line` into `out` (reused: this runs once per line).
void words(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    std::size_t at = 0;
    while (at < line.size()) {
        while (at < line.size() && is_blank(line[at])) ++at;
        std::size_t end = at;
        while (end < line.size() && !is_blank(line[end])) ++end;
        if (end > at) out.push_back(line.substr(at, end - at));
        at = end;
    }
}

// An optional '-' and digits without a leading zero, as the reader takes an index. Past 10^15
// the value stays 10^15: out of range either way, and the message quotes the written digits.
std::optional<std::int64_t> plain_index(std::string_view text) {
    const bool negative = text.starts_with('-');
    if (negative) text.remove_prefix(1);
    if (text.empty() || text[0] == '0') return std::nullopt;
    constexpr std::int64_t kCap = 1'000'000'000'000'000;
    std::int64_t value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = std::min(kCap, value * 10 + (c - '0'));
    }
    return negative ? -value : value;
}

struct Corner {
    std::optional<std::int64_t> index[3];
    std::string_view text[3];
};

// v, v/vt, v//vn or v/vt/vn; nullopt for anything else.
std::optional<Corner> corner(std::string_view token) {
    Corner c;
    std::array<std::string_view, 3> parts;
    std::size_t n = 0;
    while (true) {
        const std::size_t slash = token.find('/');
        if (n == 3) return std::nullopt;
        parts[n++] = token.substr(0, slash);
        if (slash == std::string_view::npos) break;
        token.remove_prefix(slash + 1);
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (parts[k].empty() && k == 1 && n == 3) continue;  // v//vn
        if (!(c.index[k] = plain_index(parts[k]))) return std::nullopt;
        c.text[k] = parts[k];
    }
    return c;
}

// Control characters other than tab: Assimp breaks lines at a lone CR, so such a line's words
// are not judged (zraster's reader leaves it to Assimp too).
bool has_control(std::string_view line) {
    return std::any_of(line.begin(), line.end(),
                       [](char c) { return static_cast<unsigned char>(c) < 0x20 && c != '\t'; });
}

// The words of a v, vt or vn statement before a comment (a word starting with '#') that are not
// numbers, and the parts of face, line and point corners that are not whole numbers, refused as
// zraster's reader refuses them (Assimp would read their numeric prefix). Statements start in
// the line's first column, as both readers take them.
void check_numbers(std::string_view line, const std::string& file, std::size_t number,
                   std::string* warning) {
    const auto refuse = [&](std::string_view w) {
        throw InputError(file, "line " + std::to_string(number) + ": " + not_a_number(w));
    };
    const auto word_end = [&](std::size_t at) {
        while (at < line.size() && !is_blank(line[at])) ++at;
        return at;
    };
    const std::string_view keyword = line.substr(0, word_end(0));
    const bool values = keyword == "v" || keyword == "vt" || keyword == "vn";
    const bool corners = keyword == "f" || keyword == "l" || keyword == "p";
    if ((!values && !corners) || has_control(line)) return;
    std::size_t numbers = 0;
    std::string_view colors[3];  // a vertex's 4th to 6th numbers
    for (std::size_t at = keyword.size(); at <= line.size();) {
        while (at < line.size() && is_blank(line[at])) ++at;
        if (at == line.size() || line[at] == '#') {
            // As zraster's reader: Assimp read the first three of more.
            if (keyword == "v" && numbers == 6 && warning != nullptr && warning->empty()) {
                float rgb[3];
                for (int k = 0; k < 3; ++k)
                    rgb[k] = std::strtof(std::string(colors[k]).c_str(), nullptr);
                for (const float c : rgb)
                    if (!(c >= 0.0f && c <= 1.0f)) {
                        *warning = vertex_color_outside_warning(number, rgb);
                        break;
                    }
            }
            if (keyword == "vn" && numbers != 3)
                throw InputError(file, "line " + std::to_string(number) + ": a normal of " +
                                           std::to_string(numbers) +
                                           (numbers == 1 ? " number" : " numbers") +
                                           "; a normal is x y z");
            return;
        }
        ++numbers;
        const std::size_t end = word_end(at);
        if (values) {
            const std::string_view w = line.substr(at, end - at);
            if (!is_number_word(w)) refuse(w);
            // Assimp's OBJ reader does not count a word starting with a point as a number (it
            // misreads the line); zraster's own reader takes it, this file needs Assimp's.
            if (w.starts_with('.') || w.starts_with("-.") || w.starts_with("+."))
                throw InputError(file, "line " + std::to_string(number) + ": '" +
                                           std::string(w.substr(0, 40)) +
                                           "' starts with a point, which the importer this "
                                           "file needs does not read as a number (write 0" +
                                           std::string(w.substr(w.find('.'), 40)) + ")");
            if (numbers >= 4 && numbers <= 6) colors[numbers - 4] = w;
        } else {
            const std::string_view w = line.substr(at, end - at);
            for (std::size_t from = 0; from <= w.size();) {
                const std::size_t slash = std::min(w.find('/', from), w.size());
                const std::string_view part = w.substr(from, slash - from);
                if (!part.empty() && !is_index_word(part)) refuse(part);
                from = slash + 1;
            }
        }
        at = end;
    }
}

// A file with line continuations is not scanned for indices, but its faces still count against
// the triangulation budget: a face's corners are the words of its line and the lines it continues
// into.
void count_continued_faces(const std::string& text, const std::filesystem::path& path,
                           const LoadOptions& options) {
    TriangulationBudget triangulation(path, options);
    std::size_t number = 0, face_line = 0;
    std::uint64_t corners = 0;
    bool continued = false;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + at, end - at);
        at = end + 1;
        ++number;
        while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
        const bool continues = line.ends_with('\\');
        if (continues) line.remove_suffix(1);
        std::uint64_t words = 0;
        bool face = false;
        for (std::size_t i = 0; i < line.size();) {
            while (i < line.size() && is_blank(line[i])) ++i;
            if (i == line.size()) break;
            const std::size_t from = i;
            while (i < line.size() && !is_blank(line[i])) ++i;
            if (words++ == 0 && !continued) face = line.substr(from, i - from) == "f";
        }
        if (!continued) {
            face_line = face ? number : 0;
            corners = face ? words - 1 : 0;
        } else if (face_line != 0) {
            corners += words;
        }
        if (!continues && face_line != 0) {
            triangulation.add(corners, "line " + std::to_string(face_line));
            face_line = 0;
        }
        continued = continues;
    }
}

}  // namespace

std::string vertex_color_outside_warning(std::size_t line, const float* rgb) {
    std::ostringstream text;
    text << "line " << line << ": vertex color (" << rgb[0] << ", " << rgb[1] << ", " << rgb[2]
         << ") is outside 0..1; zraster does not use OBJ vertex colors (ignored)";
    return text.str();
}

void check_obj_indices(const std::filesystem::path& path, const LoadOptions& options,
                       std::string* warning) {
    if (warning != nullptr) warning->clear();
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string_view> lines;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + at, end - at);
        while (!line.empty() && is_blank(line.back())) line.remove_suffix(1);
        if (line.ends_with('\\')) {  // continuations: Assimp joins lines its own way
            count_continued_faces(text, path, options);
            return;
        }
        lines.push_back(line);
        at = end + 1;
    }
    const auto keyword = [](std::string_view line) {
        std::size_t at = 0;
        while (at < line.size() && is_blank(line[at])) ++at;
        std::size_t end = at;
        while (end < line.size() && !is_blank(line[end])) ++end;
        return line.substr(at, end - at);
    };
    std::array<std::int64_t, 3> total{};
    for (const std::string_view line : lines) {
        const std::string_view k = keyword(line);
        if (k == "v") ++total[kVertex];
        if (k == "vt") ++total[kUv];
        if (k == "vn") ++total[kNormal];
    }
    std::array<std::int64_t, 3> before{};
    TriangulationBudget triangulation(path, options);
    std::vector<std::string_view> w;
    std::vector<Corner> corners;
    for (std::size_t l = 0; l < lines.size(); ++l) {
        check_numbers(lines[l], path.string(), l + 1, warning);
        words(lines[l], w);
        if (w.empty()) continue;
        const auto refuse = [&](const std::string& cause) {
            throw InputError(path.string(), "line " + std::to_string(l + 1) + ": " + cause);
        };
        // Faces of one or two corners and short vertices, in zraster's reader's words: Assimp
        // fails on them in its own, or reads the next line into the vertex.
        if (w[0] == "v" && w.size() < 4)
            refuse("a vertex of " + std::to_string(w.size() - 1) +
                   (w.size() == 2 ? " number" : " numbers") + "; x y z are needed");
        if (w[0] == "v" && w.size() != 4 && w.size() != 5 && w.size() != 7)
            refuse("a vertex of " + std::to_string(w.size() - 1) +
                   " numbers; a vertex is x y z, x y z w or x y z r g b");
        if (w[0] == "f" && w.size() > 1 && w.size() < 4)  // ("f" alone: ignored by both)
            refuse("a face of " + std::to_string(w.size() - 1) +
                   (w.size() == 2 ? " corner" : " corners") + "; a face needs at least 3");
        if (w[0] == "v") ++before[kVertex];
        if (w[0] == "vt") ++before[kUv];
        if (w[0] == "vn") ++before[kNormal];
        if (w[0] != "f") continue;
        // As zraster's reader refuses it: Assimp's validation would, in its own words.
        if (w.size() - 1 > 0x7fff)
            throw InputError(path.string(), "line " + std::to_string(l + 1) + ": a face of " +
                                                std::to_string(w.size() - 1) +
                                                " corners; at most 32767");
        triangulation.add(w.size() - 1, "line " + std::to_string(l + 1));
        corners.clear();
        for (std::size_t i = 1; i < w.size(); ++i) {
            const std::optional<Corner> c = corner(w[i]);
            if (!c) break;
            corners.push_back(*c);
        }
        if (corners.size() + 1 != w.size()) continue;  // not plain corners: left to Assimp
        // Before the first vt, Assimp reads a texture slot as a normal index: not checked.
        if (before[kUv] == 0 && std::any_of(corners.begin(), corners.end(), [](const Corner& c) {
                return c.index[kUv].has_value();
            }))
            continue;
        for (const Corner& c : corners) {
            for (int kind : {kVertex, kUv, kNormal}) {
                if (!c.index[kind]) continue;
                const std::int64_t i = *c.index[kind];
                if (i > 0 && i <= total[kind]) continue;
                if (i < 0 && -i <= before[kind]) continue;
                const std::string cause =
                    i > 0 ? std::string(kWhat[kind]) + " index out of range (" +
                                std::string(c.text[kind]) + "; the file has " +
                                std::to_string(total[kind]) + " " + kValues[kind] + ")"
                          : std::string(kWhat[kind]) +
                                " index out of range (a negative index before the first " +
                                kWhat[kind] + ")";
                throw InputError(path.string(), "line " + std::to_string(l + 1) + ": " + cause);
            }
        }
    }
}

}  // namespace zraster::io
