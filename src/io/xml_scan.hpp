// A light scan of an XML document's tags, for the checks made before Assimp reads an XML format
// (COLLADA): no tree is built, comments, CDATA, processing instructions and declarations are
// skipped, and text is reached through the offsets the tags give.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace zraster::io {

struct XmlTag {
    std::string_view name;        // the element's local name (a namespace prefix removed)
    std::string_view attributes;  // the start tag's text after its name
    bool end = false;             // </name>
    bool empty = false;           // <name ... />
    std::size_t after = 0;        // the offset just past the tag's '>'
};

// Calls visit(tag) for every start and end tag in document order; stops at the first
// unterminated construct.
template <class Visit>
void for_each_xml_tag(std::string_view doc, Visit&& visit);

// The value of attribute `name` in a start tag's attributes, "" if none.
std::string xml_attribute(std::string_view attributes, std::string_view name);

// The text from `offset` to the next '<' (an element's text when it has no children).
std::string_view xml_text_at(std::string_view doc, std::size_t offset);

// --- implementation ---

namespace detail {
inline bool is_xml_name_char(char c) {
    return c != '>' && c != '/' && c != ' ' && c != '\t' && c != '\n' && c != '\r';
}
}  // namespace detail

template <class Visit>
void for_each_xml_tag(std::string_view doc, Visit&& visit) {
    std::size_t i = 0;
    while ((i = doc.find('<', i)) != std::string_view::npos) {
        if (doc.compare(i, 4, "<!--") == 0) {
            const std::size_t end = doc.find("-->", i + 4);
            if (end == std::string_view::npos) return;
            i = end + 3;
            continue;
        }
        if (doc.compare(i, 9, "<![CDATA[") == 0) {
            const std::size_t end = doc.find("]]>", i + 9);
            if (end == std::string_view::npos) return;
            i = end + 3;
            continue;
        }
        const std::size_t close = doc.find('>', i);
        if (close == std::string_view::npos) return;
        std::string_view tag = doc.substr(i + 1, close - i - 1);
        i = close + 1;
        if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
        XmlTag t;
        t.end = tag[0] == '/';
        if (t.end) tag.remove_prefix(1);
        t.empty = !tag.empty() && tag.back() == '/';
        std::size_t name_end = 0;
        while (name_end < tag.size() && detail::is_xml_name_char(tag[name_end])) ++name_end;
        t.name = tag.substr(0, name_end);
        if (const std::size_t colon = t.name.rfind(':'); colon != std::string_view::npos)
            t.name.remove_prefix(colon + 1);
        t.attributes = tag.substr(name_end);
        t.after = i;
        visit(t);
    }
}

}  // namespace zraster::io
