// See gltf_material_types.hpp.
#include "io/gltf_material_types.hpp"

#include "io/gltf_document.hpp"
#include "io/text_util.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace zraster::io {

namespace {

using nlohmann::json;

// A member's JSON, short enough for a one-line message.
std::string shown(const json& value) {
    std::string text = value.dump();
    if (text.size() > 40) text = text.substr(0, 40) + "...";
    return one_line(text);
}

class MaterialTypes {
  public:
    MaterialTypes(const json& material, std::size_t index, std::vector<std::string>& out)
        : material_(material), out_(out) {
        // As the range warnings name a material (assimp_material.cpp), by index when unnamed.
        const auto name = material.find("name");
        label_ = name != material.end() && name->is_string()
                     ? "material '" + one_line(name->get<std::string>().substr(0, 64)) + "'"
                     : "material " + std::to_string(index);
    }

    void run() {
        member(material_, "alphaMode", &json::is_string, "a string (OPAQUE, MASK or BLEND)",
               "drawn opaque (glTF's default)");
        member(material_, "alphaCutoff", &json::is_number, "a number",
               "using 0.5 (glTF's default)");
        member(material_, "doubleSided", &json::is_boolean, "true or false",
               "using false (glTF's default)");
        const auto pbr = material_.find("pbrMetallicRoughness");
        if (pbr != material_.end() && !pbr->is_object()) {
            warn("pbrMetallicRoughness " + shown(*pbr) +
                 " is not an object, using glTF's defaults");
        } else if (pbr != material_.end()) {
            numbers(*pbr, "baseColorFactor", 4, "1, 1, 1, 1");
            member(*pbr, "metallicFactor", &json::is_number, "a number",
                   "using 1 (glTF's default)");
            member(*pbr, "roughnessFactor", &json::is_number, "a number",
                   "using 1 (glTF's default)");
        }
        numbers(material_, "emissiveFactor", 3, "0, 0, 0");
    }

  private:
    void warn(const std::string& what) { out_.push_back(label_ + ": " + what); }

    void member(const json& holder, const char* key, bool (json::*is)() const noexcept,
                const char* expected, const char* used) {
        const auto it = holder.find(key);
        if (it == holder.end() || ((*it).*is)()) return;
        warn(std::string(key) + " " + shown(*it) + " is not " + expected + ", " + used);
    }

    // An array of `n` numbers. (Assimp takes an array of the right length whatever its elements
    // are, keeping the default for an element that is not a number.)
    void numbers(const json& holder, const char* key, std::size_t n, const char* defaults) {
        const auto it = holder.find(key);
        if (it == holder.end()) return;
        if (!it->is_array() || it->size() != n) {
            warn(std::string(key) + " " + shown(*it) + " is not " + std::to_string(n) +
                 " numbers, using " + defaults + " (glTF's default)");
            return;
        }
        if (!std::all_of(it->begin(), it->end(), [](const json& x) { return x.is_number(); }))
            warn(std::string(key) + " " + shown(*it) + " is not " + std::to_string(n) +
                 " numbers, using glTF's default (" + defaults + ") where it is not a number");
    }

    const json& material_;
    std::vector<std::string>& out_;
    std::string label_;
};

}  // namespace

std::vector<std::string> gltf_material_type_warnings(const std::filesystem::path& path) {
    std::vector<std::string> out;
    const std::string text = gltf_document(path);
    if (text.empty()) return out;
    const json document = json::parse(text, nullptr, false);
    const auto materials = document.is_object() ? document.find("materials") : document.end();
    if (materials == document.end() || !materials->is_array()) return out;
    for (std::size_t m = 0; m < materials->size(); ++m)
        if ((*materials)[m].is_object()) MaterialTypes((*materials)[m], m, out).run();
    return out;
}

}  // namespace zraster::io
