// Helpers of the rotation tests (Euler angles, quaternions).
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace zraster::test {

inline constexpr float kPi = std::numbers::pi_v<float>;

// The largest difference between two matrices' elements.
inline float max_difference(const glm::mat3& a, const glm::mat3& b) {
    float d = 0.0f;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
    return d;
}

}  // namespace zraster::test
