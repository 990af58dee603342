#include "io/texture_loader.hpp"

#include "io/text_util.hpp"

#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include <assimp/scene.h>
#include <stb/stb_image.h>

#include <cctype>
#include <climits>
#include <optional>

namespace zraster::io {

namespace {

std::shared_ptr<const Texture> make_texture(int width, int height,
                                            std::span<const std::uint8_t> rgba) {
    return std::make_shared<const Texture>(width, height, rgba);
}

// %XX escapes, as glTF URIs may carry them ("my%20texture.png").
std::optional<std::string> percent_decoded(const std::string& s) {
    if (s.find('%') == std::string::npos) return std::nullopt;
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size() &&
            std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
            out.push_back(static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(s[i]);
        }
    }
    return out;
}

}  // namespace

TextureLoader::TextureLoader(const aiScene& scene, const std::filesystem::path& model_path,
                             ReferencePolicy policy, std::vector<std::string>& warnings)
    : scene_(scene),
      model_dir_(model_path.parent_path()),
      policy_(std::move(policy)),
      warnings_(warnings) {}

std::shared_ptr<const Texture> TextureLoader::load(const std::string& reference) {
    if (scene_.GetEmbeddedTexture(reference.c_str()) != nullptr) return load_embedded(reference);
    return load_external(reference);
}

std::shared_ptr<const Texture> TextureLoader::load_embedded(const std::string& reference) {
    const aiTexture* texture = scene_.GetEmbeddedTexture(reference.c_str());
    const std::string key = "embedded:" + std::to_string(reinterpret_cast<std::uintptr_t>(texture));
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;

    std::shared_ptr<const Texture> result;
    try {
        if (texture->mHeight == 0) {
            // Compressed (PNG, JPEG, ...): mWidth is the byte count.
            if (texture->mWidth > static_cast<unsigned>(INT_MAX))
                throw std::invalid_argument("embedded image too large");
            stbi_set_flip_vertically_on_load_thread(0);
            int w = 0, h = 0, channels = 0;
            std::unique_ptr<stbi_uc, decltype(&stbi_image_free)> pixels(
                stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(texture->pcData),
                                      static_cast<int>(texture->mWidth), &w, &h, &channels, 4),
                &stbi_image_free);
            if (!pixels) {
                const char* reason = stbi_failure_reason();
                throw std::invalid_argument(reason ? one_line(reason) : "unknown error");
            }
            result = make_texture(w, h, {pixels.get(), static_cast<std::size_t>(w) * h * 4});
        } else {
            // Raw aiTexel, stored b, g, r, a.
            const std::size_t count = std::size_t{texture->mWidth} * texture->mHeight;
            if (texture->mWidth > static_cast<unsigned>(INT_MAX) ||
                texture->mHeight > static_cast<unsigned>(INT_MAX))
                throw std::invalid_argument("embedded image too large");
            std::vector<std::uint8_t> rgba(count * 4);
            for (std::size_t i = 0; i < count; ++i) {
                const aiTexel& t = texture->pcData[i];
                rgba[4 * i] = t.r;
                rgba[4 * i + 1] = t.g;
                rgba[4 * i + 2] = t.b;
                rgba[4 * i + 3] = t.a;
            }
            result = make_texture(static_cast<int>(texture->mWidth),
                                  static_cast<int>(texture->mHeight), rgba);
        }
    } catch (const std::exception& e) {
        warnings_.push_back("embedded texture '" + reference + "' cannot be decoded (" + e.what() +
                            "), using the material color");
    }
    cache_[key] = result;
    return result;
}

std::shared_ptr<const Texture> TextureLoader::load_external(const std::string& reference) {
    // Windows exporters write ".\tex.jpg" or "C:\models\tex.jpg"; try the path as written
    // (relative to the model), decoded from a URI, and finally just the file name beside the
    // model, which is where copied models keep their textures.
    std::string portable = reference;
    for (char& c : portable)
        if (c == '\\') c = '/';
    if (portable.starts_with("file://")) portable.erase(0, 7);
    std::vector<std::filesystem::path> candidates;
    std::vector<std::string> spellings{portable};
    if (auto decoded = percent_decoded(portable)) spellings.push_back(*decoded);
    for (const std::string& s : spellings) {
        const std::filesystem::path p(s);
        candidates.push_back(p.is_absolute() ? p : model_dir_ / p);
        candidates.push_back(model_dir_ / p.filename());
    }

    std::filesystem::path found;
    std::string refused;  // the first candidate the policy refused, with the reason
    for (const auto& c : candidates) {
        const ReferencePolicy::Check check = policy_.check(c);
        if (check.verdict == ReferencePolicy::Verdict::Readable) {
            found = c;
            break;
        }
        if (check.verdict == ReferencePolicy::Verdict::Refused && refused.empty())
            refused = c.string() + " " + check.reason;
    }
    std::error_code ec;
    const std::string key = found.empty() ? "missing:" + reference
                                          : std::filesystem::weakly_canonical(found, ec).string();
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;

    std::shared_ptr<const Texture> result;
    if (found.empty() && !refused.empty()) {
        warnings_.push_back("texture '" + reference + "' not read: " + refused +
                            ", using the material color (" + ReferencePolicy::how_to_allow() + ")");
    } else if (found.empty()) {
        warnings_.push_back("texture '" + reference + "' not found, using the material color");
    } else {
        try {
            const ImageRGBA8 image = read_image_rgba8(found);
            result = make_texture(image.width, image.height, image.rgba);
        } catch (const InputError& e) {
            warnings_.push_back("texture '" + reference + "' cannot be read (" + e.cause() +
                                "), using the material color");
        } catch (const std::exception& e) {
            warnings_.push_back("texture '" + reference + "' cannot be used (" + e.what() +
                                "), using the material color");
        }
    }
    cache_[key] = result;
    return result;
}

}  // namespace zraster::io
