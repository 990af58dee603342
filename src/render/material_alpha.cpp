// See material_alpha.hpp.
#include "render/material_alpha.hpp"

#include <cmath>

namespace zraster::detail {

AlphaMode effective_alpha_mode(const Material& material, bool textured, float least_vertex_alpha,
                               const RenderOptions& options) {
    if (options.alpha_mode == MaterialAlpha::Opaque || material.alpha_mode == AlphaMode::Opaque)
        return AlphaMode::Opaque;
    const bool texture_alpha =
        textured && ((material.base_color_texture != nullptr &&
                      material.base_color_texture->has_translucent_texels()) ||
                     material.opacity_texture != nullptr);
    // (A NaN opacity counts as 1, as the A-buffer takes it.)
    const float opacity = std::isnan(material.opacity) ? 1.0f : material.opacity;
    const float least = least_vertex_alpha < 1.0f ? opacity * least_vertex_alpha : opacity;
    if (material.alpha_mode == AlphaMode::Mask)
        return texture_alpha || least < material.alpha_cutoff ? AlphaMode::Mask : AlphaMode::Opaque;
    return texture_alpha || least < 1.0f ? AlphaMode::Blend : AlphaMode::Opaque;
}

}  // namespace zraster::detail
