#include "io/opengex_check.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <vector>

namespace zraster::io {

namespace {

constexpr std::size_t kMaxStructureDepth = 1000;

enum class Kind { Identifier, Name, Number, String, Punct, End };

struct Token {
    Kind kind = Kind::End;
    std::string_view text;
    std::size_t line = 1;
};

// OpenDDL's tokens: identifiers, names ($x, %x), numbers, strings, and { } [ ] ( ) , =; comments
// (//, /* */) and blanks between them.
class Tokens {
  public:
    explicit Tokens(std::string_view text) : text_(text) {}

    Token next() {
        skip_blanks();
        Token t;
        t.line = line_;
        if (at_ >= text_.size()) return t;
        const std::size_t start = at_;
        const char c = text_[at_];
        if (is_identifier_start(c) || c == '$' || c == '%') {
            t.kind = is_identifier_start(c) ? Kind::Identifier : Kind::Name;
            ++at_;
            while (at_ < text_.size() && is_identifier_char(text_[at_])) ++at_;
        } else if (c == '"') {
            t.kind = Kind::String;
            for (++at_; at_ < text_.size() && text_[at_] != '"'; ++at_) {
                if (text_[at_] == '\\') ++at_;
                if (at_ < text_.size() && text_[at_] == '\n') ++line_;
            }
            ++at_;
        } else if (std::string_view("{}[](),=").find(c) != std::string_view::npos) {
            t.kind = Kind::Punct;
            ++at_;
        } else {
            t.kind = Kind::Number;  // digits, signs, points, exponents, hex, binary: one word
            while (at_ < text_.size() && !is_blank(text_[at_]) &&
                   std::string_view("{}[](),=\"").find(text_[at_]) == std::string_view::npos)
                ++at_;
        }
        t.text = text_.substr(start, std::min(at_, text_.size()) - start);
        return t;
    }

