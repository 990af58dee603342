// Materials' alpha for the algorithms that keep subsample masks (the A-buffer, multisampling):
// one alpha per fragment (polygon x pixel), taken where the fragment is shaded.
//
// A fragment covering every sample of its pixel takes its alpha at the pixel center, as render()
// does (SurfaceShader::alpha: the same texture coordinates and derivatives, so the same alpha bit
// for bit for an unsplit polygon); a partial one at the centroid of the samples it covers (always
// inside the convex polygon), where it is shaded. Mask fragments are kept whole or dropped whole
// by that one alpha, as graphics hardware's multisampling tests alpha once per pixel (without
// alpha-to-coverage): cut-out edges inside a polygon are aliased at pixel size, the polygon's own
// edges keep their subsample coverage.
#pragma once
#include <zraster/material.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "visibility/surface_shader.hpp"

namespace zraster::visibility_detail {

// The center of the samples of `mask` (bit j * n + i is sample (i, j) of the n x n grid) in
// pixel (px, py), in window pixels.
glm::dvec2 mask_centroid(std::uint64_t mask, int n, int px, int py);

class FragmentAlphas {
  public:
    // `shader` and `polygons` must outlive this.
    FragmentAlphas(const SurfaceShader& shader, std::span<const ScreenPolygon> polygons,
                   int samples_per_side);

    // The alpha of polygon `polygon`'s fragment covering `mask` of pixel (px, py), in [0, 1]:
    // Opaque 1; Mask 1 where the alpha passes the test, else 0; Blend clamped into [0, 1] (NaN:
    // 0). `prepared` is the polygon prepared by the shader.
    float at(const SurfaceShader::Prepared& prepared, std::uint32_t polygon, std::uint64_t mask,
             int px, int py) const;
    AlphaMode mode(std::uint32_t polygon) const { return modes_[polygon]; }
    bool blended(std::uint32_t polygon) const { return modes_[polygon] == AlphaMode::Blend; }
    // Whether some polygon is not opaque.
    bool any() const { return any_; }

  private:
    const SurfaceShader& shader_;
    std::span<const ScreenPolygon> polygons_;
    int n_;
    std::uint64_t full_;
    std::vector<AlphaMode> modes_;
    std::vector<float> constant_;  // the alpha of a polygon whose alpha does not vary, else -1
    bool any_ = false;
};

}  // namespace zraster::visibility_detail
