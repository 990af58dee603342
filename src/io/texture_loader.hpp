// Textures of a loaded model (base color, opacity): embedded ones (glTF binary, data URIs) and
// image files beside the model. Each image is decoded once and shared by the materials that use
// it.
#pragma once
#include <zraster/load.hpp>
#include <zraster/material.hpp>
#include <zraster/texture.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/reference_policy.hpp"

struct aiMaterial;
struct aiScene;

namespace zraster::io {

class TextureLoader {
  public:
    // Problems are appended to `warnings` (as causes, without the model's name). Image files
    // are read only where `policy` allows (the model's folder by default). The textures' sizes
    // and bytes stay within the options' max_texture_side and max_texture_bytes.
    TextureLoader(const aiScene& scene, const std::filesystem::path& model_path,
                  ReferencePolicy policy, const LoadOptions& options,
                  std::vector<std::string>& warnings);

    // The texture a material refers to, or null (with a warning) when it is missing or
    // unreadable: the material's color is used then.
    std::shared_ptr<const Texture> load(const std::string& reference);

    // The textures `source` refers to, into `material` (converted from it): the base-color
    // texture and, unless alpha is ignored (AlphaMode::Opaque), the opacity texture.
    void attach_textures(const aiMaterial& source, Material& material);

    // An opacity image (MTL map_d) as Material::opacity_texture reads it, in its red channel:
    // an image with translucent texels (a PNG with an alpha channel) gives its alpha, any other
    // its red (a grey image's grey). Null when the image is `base_color` and has translucent
    // texels: that alpha already counts once as the base-color texture's.
    std::shared_ptr<const Texture> load_opacity(const std::string& reference,
                                                const Texture* base_color);

  private:
    std::shared_ptr<const Texture> load_embedded(const std::string& reference);
    std::shared_ptr<const Texture> load_external(const std::string& reference);
    // False, with a warning, when decoding a width x height image would exceed the budget.
    bool may_decode(const std::string& reference, std::uint64_t width, std::uint64_t height);
    // The texture of decoded pixels, reduced to max_texture_side, if it fits in what is left of
    // the budget; else null with a warning.
    std::shared_ptr<const Texture> admit(const std::string& reference, int width, int height,
                                         std::span<const std::uint8_t> rgba);

    const aiScene& scene_;
    std::filesystem::path model_dir_;
    ReferencePolicy policy_;
    int max_side_;
    std::size_t max_bytes_;
    std::size_t used_bytes_ = 0;
    std::vector<std::string>& warnings_;
    std::map<std::string, std::shared_ptr<const Texture>> cache_;  // null entries: warned once
    // Images with translucent texels and their alpha as an opacity texture (null: over budget).
    std::map<const Texture*, std::shared_ptr<const Texture>> alpha_as_red_;
};

}  // namespace zraster::io
