#include "io/declared_counts_check.hpp"

#include "io/collada_instances_check.hpp"
#include "io/collada_values_check.hpp"
#include "io/gltf_bounds_check.hpp"
#include "io/lightwave_scene_check.hpp"
#include "io/md5_ms3d_check.hpp"
#include "io/nesting_depth_check.hpp"
#include "io/obj_number_token.hpp"
#include "io/ogre_xml_check.hpp"
#include "io/opengex_check.hpp"
#include "io/text_util.hpp"
#include "io/triangulation_budget.hpp"
#include "io/zip_archive_check.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
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

// The most corners Assimp keeps in a face (AI_MAX_FACE_INDICES).
constexpr std::uint64_t kMaxPlyFaceCorners = 0x7fff;

struct DeclaredElement {
    std::string name;
    std::uint64_t count = 0;
    std::uint64_t min_record_bytes = 1;
};

// The leading digits, as Assimp's strtoul10 reads a count: it stops at the first non-digit, so
// "1099511627-776" declares 1099511627 records (found by fuzz_load_off: Assimp then allocated
// 16 GiB of faces). No leading digit: nullopt, Assimp reads 0 and reports the file itself.
// Saturates instead of wrapping.
std::optional<std::uint64_t> parse_count(const std::string& token) {
    if (token.empty() || token[0] < '0' || token[0] > '9') return std::nullopt;
    std::uint64_t value = 0;
    for (char c : token) {
        if (c < '0' || c > '9') break;
        const std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
        value = value > (UINT64_MAX - digit) / 10 ? UINT64_MAX : value * 10 + digit;
    }
    return value;
}

std::string read_prefix(const std::filesystem::path& path, std::size_t limit) {
    std::ifstream in(path, std::ios::binary);
    std::string text(limit, '\0');
    in.read(text.data(), static_cast<std::streamsize>(limit));
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
}

// body_bytes: what follows the header (PLY) or the whole file (OFF, whose header is tiny).
void check_body(const std::filesystem::path& path, const char* format,
                const std::vector<DeclaredElement>& elements, std::uint64_t body_bytes) {
    std::uint64_t needed = 0;
    for (const DeclaredElement& e : elements) {
        // The last record may lack its trailing separator, hence the one byte of slack.
        const std::uint64_t available = body_bytes + 1 - needed;
        if (e.count > available / e.min_record_bytes) {
            throw InputError(path.string(),
                             std::string("truncated or malformed file: the ") + format +
                                 " header declares " + std::to_string(e.count) + " " + e.name +
                                 " records, more than its " + std::to_string(body_bytes) +
                                 " bytes of data can hold");
        }
        needed += e.count * e.min_record_bytes;
    }
}

std::uint64_t ply_scalar_size(const std::string& type) {
    if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
    if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
    if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
        type == "float32")
        return 4;
    if (type == "double" || type == "float64") return 8;
    return 1;  // unknown: Assimp will complain; stay conservative here
}

struct PlyProperty {
    bool list = false;
    std::uint64_t bytes = 1;       // the scalar, or the list's length
    std::uint64_t item_bytes = 1;  // list items
    std::string name;
    bool item_signed = false, item_float = false;
    bool length_signed = false;  // the list length's type (binary: "int" can hold -3)
    // A face's vertex indices: each checked against the vertex count (Assimp wraps a value past
    // its integer type, 2^32 to 0, and clamps others, without a word).
    bool vertex_indices() const {
        return list && (name == "vertex_indices" || name == "vertex_index");
    }
};

