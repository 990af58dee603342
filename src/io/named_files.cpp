#include "io/named_files.hpp"

#include "io/gltf_document.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace zraster::io {

namespace {

// A URI's percent escapes decoded ("a%20b.png" names "a b.png"); others kept as written.
std::string decoded_uri(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        const auto hex = [](char c) {
            if (c >= '0' && c <= '9') return c - '0';
            if (c >= 'a' && c <= 'f') return c - 'a' + 10;
            if (c >= 'A' && c <= 'F') return c - 'A' + 10;
            return -1;
        };
        if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
            out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

}  // namespace

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
        (void)policy.check(model.parent_path() / decoded_uri(name));
    }
}

}  // namespace zraster::io
