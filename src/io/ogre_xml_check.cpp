#include "io/ogre_xml_check.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>

#include "io/obj_number_token.hpp"
#include "io/xml_scan.hpp"

namespace zraster::io {

namespace {

std::optional<std::uint64_t> whole(const std::string& text) {
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

}  // namespace

void check_ogre_xml(std::string_view doc, const std::string& file) {
    const auto refuse = [&](const std::string& cause) {
        return InputError(file, "malformed Ogre XML file: " + cause);
    };
    // A geometry (shared or a submesh's): its declared and counted vertices.
    constexpr std::uint64_t kUndeclared = ~std::uint64_t{0};
    struct Geometry {
        std::uint64_t declared = kUndeclared;
        std::uint64_t vertices = 0;
    };
    Geometry shared, own;
    Geometry* geometry = nullptr;  // the one being read
    bool uses_shared = false;
    std::uint64_t faces_declared = kUndeclared;
    std::uint64_t faces = 0, largest_index = 0, submesh = 0;
    bool any_face = false;
    const auto count_of = [&](const XmlTag& tag, const char* name) {
        const std::string text = xml_attribute(tag.attributes, name);
        if (text.empty()) return kUndeclared;
        const std::optional<std::uint64_t> n = whole(text);
        if (!n || *n == kUndeclared)
            throw refuse("<" + std::string(tag.name) + " " + name + "=\"" + text.substr(0, 32) +
                         "\"> is not a whole number");
        return *n;
    };
    for_each_xml_tag(doc, [&](const XmlTag& tag) {
        const std::string_view name = tag.name;
        if (tag.end) {
            if (name == "sharedgeometry" || name == "geometry") {
                if (geometry->declared != kUndeclared && geometry->declared != geometry->vertices)
                    throw refuse("<" + std::string(name) + " vertexcount=\"" +
                                 std::to_string(geometry->declared) + "\"> holds " +
                                 std::to_string(geometry->vertices) + " vertices");
                geometry = nullptr;
            } else if (name == "submesh") {
                if (faces_declared != kUndeclared && faces_declared != faces)
                    throw refuse("submesh " + std::to_string(submesh) + ": <faces count=\"" +
                                 std::to_string(faces_declared) + "\"> holds " +
                                 std::to_string(faces) + " faces");
                const Geometry& g = uses_shared ? shared : own;
                if (any_face && largest_index >= g.vertices)
                    throw refuse("submesh " + std::to_string(submesh) + ": a face names vertex " +
                                 std::to_string(largest_index) + ", its geometry has " +
                                 std::to_string(g.vertices) + " vertices");
                ++submesh;
            }
            return;
        }
        if (name == "sharedgeometry" || name == "geometry") {
            geometry = name == "sharedgeometry" ? &shared : &own;
            *geometry = Geometry{count_of(tag, "vertexcount"), 0};
        } else if (name == "submesh") {
            uses_shared = xml_attribute(tag.attributes, "usesharedvertices") == "true";
            own = Geometry{};
            faces_declared = kUndeclared;
            faces = largest_index = 0;
            any_face = false;
        } else if (name == "faces") {
            faces_declared = count_of(tag, "count");
        } else if (name == "face") {
            ++faces;
            for (const char* v : {"v1", "v2", "v3"}) {
                const std::uint64_t index = count_of(tag, v);
                if (index != kUndeclared) {
                    largest_index = std::max(largest_index, index);
                    any_face = true;
                }
            }
        } else if (name == "vertex" && geometry != nullptr) {
            ++geometry->vertices;
        } else if (name == "position" || name == "normal" || name == "texcoord") {
            for (const char* axis : {"x", "y", "z", "u", "v"}) {
                const std::string value = xml_attribute(tag.attributes, axis);
                if (!value.empty() && !is_number_word(value))
                    throw refuse("<" + std::string(name) + " " + axis +
                                 "=\"...\">: " + not_a_number(value));
            }
        }
    });
}

}  // namespace zraster::io