// PLY lists: Assimp resizes a list to its declared length (8 bytes per entry) before reading the
// entries, so one binary length of 0x3ff00000 allocated 8 GiB for a 400-byte file (found by
// fuzz_load_ply); an ASCII "4000000000" would ask for 32 GiB. Walks the records as Assimp does
// (binary: packed; ASCII: one record per line) and refuses a list longer than the rest of the
// file can hold.
void check_ply_lists(const std::filesystem::path& path, std::size_t header_bytes,
                     const std::vector<DeclaredElement>& elements,
                     const std::vector<std::vector<PlyProperty>>& layout, bool ascii,
                     bool big_endian, const LoadOptions& options) {
    bool has_list = false;
    for (const auto& properties : layout)
        for (const PlyProperty& p : properties) has_list |= p.list;
    if (!has_list && !ascii) return;
    std::ifstream in(path, std::ios::binary);
    const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::uint64_t at = std::min<std::uint64_t>(header_bytes, file.size());
    TriangulationBudget triangulation(path, options);
    const std::uint64_t end = file.size();
    const auto refuse = [&](const std::string& element, std::uint64_t length) {
        throw InputError(path.string(), "truncated or malformed file: a PLY " + element +
                                            " record holds a list of " + std::to_string(length) +
                                            " entries, more than the rest of the file can hold");
    };
    // The vertices the faces' indices may name: the "vertex" element's count.
    std::uint64_t vertices = 0;
    bool have_vertices = false;
    for (const DeclaredElement& element : elements)
        if (element.name == "vertex") {
            vertices = element.count;
            have_vertices = true;
        }
    for (std::size_t e = 0; e < elements.size(); ++e) {
        const bool check_indices = have_vertices && elements[e].name == "face";
        const auto refuse_index = [&](std::uint64_t record, const std::string& value) {
            throw InputError(
                path.string(),
                "malformed PLY file: face " + std::to_string(record) + " names vertex " + value +
                    ", but the file has " + std::to_string(vertices) + " vertices" +
                    (vertices > 0 ? " (0 to " + std::to_string(vertices - 1) + ")" : ""));
        };
        // A face's corner count, in the user's terms: Assimp reads a negative one as a huge
        // length (std::bad_alloc) and refuses a face of more than 0x7fff corners in its
        // validation ("Face 0 has too many faces").
        const auto check_corners = [&](std::uint64_t record, const PlyProperty& p, bool negative,
                                       const std::string& written) {
            if (!check_indices || !p.vertex_indices()) return;
            if (negative)
                throw InputError(path.string(),
                                 "malformed PLY file: face " + std::to_string(record) +
                                     " has a negative corner count (" + written + ")");
            const std::uint64_t corners = parse_count(written).value_or(0);
            if (corners > kMaxPlyFaceCorners)
                throw InputError(path.string(), "malformed PLY file: face " +
                                                    std::to_string(record) + " has " + written +
                                                    " corners; at most " +
                                                    std::to_string(kMaxPlyFaceCorners));
            triangulation.add(corners, "face " + std::to_string(record));
        };
        if (layout[e].empty()) continue;  // Assimp skips the records of such an element
        for (std::uint64_t r = 0; r < elements[e].count && at < end; ++r) {
            if (ascii) {
                std::uint64_t line_end = file.find('\n', at);
                if (line_end == std::string::npos) line_end = end;
                std::istringstream words(file.substr(at, line_end - at));
                // Each entry takes at least a digit and a separator of what is left.
                const std::uint64_t available = end - at;
                at = line_end + 1;
                // Assimp reads a number's prefix ("0x" as 0, "1e5x" as 1e5) without a word.
                const auto check_number = [&](const PlyProperty& p, const std::string& word) {
                    if (!is_number_word(word))
                        throw InputError(path.string(), "malformed PLY file: " + elements[e].name +
                                                            " " + std::to_string(r) + "'s " +
                                                            p.name + ": " + not_a_number(word));
                };
                bool complete = true;  // every property read
                for (const PlyProperty& p : layout[e]) {
                    std::string token;
                    if (!(words >> token)) {
                        complete = false;
                        break;
                    }
                    if (!p.list) {
                        check_number(p, token);
                        continue;
                    }
                    // A length that is not digits: Assimp reads "-3" as a huge length.
                    if (token.find_first_not_of("0123456789") != std::string::npos) {
                        if (token.size() > 1 && token[0] == '-' &&
                            token.find_first_not_of("0123456789", 1) == std::string::npos)
                            check_corners(r, p, true, token);
                        throw InputError(path.string(), "malformed PLY file: a " +
                                                            elements[e].name +
                                                            " record's list length '" +
                                                            one_line(token.substr(0, 40)) +
                                                            "' is not a whole number of 0 or more");
                    }
                    const std::uint64_t length = parse_count(token).value_or(0);
                    if (length > available / 2 + 1) refuse(elements[e].name, length);
                    check_corners(r, p, false, token);
                    for (std::uint64_t i = 0; i < length && words >> token; ++i) {
                        if (!check_indices || !p.vertex_indices()) {
                            check_number(p, token);
                            continue;
                        }
                        long long index = -1;
                        const auto [end_of, error] =
                            std::from_chars(token.data(), token.data() + token.size(), index);
                        if (error != std::errc{} || end_of != token.data() + token.size())
                            index = -1;
                        if (index < 0 || std::uint64_t(index) >= vertices) refuse_index(r, token);
                    }
                }
                // A word past the declared properties ("3 0 1 2 5" for a face of one list):
                // Assimp skipped it without a word.
                if (std::string extra; complete && words >> extra)
                    throw InputError(path.string(), "malformed PLY file: " + elements[e].name +
                                                        " " + std::to_string(r) + " has a word '" +
                                                        one_line(extra.substr(0, 40)) +
                                                        "' past its declared properties");
                continue;
            }
            for (const PlyProperty& p : layout[e]) {
                if (p.bytes > 8 || end - at < p.bytes) return;  // truncated: Assimp reports it
                if (!p.list) {
                    at += p.bytes;
                    continue;
                }
                std::uint64_t length = 0;
                for (std::uint64_t b = 0; b < p.bytes; ++b) {
                    const auto byte = static_cast<std::uint8_t>(file[at + b]);
                    const std::uint64_t shift = big_endian ? 8 * (p.bytes - 1 - b) : 8 * b;
                    length |= std::uint64_t{byte} << shift;
                }
                at += p.bytes;
                const std::uint64_t length_sign = std::uint64_t{1} << (8 * p.bytes - 1);
                if (p.length_signed && (length & length_sign) != 0) {
                    check_corners(r, p, true,
                                  std::to_string(static_cast<std::int64_t>(
                                      length | ~(length_sign | (length_sign - 1)))));
                    throw InputError(path.string(), "malformed PLY file: a " + elements[e].name +
                                                        " record's list has a negative length");
                }
                if (length > (end - at) / p.item_bytes) refuse(elements[e].name, length);
                check_corners(r, p, false, std::to_string(length));
                if (check_indices && p.vertex_indices() && !p.item_float && p.item_bytes <= 8)
                    for (std::uint64_t i = 0; i < length; ++i) {
                        std::uint64_t value = 0;
                        for (std::uint64_t b = 0; b < p.item_bytes; ++b) {
                            const auto byte =
                                static_cast<std::uint8_t>(file[at + i * p.item_bytes + b]);
                            const std::uint64_t shift =
                                big_endian ? 8 * (p.item_bytes - 1 - b) : 8 * b;
                            value |= std::uint64_t{byte} << shift;
                        }
                        const std::uint64_t sign = std::uint64_t{1} << (8 * p.item_bytes - 1);
                        const bool negative = p.item_signed && (value & sign) != 0;
                        if (negative || value >= vertices)
                            refuse_index(r, negative ? "a negative index" : std::to_string(value));
                    }
                at += length * p.item_bytes;
            }
        }
    }
}

