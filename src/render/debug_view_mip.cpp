// The mip view's level (debug_view_mip.hpp).
#include "render/debug_view_mip.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace zraster::detail {
namespace {

struct ClipCorners {
    std::array<glm::dvec4, 3> clip;
    std::array<glm::dvec2, 3> uv;
};

// Texture coordinates at the pixel center (px + 0.5, py + 0.5): the weights w of the corners
// whose clip-space combination projects there solve sum w_k (x_k - X w_k) = 0 and
// sum w_k (y_k - Y w_k) = 0 (X, Y in normalized device coordinates), so they are the cross
// product of those two rows, normalized to sum 1. Exact perspective-correct interpolation.
std::optional<glm::dvec2> uv_at(const ClipCorners& t, int width, int height, double px, double py) {
    const double x = (px + 0.5) * 2.0 / width - 1.0;
    const double y = 1.0 - (py + 0.5) * 2.0 / height;
    glm::dvec3 a, b;
    for (int k = 0; k < 3; ++k) {
        a[k] = t.clip[std::size_t(k)].x - x * t.clip[std::size_t(k)].w;
        b[k] = t.clip[std::size_t(k)].y - y * t.clip[std::size_t(k)].w;
    }
    const glm::dvec3 w = glm::cross(a, b);
    const double sum = w.x + w.y + w.z;
    if (!(std::abs(sum) > 0.0)) return std::nullopt;
    return (t.uv[0] * w.x + t.uv[1] * w.y + t.uv[2] * w.z) / sum;
}

}  // namespace

std::optional<float> sampled_mip_level(const Frame& frame, const FrameInstance& instance,
                                       std::uint32_t primitive, int px, int py) {
    if (!instance.textured || !instance.material->base_color_texture) return std::nullopt;
    const Texture& texture = *instance.material->base_color_texture;
    const RenderOptions& options = *frame.options;
    if (options.texture_filter != TextureFilter::Trilinear) return 0.0f;
    ClipCorners t;
    const glm::dmat4 mvp(instance.mvp);
    for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t v = instance.mesh->index(std::size_t(primitive) * 3 + k);
        t.clip[k] = mvp * glm::dvec4(glm::dvec3(instance.mesh->position(v)), 1.0);
        t.uv[k] = glm::dvec2(instance.mesh->uv(v));
    }
    const int width = options.width, height = options.height;
    const auto at = uv_at(t, width, height, px, py);
    const auto right = uv_at(t, width, height, px + 1, py);
    const auto below = uv_at(t, width, height, px, py + 1);
    if (!at || !right || !below) return 0.0f;
    const float lod = texture.level_of_detail(glm::vec2(*right - *at), glm::vec2(*below - *at));
    if (!std::isfinite(lod)) return 0.0f;
    return std::clamp(lod, 0.0f, float(texture.levels() - 1));
}

}  // namespace zraster::detail
