// The line parser (see obj_chunk_parser.hpp). Each statement is read as Assimp 5.2's OBJ importer
// reads it, found by feeding it small files: the first character picks the statement, and lines
// it would read in a way the Assimp path does not agree with are left to that path.
#include "io/obj_chunk_parser.hpp"

#include <zraster/mesh.hpp>

#include "io/obj_number_token.hpp"
#include "io/obj_numbers.hpp"
#include "io/obj_scan.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>

namespace zraster::io::obj {

namespace {

// The numbers of a v, vt or vn statement up to the end of the line or a '#'. Returns how many
// (at most max), or -1 if a token is not a number or there are more than max.
int parse_floats(const char* q, const char* e, float* out, int max) {
    int count = 0;
    while (true) {
        while (is_blank(*q)) ++q;
        if (q == e || *q == '#') return count;
        if (count == max || !parse_float(q, e, out[count])) return -1;
        ++count;
    }
}

// The first word of a v, vt or vn statement that is not a number at all ("1e5x", "1.#INF"), which
// Assimp would read a prefix of; empty when every word is one (a count or a form the reader
// leaves to Assimp) or the line holds a control character (Assimp breaks lines at a lone CR).
[[gnu::noinline]] std::string_view first_non_number(const char* q, const char* e) {
    if (has_control(q, e)) return {};
    while (true) {
        q = skip_blanks(q, e);
        if (q == e || *q == '#') return {};
        const char* word = q;
        q = skip_word(q, e);
        const std::string_view w(word, static_cast<std::size_t>(q - word));
        if (!is_number_word(w)) return w;
    }
}

// How many words a v, vt or vn statement has before a comment when every one is a number, else
// -1 (or when the line holds a control character).
[[gnu::noinline]] int number_words(const char* q, const char* e) {
    if (has_control(q, e)) return -1;
    int words = 0;
    while (true) {
        q = skip_blanks(q, e);
        if (q == e || *q == '#') return words;
        const char* word = q;
        q = skip_word(q, e);
        if (!is_number_word(std::string_view(word, static_cast<std::size_t>(q - word)))) return -1;
        ++words;
    }
}

// The same for a face corner (v, v/vt, v//vn, v/vt/vn, or a form left to Assimp): the first
// part between slashes that is not a whole number ("1x", "1.5"). A word starting with '#' is a
// comment Assimp refuses its own way.
[[gnu::noinline]] std::string_view non_number_index(const char* q, const char* e) {
    if (has_control(q, e) || *q == '#') return {};
    const std::string_view word(q, static_cast<std::size_t>(skip_word(q, e) - q));
    std::size_t at = 0;
    while (at <= word.size()) {
        const std::size_t slash = std::min(word.find('/', at), word.size());
        const std::string_view part = word.substr(at, slash - at);
        if (!part.empty() && !is_index_word(part)) return part;
        at = slash + 1;
    }
    return {};
}

// Assimp keeps at most 0x7fff corners in a face (AI_MAX_FACE_INDICES) and refuses the scene in
// its validation otherwise.
constexpr std::size_t kMaxFaceCorners = 0x7fff;

[[gnu::noinline]] std::string too_many_corners(std::size_t corners) {
    return "a face of " + std::to_string(corners) + " corners; at most " +
           std::to_string(kMaxFaceCorners);
}

class ChunkParser {
  public:
    explicit ChunkParser(Chunk& chunk) : c_(chunk) {}

    // The parsers rely on the byte at a line's end `e` being readable and not part of any
    // token: it is the line's '\n', the '\r' before it, or the zero padding after the file.
    void run() {
        const char* p = c_.begin;
        std::uint32_t line = 0;
        while (p < c_.end) {
            const char* newline = static_cast<const char*>(
                std::memchr(p, '\n', static_cast<std::size_t>(c_.end - p)));
            ++c_.lines;
            const char* e = newline != nullptr ? newline : c_.end;
            const char* next = newline != nullptr ? newline + 1 : c_.end;
            if (e > p && e[-1] == '\r') --e;
            if (!parse_line(p, e, line)) return;
            p = next;
            ++line;
        }
    }

  private:
    bool leave(std::uint32_t line, std::string what) {
        c_.problem = Problem{false, line, std::move(what)};
        return false;
    }
    bool error(std::uint32_t line, std::string what) {
        c_.problem = Problem{true, line, std::move(what)};
        return false;
    }
    [[gnu::noinline]] bool skip(const char* p, const char* e, std::uint32_t line) {
        return !has_control(p, e) || leave(line, "control character in the line");
    }