// GLB (binary glTF): Assimp allocates each chunk's declared length before reading it (a JSON
// chunk claiming 1.9 GB in a 3 KB file, found by fuzz_load_gltf). Chunks must fit in the file,
// and so must the whole length the header declares (0xFFFFFFFF made Assimp answer "no suitable
// reader found").
void check_glb(const std::filesystem::path& path, std::uintmax_t file_size,
               const LoadOptions& options) {
    std::ifstream in(path, std::ios::binary);
    char file_header[12];
    if (!in.read(file_header, 12)) return;
    std::uint64_t declared_size = 0;
    for (int b = 0; b < 4; ++b)
        declared_size |= std::uint64_t{static_cast<std::uint8_t>(file_header[8 + b])} << (8 * b);
    std::uint64_t at = 12;
    std::string json;
    std::optional<std::uint64_t> binary;
    for (int chunk = 0; at + 8 <= file_size; ++chunk) {
        char header[8];
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(header, 8)) return;
        std::uint64_t length = 0;
        for (int b = 0; b < 4; ++b)
            length |= std::uint64_t{static_cast<std::uint8_t>(header[b])} << (8 * b);
        if (length > file_size - at - 8)
            throw InputError(path.string(),
                             "truncated or malformed GLB file: GLB chunk " + std::to_string(chunk) +
                                 " declares " + std::to_string(length) + " bytes, more than the " +
                                 std::to_string(file_size - at - 8) + " left in the file");
        if (chunk == 0 && std::string_view(header + 4, 4) == "JSON") {
            json.resize(static_cast<std::size_t>(length));
            if (!in.read(json.data(), static_cast<std::streamsize>(length))) return;
        } else if (chunk > 0 && std::string_view(header + 4, 4) == std::string_view("BIN\0", 4)) {
            // The specification allows one, right after the JSON chunk; Assimp reads only that
            // one and would take buffer bytes from the wrong place otherwise. (A first chunk that
            // is not JSON is the structure check's to name.)
            if (chunk != 1 || binary)
                throw InputError(path.string(),
                                 "malformed GLB file: a BIN chunk as chunk " +
                                     std::to_string(chunk) +
                                     " (GLB allows one, right after the JSON chunk)");
            binary = length;
        }
        at += 8 + length;
    }
    // The header's length is the whole file's (a shorter one made Assimp read past it and report
    // a face past the vertices).
    if (declared_size != file_size)
        throw InputError(path.string(),
                         "truncated or malformed GLB file: the GLB header declares " +
                             std::to_string(declared_size) + " bytes, the file holds " +
                             std::to_string(file_size) +
                             (declared_size > file_size ? " (truncated?)" : ""));
    check_gltf_bounds(path, json, binary, options);
}

