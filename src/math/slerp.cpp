// Spherical linear interpolation of unit quaternions: Shoemake 1985, "Animating Rotation with
// Quaternion Curves" (SIGGRAPH '85). Constant angular speed along the great arc from a to b.
#include <zraster/rotation.hpp>

#include <cmath>

namespace zraster {

glm::quat slerp(const glm::quat& a, const glm::quat& b, float t) {
    glm::dquat p = glm::normalize(glm::dquat(a)), q = glm::normalize(glm::dquat(b));
    // q and -q are the same rotation; the one in p's hemisphere gives the shorter arc.
    if (glm::dot(p, q) < 0.0) q = -q;
    // The angle between them from atan2 of the chord lengths: exact at both ends, where
    // acos(dot) loses half of the digits.
    const double theta = 2.0 * std::atan2(glm::length(p - q), glm::length(p + q));
    const double s = std::sin(theta), td = double(t);
    glm::dquat r;
    if (s < 1e-6) {
        // Nearly parallel: sin(t theta) / sin(theta) -> t, slerp and lerp agree to O(theta^2).
        r = p * (1.0 - td) + q * td;
    } else {
        r = p * (std::sin((1.0 - td) * theta) / s) + q * (std::sin(td * theta) / s);
    }
    return glm::quat(glm::normalize(r));
}

glm::mat3 lerp_matrices(const glm::mat3& a, const glm::mat3& b, float t) {
    return a * (1.0f - t) + b * t;
}

}  // namespace zraster