    bool parse_line(const char* p, const char* e, std::uint32_t line) {
        if (p == e) return true;
        // Assimp joins a line ending in '\' with the next one.
        const char* last = e;
        while (last > p && is_blank(last[-1])) --last;
        if (last > p && last[-1] == '\\') return leave(line, "line continuation ('\\')");

        const char* second = p + 1;
        const bool keyword_alone = second == e || is_blank(*second);
        switch (*p) {
            case 'v':
                if (keyword_alone) return vertex(second, e, line);
                if (*second == 't' || *second == 'n') {
                    if (second + 1 != e && !is_blank(second[1]))
                        return leave(line, "unknown statement starting with 'v" +
                                               std::string(1, *second) + "'");
                    return *second == 't' ? uv(second + 1, e, line) : normal(second + 1, e, line);
                }
                return skip(p, e, line);  // vp and the like: ignored by Assimp too
            case 'f':
            case 'l':
            case 'p':
                if (!keyword_alone)
                    return leave(line, "unknown statement read as a face by Assimp");
                return face(*p, second, e, line);
            case 'o':
                if (!keyword_alone) return leave(line, "unknown statement read as 'o' by Assimp");
                return object(second, e, line);
            case 'g':
                if (!keyword_alone) return leave(line, "unknown statement read as 'g' by Assimp");
                return group(second, e, line);
            case 'u': {
                const char* word_end = skip_word(p, e);
                if (std::string_view(p, word_end - p) != "usemtl") return skip(p, e, line);
                return use_material(word_end, e, line);
            }
            case 'm': {
                const char* word_end = skip_word(p, e);
                if (std::string_view(p, word_end - p) != "mtllib") return skip(p, e, line);
                return library(word_end, e, line);
            }
            case 'c': {
                const char* word_end = skip_word(p, e);
                if (std::string_view(p, word_end - p) == "cstype")
                    return leave(line, "curves and surfaces (cstype)");
                return skip(p, e, line);
            }
            case ' ':
            case '\t': {
                // Ignored by Assimp, but a material library named there would be looked for by
                // the library check of the Assimp path: leave such a file to that path.
                const char* word = skip_blanks(p, e);
                if (std::string_view(word, skip_word(word, e) - word) == "mtllib")
                    return leave(line, "indented mtllib");
                return skip(p, e, line);
            }
            default:
                return skip(p, e, line);
        }
    }

    // The statements of almost every line (v, vt, vn, f) are inlined into the line loop, and
    // the rare ones (o, g, usemtl, mtllib, ignored lines) kept out of it. GCC's own choice
    // depends on the size of the whole translation unit; this layout runs the fewest
    // instructions (callgrind, nefertiti.obj).
    [[gnu::always_inline]] bool vertex(const char* q, const char* e, std::uint32_t line) {
        float v[7];
        const int n = parse_floats(q, e, v, 7);
        if (n == 0) return true;  // "v" alone: Assimp adds nothing either
        if (n == 4) {
            // Homogeneous coordinates, divided as Assimp divides them.
            if (v[3] == 0.0f) return leave(line, "vertex with w = 0");
            v[0] = v[0] / v[3];
            v[1] = v[1] / v[3];
            v[2] = v[2] / v[3];
        } else if (n != 3 && n != 6) {  // 6: with a colour, which zraster does not use
            if (n < 0)
                if (const std::string_view w = first_non_number(q, e); !w.empty())
                    return error(line, not_a_number(w));
            // (Assimp reads the next line's numbers into a short vertex, or fails far away.)
            if (n >= 0 && n < 3)
                return error(line, "a vertex of " + std::to_string(n) +
                                       (n == 1 ? " number" : " numbers") + "; x y z are needed");
            // (Assimp misreads these as well, and blames a vertex index.)
            if (n >= 0)
                return error(line, "a vertex of " + std::to_string(n) +
                                       " numbers; a vertex is x y z, x y z w or x y z r g b");
            // (More than 7 numbers, or numbers this reader does not take: the Assimp path's
            // scan tells them apart.)
            return leave(line, "vertex coordinate that is not a plain number");
        }
        if (n == 6 && !c_.color_outside_line)
            for (int k = 3; k < 6; ++k)
                if (!(v[k] >= 0.0f && v[k] <= 1.0f)) {
                    c_.color_outside_line = line;
                    std::copy(v + 3, v + 6, c_.color_outside);
                    break;
                }
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            c_.non_finite_positions.emplace_back(static_cast<std::uint32_t>(positions_), line);
        // Three push_backs inline, where insert's range path is a call.
        c_.positions.push_back(v[0]);
        c_.positions.push_back(v[1]);
        c_.positions.push_back(v[2]);
        ++positions_;
        return true;
    }