// Binary records hold every scalar and each list's length; ASCII records at least one digit and
// one separator per value.
void check_ply(const std::filesystem::path& path, const std::string& head, std::uintmax_t file_size,
               const LoadOptions& options) {
    std::istringstream lines(head);
    std::string line;
    bool ascii = false;
    bool ended = false;
    std::vector<DeclaredElement> elements;
    std::vector<std::uint64_t> property_bytes;     // per element, binary size
    std::vector<std::uint64_t> property_count;     // per element
    std::vector<std::vector<PlyProperty>> layout;  // per element
    bool big_endian = false;
    // Assimp attaches property lines to an element only while they follow it directly (comments
    // aside); a property after any other line belongs to no element.
    bool in_element = false;
    std::size_t header_bytes = 0;
    while (std::getline(lines, line)) {
        header_bytes += line.size() + 1;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        // Assimp matches "end_header" after spaces and tabs only, followed by white space.
        if (keyword == "end_header") {
            const std::size_t at = line.find_first_not_of(" \t");
            const std::size_t after = at + 10;
            const bool exact =
                line.compare(at, 10, "end_header") == 0 &&
                (after >= line.size() ||
                 std::string_view(" \t\r\f\0", 5).find(line[after]) != std::string_view::npos);
            if (!exact) keyword.clear();
        }
        if (keyword != "property" && keyword != "comment" && keyword != "element")
            in_element = false;
        if (keyword == "format") {
            std::string kind, version;
            words >> kind >> version;
            // The three formats of PLY 1.0 (Assimp took binary_middle_endian and version 2.0).
            if ((kind != "ascii" && kind != "binary_little_endian" &&
                 kind != "binary_big_endian") ||
                version != "1.0")
                throw InputError(path.string(),
                                 "malformed PLY file: 'format " + one_line(kind) + " " +
                                     one_line(version) +
                                     "': the format is ascii, binary_little_endian or "
                                     "binary_big_endian, version 1.0");
            ascii = kind == "ascii";
            big_endian = kind == "binary_big_endian";
        } else if (keyword == "element") {
            std::string name, count;
            words >> name >> count;
            // Digits only: Assimp reads "-1" as 0 and "3abc" as 3, without a word.
            if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos)
                throw InputError(path.string(), "malformed PLY file: element '" + one_line(name) +
                                                    "' declares the count '" + one_line(count) +
                                                    "', not a number of 0 or more");
            elements.push_back({name, parse_count(count).value_or(0), 1});
            property_bytes.push_back(0);
            property_count.push_back(0);
            layout.emplace_back();
            in_element = true;
        } else if (keyword == "property" && in_element) {
            std::string type;
            words >> type;
            PlyProperty property;
            if (type == "list") {
                std::string item;
                words >> type >> item;  // the list's length type, then its items'
                property.list = true;
                property.item_bytes = ply_scalar_size(item);
                property.item_float =
                    item == "float" || item == "float32" || item == "double" || item == "float64";
                // A face's corners are vertex numbers (Assimp truncated a float index 2.5 to 2).
                if (property.item_float && words.peek() != EOF) {
                    std::string name;
                    std::istringstream rest(words.str().substr(std::size_t(words.tellg())));
                    rest >> name;
                    if (name == "vertex_indices" || name == "vertex_index")
                        throw InputError(path.string(),
                                         "malformed PLY file: the list '" + one_line(name) +
                                             "' holds vertex numbers as " + item +
                                             ": they are integers (char, uchar, short, ushort, "
                                             "int, uint)");
                }
                const auto is_signed = [](const std::string& t) {
                    return t == "char" || t == "int8" || t == "short" || t == "int16" ||
                           t == "int" || t == "int32";
                };
                property.item_signed = is_signed(item);
                property.length_signed = is_signed(type);
            }
            words >> property.name;
            property.bytes = ply_scalar_size(type);
            layout.back().push_back(property);
            property_bytes.back() += ply_scalar_size(type);
            property_count.back() += 1;
        } else if (keyword == "end_header") {
            ended = true;
            break;
        }
    }
    // Assimp 5.2.5 reads a header without end_header forever (found by fuzz_load_ply).
    if (!ended)
        throw InputError(path.string(),
                         "truncated or malformed file: no end_header line in the PLY header "
                         "(first 64 KiB)");
    if (header_bytes > file_size) return;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const std::uint64_t bytes = ascii ? 2 * property_count[i] : property_bytes[i];
        elements[i].min_record_bytes = bytes > 0 ? bytes : 1;
    }
    check_body(path, "PLY", elements, file_size - header_bytes);
    check_ply_lists(path, header_bytes, elements, layout, ascii, big_endian, options);
}

