#include "io/collada_values_check.hpp"

#include <zraster/error.hpp>

#include <charconv>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <vector>

#include "io/obj_number_token.hpp"
#include "io/text_util.hpp"
#include "io/xml_scan.hpp"

namespace zraster::io {

namespace {

bool is_xml_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && is_xml_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_xml_space(s.back())) s.remove_suffix(1);
    return s;
}

// A whole number of digits only (no sign), as COLLADA's xs:unsignedLong attributes.
std::optional<std::uint64_t> whole_number(std::string_view s) {
    s = trimmed(s);
    std::uint64_t value = 0;
    if (s.empty() || s.front() == '+' || s.front() == '-') return std::nullopt;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return value;
}

// The array's name in messages: <float_array id="positions">.
std::string array_label(std::string_view element, const std::string& id) {
    return "<" + std::string(element) + (id.empty() ? "" : " id=\"" + id + "\"") + ">";
}

// Calls word(w, index) for each whitespace-separated word of `text`; returns the count.
template <class Word>
std::uint64_t for_each_word(std::string_view text, Word&& word) {
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < text.size();) {
        while (i < text.size() && is_xml_space(text[i])) ++i;
        if (i == text.size()) break;
        const std::size_t start = i;
        while (i < text.size() && !is_xml_space(text[i])) ++i;
        word(text.substr(start, i - start), n++);
    }
    return n;
}

// The numbers each transform element holds (COLLADA 1.4/1.5 core).
int transform_numbers(std::string_view element) {
    if (element == "matrix") return 16;
    if (element == "translate" || element == "scale") return 3;
    if (element == "rotate") return 4;
    if (element == "lookat") return 9;
    if (element == "skew") return 7;
    return 0;
}

bool is_primitive(std::string_view element) {
    return element == "triangles" || element == "polylist" || element == "polygons" ||
           element == "lines" || element == "linestrips" || element == "trifans" ||
           element == "tristrips";
}

// A primitive element while its children are scanned: its declared count, the largest <input>
// offset, and the index words of its <p>s.
struct Primitive {
    std::string label;
    std::uint64_t count = 0;
    std::uint64_t max_offset = 0;
    std::uint64_t index_words = 0;
    std::uint64_t largest_index = 0;
};

struct Accessor {
    std::string label;
    std::string source;  // the array's id, without '#'
    std::uint64_t count = 0;
    std::uint64_t offset = 0;
    std::uint64_t stride = 1;
    std::uint64_t params = 0;
};

}  // namespace

