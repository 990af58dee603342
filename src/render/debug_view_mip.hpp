// The mip view's level: the level of detail the trilinear filter samples at a pixel, from the
// same derivative rule as the shader (texture_lookup in shade/surface_shading.hpp: the
// coordinates one pixel over in x and in y, minus those at the pixel), with the pixel's
// perspective-correct weights computed from the triangle's clip-space corners.
#pragma once
#include <cstdint>
#include <optional>

#include "render/frame.hpp"

namespace zraster::detail {

// The level at pixel (px, py) of triangle `primitive` of the frame instance `instance`:
// Texture::level_of_detail clamped to the texture's levels (0 with a filter other than
// trilinear); nullopt where the instance shows no base-color texture.
std::optional<float> sampled_mip_level(const Frame& frame, const FrameInstance& instance,
                                       std::uint32_t primitive, int px, int py);

}  // namespace zraster::detail