// The OFF header read exactly as Assimp's OFF importer reads it (OFFLoader.cpp), since it
// allocates the declared vertices and faces before reading any: optional prefixes "ST", "C",
// "N", "4", "n" then "OFF" with no separator required ("OFF4294967295" declares 4294967295
// vertices: found by fuzz_load_off), or no keyword at all; comment lines start with '#'; then
// [dimension] vertices faces, each count being the leading digits of its token.
class OffHeaderReader {
  public:
    explicit OffHeaderReader(const std::string& text)
        : begin_(text.c_str()), p_(begin_), end_(p_ + text.size()) {}

    // nullopt where Assimp itself refuses the header before allocating.
    std::optional<std::vector<DeclaredElement>> read() {
        next_token();
        if (starts_with("ST")) p_ += 2;
        if (starts_with("C")) ++p_;
        if (starts_with("N")) ++p_;
        if (starts_with("4")) ++p_;
        const bool dimension = starts_with("n");
        if (dimension) ++p_;
        std::uint64_t bytes_per_vertex = 6;  // "x y z" and a line end
        if (starts_with("OFF")) {
            p_ += 3;
            next_token();
        } else {
            next_token();
            if (p_ >= end_ || *p_ < '0' || *p_ > '9') return std::nullopt;  // "Header is invalid"
        }
        if (dimension) {
            const std::uint64_t d = count();
            if (d > 3) return std::nullopt;
            bytes_per_vertex = d > 0 ? 2 * d : 1;
            next_token();
        }
        next_token();
        const std::uint64_t vertices = count();
        next_token();
        const std::uint64_t faces = count();
        if (vertices == 0 || faces == 0) return std::nullopt;  // refused by Assimp
        vertices_ = vertices;
        faces_ = faces;
        next_token();
        count();  // edges
        next_token();
        // At least one digit and a separator per vertex coordinate, "n" and a line end per face.
        return std::vector<DeclaredElement>{{"vertex", vertices, bytes_per_vertex},
                                            {"face", faces, 2}};
    }

