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
            fraction(*pbr, "metallicFactor");
        }
        numbers(material_, "emissiveFactor", 3, "0, 0, 0");
        const auto emissive = material_.find("emissiveFactor");
        if (emissive != material_.end() && emissive->is_array() && emissive->size() == 3 &&
            std::any_of(emissive->begin(), emissive->end(),
                        [](const json& x) { return x.is_number() && !(x >= 0 && x <= 1); }))
            unused("emissiveFactor " + shown(*emissive) + " is outside glTF's range [0, 1]");
        // Extensions' numbers (KHR_materials_emissive_strength, KHR_materials_ior).
        const auto extensions = material_.find("extensions");
        if (extensions == material_.end() || !extensions->is_object()) return;
        const json* strength =
            extension_number(*extensions, "KHR_materials_emissive_strength", "emissiveStrength");
        if (strength && !(*strength >= 0))
            unused("KHR_materials_emissive_strength emissiveStrength " + shown(*strength) +
                   " is negative (glTF's range: 0 or more)");
        const json* ior = extension_number(*extensions, "KHR_materials_ior", "ior");
        if (ior && !(*ior >= 1 || *ior == 0))
            unused("KHR_materials_ior ior " + shown(*ior) +
                   " is outside glTF's range (1 or more, or 0)");
    }

  private:
    void warn(const std::string& what) { out_.push_back(label_ + ": " + what); }

    // A number out of its glTF range that zraster does not shade with (metallic, emission, index
    // of refraction): said, and left unused, as it would be in range.
    void unused(const std::string& what) {
        warn(what + "; not used (zraster does not shade with it)");
    }

    // A number member in [0, 1] when it is a number (its type is checked by member()).
    void fraction(const json& holder, const char* key) {
        const auto it = holder.find(key);
        if (it != holder.end() && it->is_number() && !(*it >= 0 && *it <= 1))
            unused(std::string(key) + " " + shown(*it) + " is outside glTF's range [0, 1]");
    }

    // extensions.NAME.KEY when it is a number.
    static const json* extension_number(const json& extensions, const char* name, const char* key) {
        const auto extension = extensions.find(name);
        if (extension == extensions.end() || !extension->is_object()) return nullptr;
        const auto value = extension->find(key);
        return value != extension->end() && value->is_number() ? &*value : nullptr;
    }

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
