// Fragment shading of the forward path: interpolates the attributes a fragment needs and
// evaluates the instance's shading mode (flat, Gouraud, Phong).
#pragma once
#include "render/frame.hpp"

namespace zraster::detail {

struct ShadedFragment {
    glm::vec3 color;
    glm::vec3 normal;  // world space, facing the viewer side when two-sided lighting is on
};

// Barycentric weights of the ORIGINAL triangle's vertices at pixel (px, py).
inline glm::vec3 original_barycentrics(const RasterTriangle& t, int px, int py,
                                       Interpolation interpolation) {
    const glm::vec3 b = barycentrics(t.setup, px, py, interpolation);
    if (!t.clipped) return b;
    return b.x * t.weights[0] + b.y * t.weights[1] + b.z * t.weights[2];
}

template <class T>
T interpolate(const std::vector<T>& values, const std::array<std::uint32_t, 3>& v,
              const glm::vec3& b) {
    return values[v[0]] * b.x + values[v[1]] * b.y + values[v[2]] * b.z;
}

ShadedFragment shade_fragment(const Frame& frame, const RasterTriangle& t, int px, int py,
                              bool want_normal);

}  // namespace zraster::detail
