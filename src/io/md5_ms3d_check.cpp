#include "io/md5_ms3d_check.hpp"

#include <zraster/error.hpp>

#include <charconv>
#include <cstring>
#include <optional>
#include <sstream>
#include <vector>

namespace zraster::io {

namespace {

// A whole number of 0 or more, or nothing.
std::optional<std::uint64_t> count_word(const std::string& word) {
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (ec != std::errc() || end != word.data() + word.size()) return std::nullopt;
    return value;
}

}  // namespace

void check_md5_mesh(std::string_view text, const std::string& file) {
    const auto refuse = [&](std::size_t line, const std::string& cause) {
        return InputError(file, "malformed MD5 file: line " + std::to_string(line) + ": " + cause);
    };
    struct Vert {
        std::uint64_t start, count;
        std::size_t line;
    };
    std::uint64_t verts = 0, weights = 0;
    std::vector<Vert> vert_weights;
    bool in_mesh = false;
    std::size_t number = 0;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::istringstream words{std::string(text.substr(at, end - at))};
        at = end + 1;
        ++number;
        std::string keyword;
        if (!(words >> keyword)) continue;
        if (keyword == "mesh") {
            in_mesh = true;
            verts = weights = 0;
            vert_weights.clear();
        } else if (!in_mesh) {
            continue;
        } else if (keyword == "numverts" || keyword == "numweights") {
            std::string n;
            words >> n;
            (keyword == "numverts" ? verts : weights) = count_word(n).value_or(0);
        } else if (keyword == "vert") {
            // vert INDEX ( U V ) START COUNT
            std::string index, open, u, v, close, start, count;
            words >> index >> open >> u >> v >> close >> start >> count;
            const auto s = count_word(start), c = count_word(count);
            if (s && c) vert_weights.push_back({*s, *c, number});
        } else if (keyword == "tri") {
            std::string index, a, b, c;
            words >> index >> a >> b >> c;
            for (const std::string* corner : {&a, &b, &c}) {
                const auto vertex = count_word(*corner);
                if (!vertex || *vertex >= verts)
                    throw refuse(number, "triangle index '" + corner->substr(0, 32) +
                                             "' is not one of the mesh's " + std::to_string(verts) +
                                             " vertices");
            }
        } else if (keyword == "}") {
            for (const Vert& v : vert_weights)
                if (v.start > weights || v.count > weights - v.start)
                    throw refuse(v.line, "a vertex's weights " + std::to_string(v.start) + ".." +
                                             std::to_string(v.start + v.count) +
                                             " are past the mesh's " + std::to_string(weights) +
                                             " weights");
            in_mesh = false;
        }
    }
}

void check_ms3d(std::string_view bytes, const std::string& file) {
    // "MS3D000000", a version (4 bytes), the vertex count (2), 15 bytes a vertex, the triangle
    // count (2), 70 bytes a triangle: flags (2), then the three vertex indices (2 each).
    constexpr std::size_t kHeader = 14, kVertex = 15, kTriangle = 70;
    const auto u16 = [&](std::size_t at) {
        return static_cast<std::uint16_t>(static_cast<unsigned char>(bytes[at]) |
                                          static_cast<unsigned char>(bytes[at + 1]) << 8);
    };
    if (bytes.size() < kHeader + 2 || bytes.substr(0, 10) != "MS3D000000") return;
    const std::uint16_t vertices = u16(kHeader);
    const std::size_t triangles_at = kHeader + 2 + std::size_t{vertices} * kVertex;
    if (bytes.size() < triangles_at + 2) return;  // (the importer says the file is short)
    const std::uint16_t triangles = u16(triangles_at);
    if (bytes.size() < triangles_at + 2 + std::size_t{triangles} * kTriangle)
        throw InputError(file, "truncated or malformed MS3D file: it declares " +
                                   std::to_string(triangles) + " triangles of " +
                                   std::to_string(kTriangle) + " bytes, more than the file holds");
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::size_t record = triangles_at + 2 + t * kTriangle;
        for (int k = 0; k < 3; ++k) {
            const std::uint16_t index = u16(record + 2 + 2 * std::size_t(k));
            if (index >= vertices)
                throw InputError(file, "malformed MS3D file: triangle " + std::to_string(t) +
                                           " names vertex " + std::to_string(index) +
                                           ", the file has " + std::to_string(vertices) +
                                           " vertices");
        }
    }
}

}  // namespace zraster::io