    [[gnu::always_inline]] bool uv(const char* q, const char* e, std::uint32_t line) {
        float t[3];
        const int n = parse_floats(q, e, t, 3);
        if (n != 2 && n != 3) {
            if (n < 0)
                if (const std::string_view w = first_non_number(q, e); !w.empty())
                    return error(line, not_a_number(w));
            return leave(line, "texture coordinate that is not 2 or 3 numbers");
        }
        // Assimp reads a non-finite texture coordinate as 0.
        c_.uvs.push_back(std::isfinite(t[0]) ? t[0] : 0.0f);
        c_.uvs.push_back(1.0f - (std::isfinite(t[1]) ? t[1] : 0.0f));
        ++uvs_;
        return true;
    }

    [[gnu::always_inline]] bool normal(const char* q, const char* e, std::uint32_t line) {
        float n[3];
        if (const int count = parse_floats(q, e, n, 3); count != 3) {
            if (count < 0)
                if (const std::string_view w = first_non_number(q, e); !w.empty())
                    return error(line, not_a_number(w));
            // Assimp read the first three of more, and failed on fewer far away.
            if (count >= 0)
                return error(line, "a normal of " + std::to_string(count) +
                                       (count == 1 ? " number" : " numbers") +
                                       "; a normal is x y z");
            if (const int words = number_words(q, e); words > 3)
                return error(
                    line, "a normal of " + std::to_string(words) + " numbers; a normal is x y z");
            return leave(line, "normal that is not 3 numbers");
        }
        // Exactly as convert_mesh's copy_normals: normalised in double, usable when finite
        // with a finite, non-zero length.
        const glm::dvec3 d(n[0], n[1], n[2]);
        const double length = glm::length(d);
        if (std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]) &&
            std::isfinite(length) && length > 0.0) {
            const glm::vec3 unit(d / length);
            c_.normals.insert(c_.normals.end(), {unit.x, unit.y, unit.z});
        } else {
            c_.normals.insert(c_.normals.end(), 3, std::nanf(""));
        }
        ++normals_;
        return true;
    }

    // f, l or p: corners v, v/vt, v//vn or v/vt/vn, all of one form.
    [[gnu::always_inline]] bool face(char keyword, const char* q, const char* e,
                                     std::uint32_t line) {
        const std::size_t first = c_.corner_v.size();
        int form = -1;  // kHasUv | kHasNormal, the same for every corner
        std::size_t corners = 0;
        while (true) {
            while (is_blank(*q)) ++q;
            if (q == e) break;
            const char* corner_start = q;
            std::int32_t index[3] = {0, 0, 0};
            int this_form = 0;
            IndexParse parsed = parse_index(q, index[0]);
            if (parsed == IndexParse::Ok && *q == '/') {
                ++q;
                if (*q == '/') {
                    ++q;
                    parsed = parse_index(q, index[2]);
                    this_form = kHasNormal;
                } else {
                    parsed = parse_index(q, index[1]);
                    this_form = kHasUv;
                    if (parsed == IndexParse::Ok && *q == '/') {
                        ++q;
                        parsed = parse_index(q, index[2]);
                        this_form = kHasUv | kHasNormal;
                    }
                }
            }
            if (parsed == IndexParse::Zero) {
                if (const std::string_view w = non_number_index(corner_start, e); !w.empty())
                    return error(line, not_a_number(w));  // "0x10"
                return error(line, "invalid face index 0 (OBJ indices start at 1)");
            }
            if (parsed == IndexParse::Bad || (q != e && !is_blank(*q))) {
                if (const std::string_view w = non_number_index(corner_start, e); !w.empty())
                    return error(line, not_a_number(w));
                return leave(line, "face element that is not v, v/vt, v//vn or v/vt/vn");
            }
            if (form < 0) form = this_form;
            if (this_form != form) return leave(line, "face whose corners have different forms");
            // (Past 0x7fff a face is refused below; lines and points are left to Assimp.)
            if (++corners > 0xFFFF && keyword != 'f')
                return leave(line, "line or point element with more than 65535 corners");
            c_.corner_v.push_back(encode_index(index[0], positions_));
            if (form & kHasUv) {
                if (c_.corner_t.size() + 1 < c_.corner_v.size())
                    c_.corner_t.resize(c_.corner_v.size() - 1);
                c_.corner_t.push_back(encode_index(index[1], uvs_));
            }
            if (form & kHasNormal) {
                if (c_.corner_n.size() + 1 < c_.corner_v.size())
                    c_.corner_n.resize(c_.corner_v.size() - 1);
                c_.corner_n.push_back(encode_index(index[2], normals_));
            }
        }
        if (corners == 0) return true;  // an empty face: Assimp ignores it
        const auto kind = keyword == 'f' ? kPolygon : keyword == 'l' ? kLineElement : kPointElement;
        if (kind == kPolygon && corners > kMaxFaceCorners)
            return error(line, too_many_corners(corners));
        if (kind == kPolygon && corners < 3)  // (Assimp's validation fails in its own terms)
            return error(line, "a face of " + std::to_string(corners) +
                                   (corners == 1 ? " corner" : " corners") +
                                   "; a face needs at least 3");
        if (kind == kPolygon && corners > 4)
            return leave(line, "polygon with " + std::to_string(corners) +
                                   " corners (Assimp triangulates those by ear clipping)");
        if (kind != kPolygon && form != 0)
            return leave(line, "line or point element with texture or normal indices");
        if (kind == kLineElement && corners < 2) return leave(line, "line element with one vertex");
        if ((form & kHasUv) && uvs_ == 0 && !c_.uv_slot_without_uvs) c_.uv_slot_without_uvs = line;
        c_.faces.push_back(Face{line, static_cast<std::uint32_t>(first),
                                static_cast<std::uint16_t>(corners),
                                static_cast<std::uint8_t>(kind), static_cast<std::uint8_t>(form)});
        return true;
    }

