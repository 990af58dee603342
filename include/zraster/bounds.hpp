// Axis-aligned bounding boxes and bounding spheres.
#pragma once
#include <glm/glm.hpp>
#include <zraster/export.hpp>

#include <limits>
#include <span>

namespace zraster {

struct ZRASTER_API Bounds3f {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void extend(const Bounds3f& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    glm::vec3 center() const { return (lo + hi) * 0.5f; }
    glm::vec3 extent() const { return hi - lo; }

    // The box of the eight transformed corners (conservative bounds of the transformed box).
    Bounds3f transformed(const glm::mat4& m) const;

    static Bounds3f of(std::span<const glm::vec3> points);
};

struct BoundingSphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
};

// Center = center of the axis-aligned box, radius = max distance of a point from it, computed in
// double (as docs/bench-scenes.md frames its scenes).
ZRASTER_API BoundingSphere bounding_sphere(std::span<const glm::vec3> points);

}  // namespace zraster