    // After read(): the face records as Assimp 5.2.5 reads them (GetNextLine: lines of at most
    // 4095 characters, empty lines skipped). A face of 0 or more than 9 indices is skipped by
    // decrementing the face count without counting the line; two more such lines than faces
    // wrap the count to 2^32 - 1 and the importer crashes freeing them (found by
    // fuzz_load_off). So any such face is refused here.
    void check_faces(const std::filesystem::path& path) {
        // Vertex words are numbers (Assimp read the prefix of "1e5x" and failed on "0x1p3"
        // quoting the rest of the file).
        for (std::uint64_t v = 0; v < vertices_; ++v) {
            const char* line = p_;
            if (!next_line()) break;
            const char* line_end = p_;
            for (const char* q = line; q < line_end;) {
                while (q < line_end &&
                       (*q == ' ' || *q == '\t' || *q == '\r' || *q == '\n' || *q == '\f'))
                    ++q;
                if (q == line_end || *q == '#') break;
                const char* token = q;
                while (q < line_end && *q != ' ' && *q != '\t' && *q != '\r' && *q != '\n' &&
                       *q != '\f')
                    ++q;
                const std::string_view word(token, static_cast<std::size_t>(q - token));
                if (!is_number_word(word))
                    throw InputError(path.string(), "malformed OFF file: vertex " +
                                                        std::to_string(v) + " (line " +
                                                        std::to_string(line_number(line)) +
                                                        "): " + not_a_number(word));
            }
        }
        for (std::uint64_t f = 0; f < faces_; ++f) {
            const char* line = p_;
            if (!next_line()) return;  // a short body: Assimp reports it
            const char* line_end = p_;
            while (line_end > line &&
                   (line_end[-1] == '\r' || line_end[-1] == '\n' || line_end[-1] == '\f'))
                --line_end;
            const char* q = line;
            while (q < line_end && (*q == ' ' || *q == '\t')) ++q;
            std::uint64_t n = 0;
            for (; q < line_end && *q >= '0' && *q <= '9'; ++q)
                n = std::min<std::uint64_t>(n * 10 + std::uint64_t(*q - '0'), 1000);
            if (n == 0 || n > 9)
                throw InputError(path.string(), "malformed OFF file: OFF face record " +
                                                    std::to_string(f) + " has " +
                                                    std::to_string(n) +
                                                    " vertex indices (1 to 9 are supported)");
            check_face_indices(path, f, n, q, line_end, line);
        }
    }

