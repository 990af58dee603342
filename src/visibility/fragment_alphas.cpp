// See fragment_alphas.hpp.
#include "visibility/fragment_alphas.hpp"

namespace zraster::visibility_detail {
namespace {

float clamp_alpha(float v) {
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // (NaN: 0), as render()'s blend pass
}

}  // namespace

glm::dvec2 mask_centroid(std::uint64_t mask, int n, int px, int py) {
    double x = 0.0, y = 0.0;
    int count = 0;
    for (int s = 0; s < n * n; ++s)
        if (mask >> s & 1) {
            x += (s % n + 0.5) / n;
            y += (s / n + 0.5) / n;
            ++count;
        }
    if (count == 0) return {px + 0.5, py + 0.5};
    return {px + x / count, py + y / count};
}

FragmentAlphas::FragmentAlphas(const SurfaceShader& shader, std::span<const ScreenPolygon> polygons,
                               int samples_per_side)
    : shader_(shader), polygons_(polygons), n_(samples_per_side) {
    const int samples = n_ * n_;
    full_ = samples == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << samples) - 1;
    modes_.resize(polygons.size());
    constant_.resize(polygons.size());
    for (std::size_t i = 0; i < polygons.size(); ++i) {
        const std::int32_t instance = polygons[i].instance;
        const AlphaMode mode = shader.alpha_mode(instance);
        modes_[i] = mode;
        any_ |= mode != AlphaMode::Opaque;
        float constant = -1.0f;
        if (mode == AlphaMode::Opaque) {
            constant = 1.0f;
        } else if (!shader.alpha_varies(instance)) {
            const float a = shader.constant_alpha(instance);
            constant = mode == AlphaMode::Mask
                           ? (shader.passes_alpha_test(instance, a) ? 1.0f : 0.0f)
                           : clamp_alpha(a);
        }
        constant_[i] = constant;
    }
}

float FragmentAlphas::at(const SurfaceShader::Prepared& prepared, std::uint32_t polygon,
                         std::uint64_t mask, int px, int py) const {
    if (constant_[polygon] >= 0.0f) return constant_[polygon];
    const glm::dvec2 point = mask_centroid(mask, n_, px, py);
    const float a = shader_.alpha(prepared, px, py, mask == full_, point.x, point.y);
    if (modes_[polygon] == AlphaMode::Mask)
        return shader_.passes_alpha_test(polygons_[polygon].instance, a) ? 1.0f : 0.0f;
    return clamp_alpha(a);
}

}  // namespace zraster::visibility_detail