void check_collada_values(std::string_view doc, const std::string& file) {
    auto refuse = [&](const std::string& cause) {
        return InputError(file, "malformed COLLADA file: " + cause);
    };
    std::unordered_map<std::string, std::uint64_t> array_counts;  // by id
    std::vector<Accessor> accessors;
    bool in_accessor = false;
    std::optional<Primitive> primitive;
    std::uint64_t primitives_largest_index = 0;
    std::uint64_t largest_array = 0;
    std::optional<std::size_t> up_axis_text;

    // Every element of a primitive has at least one index, every vertex one per offset: a count
    // or an offset past the <p> words only made the importer reserve memory for them
    // (count="2000000000": out of memory).
    auto settle = [&](const Primitive& prim) {
        if (prim.count > prim.index_words)
            throw refuse(prim.label + " has count=\"" + std::to_string(prim.count) + "\" but " +
                         std::to_string(prim.index_words) + " indices in its <p>");
        if (prim.index_words > 0 && prim.max_offset >= prim.index_words)
            throw refuse(prim.label + " has an <input> of offset=\"" +
                         std::to_string(prim.max_offset) + "\" but " +
                         std::to_string(prim.index_words) + " indices in its <p>");
        primitives_largest_index = std::max(primitives_largest_index, prim.largest_index);
    };
    for_each_xml_tag(doc, [&](const XmlTag& tag) {
        if (tag.end) {
            if (tag.name == "accessor") in_accessor = false;
            if (primitive && is_primitive(tag.name)) {
                settle(*primitive);
                primitive.reset();
            }
            return;
        }
        const bool floats = tag.name == "float_array";
        if (floats || tag.name == "int_array") {
            const std::string id = xml_attribute(tag.attributes, "id");
            const std::string label = array_label(tag.name, id);
            const std::string count_text = xml_attribute(tag.attributes, "count");
            const std::optional<std::uint64_t> count = whole_number(count_text);
            if (!count)
                throw refuse(label + " has count=\"" + quoted_word(count_text) +
                             "\", not a whole number of values");
            std::uint64_t words = 0;
            if (!tag.empty)
                words = for_each_word(xml_text_at(doc, tag.after), [&](std::string_view word,
                                                                       std::uint64_t n) {
                    // (xs:float's INF and NaN are among the number words.)
                    if (floats ? is_number_word(word) : is_index_word(word)) return;
                    throw refuse(label + " value " + std::to_string(n) + ": " +
                                 (floats ? not_a_number(word)
                                         : "'" + quoted_word(word) + "' is not a whole number"));
                });
            if (words < *count)
                throw refuse(label + " has count=\"" + std::to_string(*count) + "\" but " +
                             std::to_string(words) + " values");
            if (!id.empty()) array_counts.emplace(id, *count);
            largest_array = std::max(largest_array, *count);
        } else if (tag.name == "accessor") {
            Accessor a;
            a.source = xml_attribute(tag.attributes, "source");
            a.label = "<accessor source=\"" + quoted_word(a.source) + "\">";
            if (a.source.starts_with('#')) a.source.erase(0, 1);
            for (const char* name : {"count", "offset", "stride"}) {
                const std::string text = xml_attribute(tag.attributes, name);
                if (text.empty() && std::string_view(name) != "count") continue;
                const std::optional<std::uint64_t> value = whole_number(text);
                if (!value)
                    throw refuse(a.label + " has " + name + "=\"" + quoted_word(text) +
                                 "\", not a whole number");
                (std::string_view(name) == "count"    ? a.count
                 : std::string_view(name) == "offset" ? a.offset
                                                      : a.stride) = *value;
            }
            if (a.stride == 0) throw refuse(a.label + " has stride=\"0\"");
            accessors.push_back(a);
            in_accessor = !tag.empty;
        } else if (tag.name == "param" && in_accessor) {
            ++accessors.back().params;
        } else if (is_primitive(tag.name)) {
            Primitive prim;
            prim.label = "<" + std::string(tag.name) + ">";
            const std::string text = xml_attribute(tag.attributes, "count");
            const std::optional<std::uint64_t> count = whole_number(text);
            if (!count)
                throw refuse(prim.label + " has count=\"" + quoted_word(text) +
                             "\", not a whole number");
            prim.count = *count;
            if (tag.empty)
                settle(prim);
            else
                primitive = prim;
        } else if (primitive && tag.name == "input") {
            const std::string text = xml_attribute(tag.attributes, "offset");
            if (text.empty()) return;  // (required by the schema; the importer takes 0)
            const std::optional<std::uint64_t> offset = whole_number(text);
            if (!offset)
                throw refuse(primitive->label + " has an <input> of offset=\"" + quoted_word(text) +
                             "\", not a whole number");
            primitive->max_offset = std::max(primitive->max_offset, *offset);
        } else if (primitive && (tag.name == "p" || tag.name == "vcount") && !tag.empty) {
            const bool indices = tag.name == "p";
            const std::uint64_t words = for_each_word(
                xml_text_at(doc, tag.after), [&](std::string_view word, std::uint64_t n) {
                    const std::optional<std::uint64_t> value = whole_number(word);
                    if (!value)
                        throw refuse(primitive->label + " <" + std::string(tag.name) + "> word " +
                                     std::to_string(n) + " '" + quoted_word(word) +
                                     "' is not a whole number");
                    if (indices)
                        primitive->largest_index = std::max(primitive->largest_index, *value);
                });
            if (indices) primitive->index_words += words;
        } else if (const int numbers = transform_numbers(tag.name); numbers > 0 && !tag.empty) {
            const std::string label = "<" + std::string(tag.name) + ">";
            const std::uint64_t words = for_each_word(
                xml_text_at(doc, tag.after), [&](std::string_view word, std::uint64_t n) {
                    if (!is_number_word(word))
                        throw refuse(label + " value " + std::to_string(n) + ": " +
                                     not_a_number(word));
                });
            if (words != static_cast<std::uint64_t>(numbers))
                throw refuse(label + " has " + std::to_string(words) + " numbers, not " +
                             std::to_string(numbers));
        } else if (tag.name == "unit") {
            const std::string text = xml_attribute(tag.attributes, "meter");
            if (text.empty()) return;
            const std::string_view t = trimmed(text);
            double meter = 0;
            const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), meter);
            // (Past the largest float the importer's single-precision scale is infinite.)
            if (ec != std::errc() || end != t.data() + t.size() || !(meter > 0) ||
                meter > std::numeric_limits<float>::max())
                throw refuse("<unit meter=\"" + quoted_word(text) +
                             "\"> is not a positive finite length in meters (single precision)");
        } else if (tag.name == "up_axis" && !tag.empty) {
            up_axis_text = tag.after;
        }
    });

    if (up_axis_text) {
        const std::string_view axis = trimmed(xml_text_at(doc, *up_axis_text));
        if (axis != "X_UP" && axis != "Y_UP" && axis != "Z_UP")
            throw refuse("<up_axis> '" + quoted_word(axis) + "' is none of X_UP, Y_UP, Z_UP");
    }
    // An index addresses an element of an accessor, which lies within one array.
    if (!array_counts.empty() && primitives_largest_index >= largest_array)
        throw refuse("a <p> index " + std::to_string(primitives_largest_index) +
                     " is past every array's values (the largest has " +
                     std::to_string(largest_array) + ")");
    for (const Accessor& a : accessors) {
        if (a.stride < a.params)
            throw refuse(a.label + " has stride=\"" + std::to_string(a.stride) + "\" but " +
                         std::to_string(a.params) + " <param>s");
        const auto array = array_counts.find(a.source);
        if (array == array_counts.end() || a.count == 0) continue;
        // offset + (count - 1) x stride + max(params, 1) values, in long double: the product of
        // two 64-bit numbers may not fit in 64 bits.
        const long double needed = static_cast<long double>(a.offset) +
                                   static_cast<long double>(a.count - 1) * a.stride +
                                   static_cast<long double>(std::max<std::uint64_t>(a.params, 1));
        if (needed > static_cast<long double>(array->second))
            throw refuse(a.label + " reads " + std::to_string(a.count) + " elements of stride " +
                         std::to_string(a.stride) + " from offset " + std::to_string(a.offset) +
                         ", past the end of its array's " + std::to_string(array->second) +
                         " values");
    }
}

}  // namespace zraster::io
