#include "io/gltf_image_uris.hpp"

#include <nlohmann/json.hpp>

#include "io/gltf_document.hpp"
#include "io/text_util.hpp"

namespace zraster::io {

std::vector<std::string> gltf_image_uri_warnings(const std::filesystem::path& path) {
    std::vector<std::string> out;
    const std::string text = gltf_document(path);
    if (text.empty()) return out;
    const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
    const auto images = document.is_object() ? document.find("images") : document.end();
    if (images == document.end() || !images->is_array()) return out;
    for (std::size_t i = 0; i < images->size(); ++i) {
        const nlohmann::json& image = (*images)[i];
        if (!image.is_object() || !image.contains("uri") || !image["uri"].is_string()) continue;
        const std::string uri = image["uri"].get<std::string>();
        const std::string label = "image " + std::to_string(i) + "'s uri '" +
                                  one_line(uri.substr(0, 60)) + (uri.size() > 60 ? "...'" : "'");
        if (uri.empty()) {
            out.push_back(label + " is empty: its texture is not used");
        } else if (uri.starts_with("data:")) {
            const std::size_t comma = uri.find(',');
            if (comma == std::string::npos ||
                uri.compare(comma - std::min<std::size_t>(comma, 7), 7, ";base64") != 0)
                out.push_back(label +
                              " is not a base64 data URI (data:<type>;base64,<data>): its "
                              "texture is not used");
            else if (comma + 1 == uri.size())
                out.push_back(label + " holds no data: its texture is not used");
        }
    }
    return out;
}

}  // namespace zraster::io
