#include "io/texture_loader.hpp"

#include "io/assimp_material.hpp"
#include "io/image_decode.hpp"
#include "io/read_file.hpp"
#include "io/text_util.hpp"
#include "io/uri_escapes.hpp"

#include <zraster/error.hpp>
#include <zraster/image_io.hpp>

#include <assimp/scene.h>
#include <stb/stb_image.h>

#include <cctype>
#include <climits>
#include <optional>

namespace zraster::io {

namespace {

// "3 MiB", "240 KiB", "900 bytes".
std::string byte_size(std::uint64_t bytes) {
    if (bytes >= (std::uint64_t{1} << 20))
        return std::to_string((bytes + (1u << 19)) >> 20) + " MiB";
    if (bytes >= 1024) return std::to_string((bytes + 512) >> 10) + " KiB";
    return std::to_string(bytes) + " bytes";
}

std::size_t texture_bytes(const Texture& texture) {
    std::size_t bytes = 0;
    for (int level = 0; level < texture.levels(); ++level)
        bytes +=
            std::size_t(texture.level_width(level)) * std::size_t(texture.level_height(level)) * 4;
    return bytes;
}

constexpr const char* kBudgetOption =
    "LoadOptions::max_texture_bytes; the command's --max-texture-memory";

}  // namespace

TextureLoader::TextureLoader(const aiScene& scene, const std::filesystem::path& model_path,
                             ReferencePolicy policy, const LoadOptions& options,
                             std::vector<std::string>& warnings)
    : scene_(scene),
      model_dir_(model_path.parent_path()),
      policy_(std::move(policy)),
      max_side_(options.max_texture_side),
      max_bytes_(options.max_texture_bytes),
      warnings_(warnings) {}

bool TextureLoader::may_decode(const std::string& reference, std::uint64_t width,
                               std::uint64_t height) {
    // Against what is left of the budget, not all of it: a model of many large textures would
    // otherwise decode each one (up to the whole budget) only to drop it.
    const std::uint64_t decoded = width * height * 4;
    const std::uint64_t left = max_bytes_ - std::min<std::uint64_t>(used_bytes_, max_bytes_);
    if (decoded <= left) return true;
    warnings_.push_back("texture '" + reference + "' is " + std::to_string(width) + "x" +
                        std::to_string(height) + " (" + byte_size(decoded) + " decoded), more " +
                        (used_bytes_ == 0
                             ? "than the textures' budget of " + byte_size(max_bytes_)
                             : "than the " + byte_size(left) + " left of the textures' budget of " +
                                   byte_size(max_bytes_)) +
                        ": using the material color (" + kBudgetOption + ")");
    return false;
}

std::shared_ptr<const Texture> TextureLoader::admit(const std::string& reference, int width,
                                                    int height,
                                                    std::span<const std::uint8_t> rgba) {
    auto texture = std::make_shared<const Texture>(width, height, rgba, max_side_);
    const std::size_t bytes = texture_bytes(*texture);
    if (bytes > max_bytes_ - std::min(used_bytes_, max_bytes_)) {
        warnings_.push_back(
            "texture '" + reference + "' not kept: the model's textures would take " +
            byte_size(used_bytes_ + bytes) + ", more than their budget of " +
            byte_size(max_bytes_) + "; using the material color (" + kBudgetOption + ")");
        return nullptr;
    }
    used_bytes_ += bytes;
    if (texture->width() != width || texture->height() != height)
        warnings_.push_back(
            "texture '" + reference + "' is " + std::to_string(width) + "x" +
            std::to_string(height) + ", reduced to " + std::to_string(texture->width()) + "x" +
            std::to_string(texture->height()) + " (at most " + std::to_string(max_side_) +
            " texels a side: LoadOptions::max_texture_side; the command's "
            "--max-texture-side)");
    return texture;
}

std::shared_ptr<const Texture> TextureLoader::load(const std::string& reference) {
    if (scene_.GetEmbeddedTexture(reference.c_str()) != nullptr) return load_embedded(reference);
    return load_external(reference);
}

void TextureLoader::attach_textures(const aiMaterial& source, Material& material) {
    if (auto reference = base_color_texture_reference(source))
        material.base_color_texture = load(*reference);
    if (material.alpha_mode == AlphaMode::Opaque) return;
    if (auto reference = opacity_texture_reference(source))
        material.opacity_texture = load_opacity(*reference, material.base_color_texture.get());
}

std::shared_ptr<const Texture> TextureLoader::load_opacity(const std::string& reference,
                                                           const Texture* base_color) {
    std::shared_ptr<const Texture> image = load(reference);
    if (!image || !image->has_translucent_texels()) return image;
    if (image.get() == base_color) return nullptr;
    if (auto it = alpha_as_red_.find(image.get()); it != alpha_as_red_.end()) return it->second;
    // From the image as kept (level 0, already within max_texture_side), so the size is the same.
    const std::span<const std::uint8_t> rgba = image->level_rgba(0);
    std::vector<std::uint8_t> alpha(rgba.size());
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        alpha[i] = alpha[i + 1] = alpha[i + 2] = rgba[i + 3];
        alpha[i + 3] = 255;
    }
    std::shared_ptr<const Texture> result =
        admit(reference, image->width(), image->height(), alpha);
    alpha_as_red_[image.get()] = result;
    return result;
}