  private:
    // Assimp reads each index with strtoul10 after skipping blanks: an index past the vertices
    // becomes the last vertex, and a missing or non-numeric one (a short record, "-1", "1.5")
    // becomes vertex 0, both with no more than a log line; the face is then drawn stretched
    // across the mesh. Each of the n indices must be digits naming a vertex of the file.
    void check_face_indices(const std::filesystem::path& path, std::uint64_t face, std::uint64_t n,
                            const char* q, const char* line_end, const char* line) const {
        const auto where = [&] {
            return "OFF face " + std::to_string(face) + " (line " +
                   std::to_string(line_number(line)) + ")";
        };
        for (std::uint64_t m = 0; m < n; ++m) {
            while (q < line_end && (*q == ' ' || *q == '\t')) ++q;
            const char* token = q;
            while (q < line_end && *q != ' ' && *q != '\t') ++q;
            const std::string_view text(token, static_cast<std::size_t>(q - token));
            if (text.empty())
                throw InputError(path.string(), "malformed OFF file: " + where() + " declares " +
                                                    std::to_string(n) + " vertices but lists " +
                                                    std::to_string(m) + " indices");
            std::uint64_t index = 0;
            for (const char c : text) {
                if (c < '0' || c > '9')
                    throw InputError(path.string(), "malformed OFF file: " + where() +
                                                        ": vertex index '" +
                                                        one_line(std::string(text.substr(0, 32))) +
                                                        "' is not a number of 0 or more");
                index =
                    std::min<std::uint64_t>(index * 10 + std::uint64_t(c - '0'), UINT64_MAX / 16);
            }
            if (index >= vertices_)
                throw InputError(path.string(),
                                 "malformed OFF file: " + where() + " names vertex " +
                                     std::string(text.substr(0, 32)) + ", but the file has " +
                                     std::to_string(vertices_) + " vertices (0 to " +
                                     std::to_string(vertices_ - 1) + ")");
        }
        // What follows the indices is the face's color (numbers) or a comment; Assimp reads a
        // number's prefix of anything else ("junk" was taken without a word).
        std::size_t colors = 0;
        while (q < line_end) {
            while (q < line_end && (*q == ' ' || *q == '\t' || *q == '\r')) ++q;
            if (q == line_end || *q == '#') break;
            const char* token = q;
            while (q < line_end && *q != ' ' && *q != '\t' && *q != '\r') ++q;
            const std::string_view text(token, static_cast<std::size_t>(q - token));
            if (text.find_first_not_of("0123456789+-.eE") != std::string_view::npos ||
                text.find_first_of("0123456789") == std::string_view::npos)
                throw InputError(path.string(), "malformed OFF file: " + where() + ": '" +
                                                    one_line(std::string(text.substr(0, 32))) +
                                                    "' after its indices is not a color number");
            // A color is a colormap index, RGB or RGBA, each 0..1 or 0..255 (zraster does not
            // use face colors; nonsense values were taken without a word).
            const double value = std::strtod(std::string(text).c_str(), nullptr);
            if (!std::isfinite(value) || value < 0.0 || value > 255.0)
                throw InputError(path.string(), "malformed OFF file: " + where() + ": color '" +
                                                    one_line(std::string(text.substr(0, 32))) +
                                                    "' is outside 0..255");
            ++colors;
        }
        if (colors == 2 || colors > 4)
            throw InputError(path.string(), "malformed OFF file: " + where() + " has " +
                                                std::to_string(colors) +
                                                " color numbers after its indices (a color is "
                                                "1 (a colormap index), 3 (RGB) or 4 (RGBA))");
    }

    // 1-based, counting a CR LF, a lone CR or a lone LF as one line end.
    std::size_t line_number(const char* at) const {
        std::size_t lines = 1;
        for (const char* c = begin_; c < at; ++c)
            if (*c == '\n' || (*c == '\r' && (c + 1 >= end_ || c[1] != '\n'))) ++lines;
        return lines;
    }

    bool starts_with(std::string_view s) const {
        return static_cast<std::size_t>(end_ - p_) >= s.size() &&
               std::string_view(p_, s.size()) == s;
    }
    static bool line_end(char c) { return c == '\r' || c == '\n' || c == '\0'; }
    void skip_spaces_and_line_ends() {
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n')) ++p_;
    }
    void next_token() {
        skip_spaces_and_line_ends();
        while (p_ < end_ && (*p_ == '#' || *p_ == '\n' || *p_ == '\r')) {
            while (p_ < end_ && !line_end(*p_)) ++p_;
            while (p_ < end_ && (*p_ == '\r' || *p_ == '\n')) ++p_;
            skip_spaces_and_line_ends();
        }
    }
    // strtoul10: the leading digits (saturating here, where Assimp wraps at 2^32).
    std::uint64_t count() {
        std::uint64_t value = 0;
        for (; p_ < end_ && *p_ >= '0' && *p_ <= '9'; ++p_) {
            const auto digit = static_cast<std::uint64_t>(*p_ - '0');
            value = value > (UINT64_MAX - digit) / 10 ? UINT64_MAX : value * 10 + digit;
        }
        return value;
    }