    [[gnu::noinline]] void add_event(EventKind kind, std::uint32_t line, std::string text) {
        c_.events.push_back(
            Event{kind, static_cast<std::uint32_t>(c_.faces.size()), line, std::move(text)});
    }

    // `o`: the first word of the rest of the line.
    [[gnu::noinline]] bool object(const char* q, const char* e, std::uint32_t line) {
        if (has_control(q, e)) return leave(line, "control character in the line");
        const char* name = skip_blanks(q, e);
        const char* name_end = skip_word(name, e);
        if (name_end != name) add_event(EventKind::Object, line, std::string(name, name_end));
        return true;
    }

    // `g`: the whole rest of the line.
    [[gnu::noinline]] bool group(const char* q, const char* e, std::uint32_t line) {
        if (has_control(q, e)) return leave(line, "control character in the line");
        const char* name = skip_blanks(q, e);
        add_event(EventKind::Group, line, std::string(name, e));  // trailing blanks included
        return true;
    }

    [[gnu::noinline]] bool use_material(const char* q, const char* e, std::uint32_t line) {
        if (has_control(q, e)) return leave(line, "control character in the line");
        const char* name = skip_blanks(q, e);
        const char* name_end = e;
        while (name_end > name && is_blank(name_end[-1])) --name_end;
        if (name_end != name) add_event(EventKind::Material, line, std::string(name, name_end));
        return true;
    }

    [[gnu::noinline]] bool library(const char* q, const char* e, std::uint32_t line) {
        if (has_control(q, e)) return leave(line, "control character in the line");
        const char* name = skip_blanks(q, e);
        if (name == e) return true;
        // Assimp keeps trailing blanks in the name and joins the OBJ's directory and an absolute
        // name; the library check of the Assimp path does neither.
        if (is_blank(e[-1])) return leave(line, "blanks after the material library name");
        if (*name == '/') return leave(line, "absolute material library path");
        add_event(EventKind::Library, line, std::string(name, e));
        return true;
    }

    Chunk& c_;
    std::size_t positions_ = 0, uvs_ = 0, normals_ = 0;  // read so far
};

}  // namespace

std::vector<Chunk> parse_chunks(const char* data, std::size_t size) {
    const std::vector<ByteRange> ranges = line_aligned_chunks(data, size);
    std::vector<Chunk> chunks(ranges.size());
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        chunks[k].begin = ranges[k].begin;
        chunks[k].end = ranges[k].end;
    }
    tbb::parallel_for(std::size_t{0}, chunks.size(),
                      [&](std::size_t k) { ChunkParser(chunks[k]).run(); });
    return chunks;
}

}  // namespace zraster::io::obj
