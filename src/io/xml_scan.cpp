#include "io/xml_scan.hpp"

namespace zraster::io {

namespace {
bool is_xml_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}
}  // namespace

std::string xml_attribute(std::string_view tag, std::string_view name) {
    for (std::size_t at = tag.find(name); at != std::string_view::npos;
         at = tag.find(name, at + 1)) {
        if (at == 0 || !is_xml_space(tag[at - 1])) continue;
        std::size_t i = at + name.size();
        while (i < tag.size() && is_xml_space(tag[i])) ++i;
        if (i >= tag.size() || tag[i] != '=') continue;
        ++i;
        while (i < tag.size() && is_xml_space(tag[i])) ++i;
        if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\'')) continue;
        const char quote = tag[i];
        const std::size_t end = tag.find(quote, i + 1);
        if (end == std::string_view::npos) return {};
        return std::string(tag.substr(i + 1, end - i - 1));
    }
    return {};
}

std::string_view xml_text_at(std::string_view doc, std::size_t offset) {
    if (offset >= doc.size()) return {};
    const std::size_t end = doc.find('<', offset);
    return doc.substr(offset, (end == std::string_view::npos ? doc.size() : end) - offset);
}

}  // namespace zraster::io