    // GetNextLine: up to 4095 characters or a line end, then every line end character.
    bool next_line() {
        if (p_ >= end_ || *p_ == '\0') return false;
        const char* limit = p_ + std::min<std::ptrdiff_t>(end_ - p_, 4095);
        while (p_ < limit && !line_end(*p_) && *p_ != '\f') ++p_;
        while (p_ < end_ && (*p_ == '\r' || *p_ == '\n' || *p_ == '\f')) ++p_;
        return true;
    }

    const char* begin_;
    const char* p_;
    const char* end_;
    std::uint64_t vertices_ = 0, faces_ = 0;
};

void check_off(const std::filesystem::path& path, const std::string& head,
               std::uintmax_t file_size) {
    if (auto elements = OffHeaderReader(head).read()) {
        check_body(path, "OFF", *elements, file_size);
        const std::string text = read_prefix(path, static_cast<std::size_t>(file_size));
        OffHeaderReader reader(text);
        reader.read();
        reader.check_faces(path);
    }
}

// As Assimp's PLY importer tells one: its first three bytes, in any case. "plyply" and "PLY"
// are PLY files to it; a stricter test here let such a file's header reach Assimp unchecked (a
// 691-byte file of two headers run together asked for 4 GB: found by fuzz_load_ply).
bool is_ply(const std::string& head) {
    const auto lower = [&](std::size_t i) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(head[i])));
    };
    return head.size() >= 3 && lower(0) == 'p' && lower(1) == 'l' && lower(2) == 'y';
}

}  // namespace

void check_declared_counts(const std::filesystem::path& path, std::uintmax_t file_size,
                           const LoadOptions& options) {
    // Headers are short; 64 KiB leaves room for long comment blocks.
    const std::string head = read_prefix(path, std::size_t{64} * 1024);
    if (is_ply(head)) {
        check_ply(path, head, file_size, options);
        return;
    }
    if (head.size() >= 12 && head.starts_with("glTF")) {
        check_glb(path, file_size, options);
        return;
    }
    // Assimp picks the importer by extension for the formats below; for an unknown one it asks
    // every importer, and the OFF importer claims anything with "off" in its first bytes: read
    // the header as OFF then too (it only refuses what Assimp would take as an OFF header).
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".gltf") {
        std::ifstream in(path, std::ios::binary);
        check_gltf_bounds(
            path, std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()),
            std::nullopt, options);
        return;
    }
    // (Assimp reads COLLADA by its root element under another name, an .xml too.)
    if (extension == ".dae" ||
        (extension != ".obj" && extension != ".ply" && extension != ".stl" && extension != ".off" &&
         head.find("<COLLADA") != std::string::npos)) {
        std::ifstream in(path, std::ios::binary);
        const std::string doc((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
        check_collada_values(doc, path.string());
        check_collada_instances(doc, path.string(), options);
        return;
    }
    if (extension == ".lws" || head.starts_with("LWSC")) {
        check_lightwave_scene(path, options);
        return;
    }
    check_nesting_depth(path, head);
    if (extension == ".md5mesh" || extension == ".ms3d") {
        std::ifstream in(path, std::ios::binary);
        const std::string bytes(std::istreambuf_iterator<char>(in), {});
        if (extension == ".ms3d")
            check_ms3d(bytes, path.string());
        else
            check_md5_mesh(bytes, path.string());
        return;
    }
    if (path.filename().string().ends_with(".mesh.xml") ||
        (extension == ".xml" && head.find("<mesh") != std::string::npos)) {
        std::ifstream in(path, std::ios::binary);
        check_ogre_xml(std::string(std::istreambuf_iterator<char>(in), {}), path.string());
        return;
    }
    if (extension == ".ogex") {
        std::ifstream in(path, std::ios::binary);
        check_opengex(
            std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()),
            path.string());
        return;
    }
    if (head.starts_with(std::string_view("PK\x03\x04", 4))) {
        check_zip_archive(path, options);
        return;
    }
    for (const char* other : {".obj", ".ply", ".stl", ".glb", ".3ds"})
        if (extension == other) return;
    if (extension != ".off" && starts_json_object(head)) {
        std::ifstream in(path, std::ios::binary);
        check_gltf_bounds(
            path, std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()),
            std::nullopt, options);
        return;
    }
    check_off(path, head, file_size);
}

}  // namespace zraster::io