  private:
    static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
    static bool is_identifier_start(char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    }
    static bool is_identifier_char(char c) {
        return is_identifier_start(c) || (c >= '0' && c <= '9');
    }
    void skip_blanks() {
        while (at_ < text_.size()) {
            if (text_[at_] == '\n') ++line_;
            if (is_blank(text_[at_])) {
                ++at_;
            } else if (text_.compare(at_, 2, "//") == 0) {
                while (at_ < text_.size() && text_[at_] != '\n') ++at_;
            } else if (text_.compare(at_, 2, "/*") == 0) {
                const std::size_t end = text_.find("*/", at_ + 2);
                for (std::size_t i = at_; i < std::min(end, text_.size()); ++i)
                    line_ += text_[i] == '\n';
                at_ = end == std::string_view::npos ? text_.size() : end + 2;
            } else {
                return;
            }
        }
    }
    std::string_view text_;
    std::size_t at_ = 0;
    std::size_t line_ = 1;
};

bool is_data_type(std::string_view s) {
    for (const char* type : {"bool",
                             "int8",
                             "int16",
                             "int32",
                             "int64",
                             "unsigned_int8",
                             "unsigned_int16",
                             "unsigned_int32",
                             "unsigned_int64",
                             "half",
                             "float",
                             "double",
                             "string",
                             "ref",
                             "type",
                             "float16",
                             "float32",
                             "float64",
                             "u8",
                             "u16",
                             "u32",
                             "u64",
                             "i8",
                             "i16",
                             "i32",
                             "i64",
                             "b",
                             "h",
                             "f",
                             "d",
                             "s",
                             "r",
                             "t",
                             "uint8",
                             "uint16",
                             "uint32",
                             "uint64"})
        if (s == type) return true;
    return false;
}

// A data list: its elements (subarrays, or single values) and each element's values.
struct DataList {
    std::string_view type;  // float, unsigned_int32, ...
    std::size_t width = 0;  // [N], 0 without
    std::vector<std::vector<std::string_view>> elements;
    std::size_t line = 1;
};

struct Structure {
    std::string_view identifier;
    std::string_view attrib;  // VertexArray (attrib = "...")
    std::size_t line = 1;
    // Mesh: the position array's count and the index arrays' lines and values.
    std::optional<std::size_t> vertices;
    struct Array {
        std::string_view attrib;
        std::size_t count;
        std::size_t width;
        std::size_t line;
    };
    std::vector<Array> vertex_arrays;
    std::vector<DataList> index_arrays;
};

}  // namespace

void check_opengex(std::string_view text, const std::string& file) {
    Tokens tokens(text);
    const auto refuse = [&](std::size_t line, const std::string& cause) {
        return InputError(file,
                          "malformed OpenGEX file: line " + std::to_string(line) + ": " + cause);
    };
    std::vector<Structure> open;
    // Global names of structures ($x), and the references to them (ref {$x}): a reference to no
    // structure left the importer without the mesh or material it names.
    std::vector<std::string_view> names;
    struct Reference {
        std::string_view name;
        std::size_t line;
    };
    std::vector<Reference> references;
    const auto mesh = [&]() -> Structure* {
        for (auto it = open.rbegin(); it != open.rend(); ++it)
            if (it->identifier == "Mesh") return &*it;
        return nullptr;
    };
    const auto close_mesh = [&](const Structure& m) {
        std::optional<std::size_t> positions;
        for (const Structure::Array& a : m.vertex_arrays)
            if (a.attrib == "position" || a.attrib.starts_with("position["))
                positions = positions ? positions : std::optional<std::size_t>(a.count);
        if (!positions) return;  // (the importer says what is missing)
        for (const Structure::Array& a : m.vertex_arrays) {
            if ((a.attrib == "position" || a.attrib.starts_with("position[")) && a.width != 3)
                throw refuse(a.line, "the position array's elements are " +
                                         std::to_string(a.width) +
                                         " numbers; x y z are needed ([3])");
            if (a.count == 0)
                throw refuse(a.line, "vertex array '" + std::string(a.attrib) + "' is empty");
            if (a.count != *positions)
                throw refuse(a.line, "vertex array '" + std::string(a.attrib) + "' has " +
                                         std::to_string(a.count) + " elements, the positions " +
                                         std::to_string(*positions));
        }
        for (const DataList& list : m.index_arrays) {
            if (list.width != 3)
                throw refuse(list.line, "an index array of " +
                                            (list.width == 0 ? std::string("single values")
                                                             : std::to_string(list.width)) +
                                            " (faces are triangles: [3])");
            for (const auto& element : list.elements)
                for (const std::string_view word : element) {
                    std::uint64_t index = 0;
                    const auto [end, ec] =
                        std::from_chars(word.data(), word.data() + word.size(), index);
                    if (ec != std::errc() || end != word.data() + word.size() ||
                        index >= *positions)
                        throw refuse(list.line, "index '" + std::string(word.substr(0, 32)) +
                                                    "' is not one of the mesh's " +
                                                    std::to_string(*positions) + " vertices");
                }
        }
    };

    for (Token t = tokens.next(); t.kind != Kind::End;) {
        if (t.kind == Kind::Punct && t.text == "}") {
            if (!open.empty()) {
                if (open.back().identifier == "Mesh") close_mesh(open.back());
                open.pop_back();
            }
            t = tokens.next();
            continue;
        }
        if (t.kind != Kind::Identifier) {
            t = tokens.next();
            continue;
        }
        const Token identifier = t;
        t = tokens.next();
        if (is_data_type(identifier.text)) {
            // A data list: type [N] name? { ... }
            DataList list;
            list.line = identifier.line;
            list.type = identifier.text;
            if (t.kind == Kind::Punct && t.text == "[") {
                t = tokens.next();
                std::size_t width = 0;
                std::from_chars(t.text.data(), t.text.data() + t.text.size(), width);
                list.width = width;
                t = tokens.next();  // ]
                t = tokens.next();
            }
            if (t.kind == Kind::Name) t = tokens.next();
            if (!(t.kind == Kind::Punct && t.text == "{")) continue;
            // Values until the list's closing brace (one level of subarrays).
            int depth = 1;
            std::vector<std::string_view> current;
            for (t = tokens.next(); t.kind != Kind::End && depth > 0; t = tokens.next()) {
                if (t.kind == Kind::Punct && t.text == "{") {
                    ++depth;
                    current.clear();
                } else if (t.kind == Kind::Punct && t.text == "}") {
                    if (--depth == 1 && list.width > 0) list.elements.push_back(current);
                } else if (t.kind != Kind::Punct) {
                    if (list.width == 0)
                        list.elements.push_back({t.text});
                    else
                        current.push_back(t.text);
                }
            }
            // Debian's Assimp reads vertex arrays of float and index arrays of unsigned_int32
            // only (other types failed its parser's assertions or were read as zeros), and
            // light colors of 4 numbers (3 failed an assertion).
            const std::string_view owner =
                open.empty() ? std::string_view() : open.back().identifier;
            if (owner == "VertexArray" && list.type != "float" && list.type != "float32" &&
                list.type != "f")
                throw refuse(list.line, "a vertex array of " + std::string(list.type) +
                                            ": the importer reads float arrays only");
            if (owner == "IndexArray" && list.type != "unsigned_int32" && list.type != "u32" &&
                list.type != "uint32")
                throw refuse(list.line, "an index array of " + std::string(list.type) +
                                            ": the importer reads unsigned_int32 indices only");
            const bool in_light = std::any_of(open.begin(), open.end(), [](const Structure& o) {
                return o.identifier == "LightObject";
            });
            if (owner == "Color" && in_light && list.width != 4)
                throw refuse(list.line, "a light's Color of " + std::to_string(list.width) +
                                            " numbers: the importer reads 4 (r g b a)");
            Structure* m = mesh();
            if (m != nullptr && !open.empty() && open.back().identifier == "VertexArray")
                m->vertex_arrays.push_back(
                    {open.back().attrib, list.elements.size(), list.width, open.back().line});
            for (const auto& element : list.elements)
                for (const std::string_view word : element)
                    if (word.starts_with('$')) references.push_back({word, list.line});
            if (m != nullptr && !open.empty() && open.back().identifier == "IndexArray")
                m->index_arrays.push_back(std::move(list));
            continue;
        }
        // A structure: identifier name? (properties)? {
        Structure s;
        s.identifier = identifier.text;
        s.line = identifier.line;
        if (t.kind == Kind::Name) {
            names.push_back(t.text);
            t = tokens.next();
        }
        if (t.kind == Kind::Punct && t.text == "(") {
            std::string_view key;
            for (t = tokens.next();
                 t.kind != Kind::End && !(t.kind == Kind::Punct && t.text == ")");
                 t = tokens.next()) {
                if (t.kind == Kind::Identifier) key = t.text;
                if (t.kind == Kind::String && key == "attrib" && t.text.size() >= 2)
                    s.attrib = t.text.substr(1, t.text.size() - 2);
            }
            t = tokens.next();
        }
        if (!(t.kind == Kind::Punct && t.text == "{")) continue;
        open.push_back(s);
        if (open.size() > kMaxStructureDepth)
            throw refuse(identifier.line, "structures nest more than " +
                                              std::to_string(kMaxStructureDepth) +
                                              " levels deep (the importer reads them "
                                              "recursively)");
        t = tokens.next();
    }
    std::sort(names.begin(), names.end());
    for (const Reference& r : references)
        if (!std::binary_search(names.begin(), names.end(), r.name))
            throw refuse(r.line, "a reference to " + std::string(r.name.substr(0, 64)) +
                                     ", which no structure is named");
}

}  // namespace zraster::io