std::shared_ptr<const Texture> TextureLoader::load_embedded(const std::string& reference) {
    const aiTexture* texture = scene_.GetEmbeddedTexture(reference.c_str());
    const std::string key = "embedded:" + std::to_string(reinterpret_cast<std::uintptr_t>(texture));
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;

    std::shared_ptr<const Texture> result;
    try {
        if (texture->mHeight == 0) {
            // Compressed (PNG, JPEG, ...): mWidth is the byte count.
            const std::span<const std::uint8_t> bytes(
                reinterpret_cast<const std::uint8_t*>(texture->pcData), texture->mWidth);
            const std::optional<ImageSize> size = encoded_image_size(bytes);
            if (!size ||
                may_decode(reference, std::uint64_t(size->width), std::uint64_t(size->height))) {
                const ImageRGBA8 image = decode_image_rgba8(bytes, reference);
                result = admit(reference, image.width, image.height, image.rgba);
            }
        } else {
            // Raw aiTexel, stored b, g, r, a.
            const std::size_t count = std::size_t{texture->mWidth} * texture->mHeight;
            if (texture->mWidth > static_cast<unsigned>(INT_MAX) ||
                texture->mHeight > static_cast<unsigned>(INT_MAX))
                throw std::invalid_argument("embedded image too large");
            if (!may_decode(reference, texture->mWidth, texture->mHeight)) {
                cache_[key] = nullptr;
                return nullptr;
            }
            std::vector<std::uint8_t> rgba(count * 4);
            for (std::size_t i = 0; i < count; ++i) {
                const aiTexel& t = texture->pcData[i];
                rgba[4 * i] = t.r;
                rgba[4 * i + 1] = t.g;
                rgba[4 * i + 2] = t.b;
                rgba[4 * i + 3] = t.a;
            }
            result = admit(reference, static_cast<int>(texture->mWidth),
                           static_cast<int>(texture->mHeight), rgba);
        }
    } catch (const InputError& e) {
        warnings_.push_back("embedded texture '" + reference + "' cannot be decoded (" + e.cause() +
                            "), using the material color");
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
    std::string refused;  // the first candidate the policy refused, with the reason and advice
    for (const auto& c : candidates) {
        const ReferencePolicy::Check check = policy_.check(c);
        if (check.verdict == ReferencePolicy::Verdict::Readable) {
            found = c;
            break;
        }
        if (check.verdict == ReferencePolicy::Verdict::Refused && refused.empty())
            refused =
                c.string() + " " + check.reason + ", using the material color" + check.advice();
    }
    std::error_code ec;
    const std::string key = found.empty() ? "missing:" + reference
                                          : std::filesystem::weakly_canonical(found, ec).string();
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;

    std::shared_ptr<const Texture> result;
    if (found.empty() && !refused.empty()) {
        warnings_.push_back("texture '" + reference + "' not read: " + refused);
    } else if (found.empty()) {
        warnings_.push_back("texture '" + reference + "' not found, using the material color");
    } else {
        try {
            // A file larger than the whole texture budget is not read at all: an image file
            // compresses its texels, so its decoded size would be past the budget too (a 3 GB
            // file was read whole before its size was looked at).
            std::error_code size_error;
            const std::uintmax_t file_bytes = std::filesystem::file_size(found, size_error);
            if (!size_error && file_bytes > max_bytes_)
                throw InputError(found.string(), "the file is " + byte_size(file_bytes) +
                                                     ", more than the textures' budget of " +
                                                     byte_size(max_bytes_) + " (" + kBudgetOption +
                                                     ")");
            const std::vector<std::uint8_t> bytes = read_file_bytes(found);
            const std::optional<ImageSize> size = encoded_image_size(bytes);
            if (!size ||
                may_decode(reference, std::uint64_t(size->width), std::uint64_t(size->height))) {
                const ImageRGBA8 image = decode_image_rgba8(bytes, found.string());
                result = admit(reference, image.width, image.height, image.rgba);
            }
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
