#include <zraster/bounds.hpp>

#include <algorithm>
#include <cmath>

namespace zraster {

Bounds3f Bounds3f::transformed(const glm::mat4& m) const {
    Bounds3f out;
    if (empty()) return out;
    // The transformed box is not axis-aligned; the box of its eight corners contains it.
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p{(corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                          (corner & 4) ? hi.z : lo.z};
        const glm::vec4 q = m * glm::vec4(p, 1.0f);
        out.extend(glm::vec3(q) / q.w);
    }
    return out;
}

Bounds3f Bounds3f::of(std::span<const glm::vec3> points) {
    Bounds3f b;
    for (const glm::vec3& p : points) b.extend(p);
    return b;
}

BoundingSphere bounding_sphere(std::span<const glm::vec3> points) {
    BoundingSphere s;
    if (points.empty()) return s;
    const Bounds3f box = Bounds3f::of(points);
    // In double, as docs/bench-scenes.md frames its scenes: the camera must match the reference's.
    s.center = (glm::dvec3(box.lo) + glm::dvec3(box.hi)) / 2.0;
    double r2 = 0.0;
    for (const glm::vec3& p : points) {
        const glm::dvec3 d = glm::dvec3(p) - s.center;
        r2 = std::max(r2, glm::dot(d, d));
    }
    s.radius = std::sqrt(r2);
    return s;
}

}  // namespace zraster
