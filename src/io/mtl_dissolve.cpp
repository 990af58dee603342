// MTL `d` over `Tr` (see mtl_dissolve.hpp).
#include "io/mtl_dissolve.hpp"

#include "io/obj_material_libraries.hpp"
#include "io/text_util.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace zraster::io {

namespace {

// The first word of `text` as a float, or nullopt. (Assimp reads it with its fast_atof, which
// may differ from this correctly rounded reading in the last bit; its exception type cannot be
// linked against, so it is not called here.)
std::optional<float> first_number(std::string_view text) {
    text = trim(text);
    text = text.substr(0, text.find_first_of(" \t"));
    if (text.starts_with('+')) text.remove_prefix(1);
    float value = 0.0f;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end == text.data()) return std::nullopt;
    return value;
}

}  // namespace

void MtlDissolve::read(const std::filesystem::path& mtl) {
    std::ifstream in(mtl, std::ios::binary);
    std::string line, name;
    Statements* current = nullptr;
    while (std::getline(in, line)) {
        if (directive(line, "newmtl", name)) {
            current = &materials_[name];
            continue;
        }
        // Assimp's reader dispatches on a statement's first letters: `d` other than `disp` is
        // the dissolve, `Tr` the transparency.
        const std::string_view text = trim(line);
        if (current == nullptr || text.empty()) continue;
        if (text[0] == 'd' && !text.starts_with("disp")) {
            if (std::optional<float> value = first_number(text.substr(1))) {
                current->dissolve = value;
                current->transparency_after = false;
            }
        } else if (text.starts_with("Tr")) {
            current->transparency_after = current->dissolve.has_value();
        }
    }
}

std::optional<float> MtlDissolve::hidden_dissolve(const std::string& material) const {
    const auto it = materials_.find(material);
    if (it == materials_.end() || !it->second.transparency_after) return std::nullopt;
    return it->second.dissolve;
}

void MtlDissolve::apply(Material& material, std::vector<std::string>& warnings) const {
    const std::optional<float> d = hidden_dissolve(material.name);
    if (!d) return;
    const float kept = std::isnan(*d) ? 1.0f : std::clamp(*d, 0.0f, 1.0f);
    if (kept != *d) {
        char text[96];
        std::snprintf(text, sizeof text, "opacity (d) %g is outside 0..1, using %g", double(*d),
                      double(kept));
        warnings.push_back("material '" + material.name + "': " + text);
    }
    material.opacity = kept;
}

}  // namespace zraster::io
