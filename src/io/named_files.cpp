#include "io/named_files.hpp"

#include "io/gltf_document.hpp"
#include "io/uri_escapes.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace zraster::io {

void note_gltf_images(const std::filesystem::path& model, const ReferencePolicy& policy) {
    const std::string text = gltf_document(model);
    if (text.empty()) return;
    const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
    if (!document.is_object()) return;
    const auto images = document.find("images");
    if (images == document.end() || !images->is_array()) return;
    for (const nlohmann::json& image : *images) {
        if (!image.is_object()) continue;
        const auto uri = image.find("uri");
        if (uri == image.end() || !uri->is_string()) continue;
        const std::string name = uri->get<std::string>();
        if (name.empty() || name.starts_with("data:")) continue;
        (void)policy.check(uri_file(model.parent_path(), name));
    }
}

}  // namespace zraster::io
