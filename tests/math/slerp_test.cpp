#include <zraster/rotation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>

#include "math/rotation_test_util.hpp"

namespace zraster {
namespace {

using test::kPi;
using test::max_difference;

glm::quat random_unit_quat(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    glm::quat q;
    q.x = n(rng), q.y = n(rng), q.z = n(rng), q.w = n(rng);
    return glm::normalize(q);
}

// The rotation angle (in [0, pi]) that takes a to b.
float angle_between(const glm::quat& a, const glm::quat& b) {
    return quat_to_axis_angle(glm::inverse(a) * b).angle;
}

TEST(Slerp, StaysUnitAndOrthonormalWithConstantAngularSpeed) {
    std::mt19937 rng(21);
    for (int trial = 0; trial < 200; ++trial) {
        const glm::quat a = random_unit_quat(rng), b = random_unit_quat(rng);
        const float total = angle_between(a, b);
        for (int step = 0; step <= 20; ++step) {
            const float t = float(step) / 20.0f;
            const glm::quat q = slerp(a, b, t);
            EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
            // GLM's cast does not renormalize: the matrix is a rotation only if q is unit.
            const glm::mat3 r = glm::mat3_cast(q);
            EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f);
            EXPECT_LT(max_difference(glm::transpose(r) * r, glm::mat3(1.0f)), 1e-5f);
            EXPECT_NEAR(angle_between(a, q), t * total, 1e-4f) << "t = " << t;
            EXPECT_NEAR(angle_between(q, b), (1.0f - t) * total, 1e-4f) << "t = " << t;
        }
    }
}

TEST(Slerp, EndpointsAreTheInputs) {
    std::mt19937 rng(22);
    const glm::quat a = random_unit_quat(rng), b = random_unit_quat(rng);
    EXPECT_LT(angle_between(slerp(a, b, 0.0f), a), 1e-3f);
    EXPECT_LT(angle_between(slerp(a, b, 1.0f), b), 1e-3f);
}

TEST(Slerp, TakesTheShorterArc) {
    std::mt19937 rng(23);
    for (int trial = 0; trial < 100; ++trial) {
        const glm::quat a = random_unit_quat(rng), b = random_unit_quat(rng);
        const float total = angle_between(a, b);  // in [0, pi]: the shorter way round
        for (float t : {0.25f, 0.5f, 0.75f}) {
            const glm::quat q = slerp(a, b, t), q_negated = slerp(a, -b, t);
            // b and -b are the same rotation, so they interpolate to the same rotation...
            EXPECT_LT(max_difference(quat_to_matrix(q), quat_to_matrix(q_negated)), 1e-5f);
            // ...along the arc of angle total, not 2 pi - total.
            EXPECT_NEAR(angle_between(a, q_negated), t * total, 1e-4f);
        }
    }
    // A concrete case: from 0 to 270 degrees about z is 90 degrees the other way.
    const glm::quat a = axis_angle_to_quat({{0, 0, 1}, 0.0f});
    glm::quat b;
    b.w = std::cos(3.0f * kPi / 4.0f), b.x = 0.0f, b.y = 0.0f, b.z = std::sin(3.0f * kPi / 4.0f);
    const glm::vec3 x = quat_to_matrix(slerp(a, b, 0.5f)) * glm::vec3(1, 0, 0);
    EXPECT_NEAR(x.x, std::cos(-kPi / 4), 1e-6f);
    EXPECT_NEAR(x.y, std::sin(-kPi / 4), 1e-6f);
}

TEST(Slerp, NearlyParallelInputsStayUnit) {
    const glm::quat a = axis_angle_to_quat({{0, 1, 0}, 0.5f});
    const glm::quat b = axis_angle_to_quat({{0, 1, 0}, 0.5f + 1e-6f});
    for (float t : {0.0f, 0.3f, 1.0f}) EXPECT_NEAR(glm::length(slerp(a, b, t)), 1.0f, 1e-6f);
    EXPECT_LT(angle_between(slerp(a, a, 0.5f), a), 1e-6f);
}

TEST(LerpMatrices, IsNotARotationHalfWayBetween120DegreesApart) {
    const glm::mat3 a = axis_angle_to_matrix({{0, 0, 1}, 0.0f});
    const glm::mat3 b = axis_angle_to_matrix({{0, 0, 1}, 2.0f * kPi / 3.0f});
    const glm::mat3 m = lerp_matrices(a, b, 0.5f);
    // Half of (I + Rz(120)): the x and y columns shrink to length 1/2, the determinant to 1/4.
    EXPECT_GT(std::abs(glm::determinant(m) - 1.0f), 0.1f);
    EXPECT_GT(std::abs(glm::length(m[0]) - 1.0f), 0.1f);
    EXPECT_NEAR(glm::determinant(m), 0.25f, 1e-6f);
    // Slerp between the same two rotations is the 60 degree rotation.
    const glm::quat q = slerp(matrix_to_quat(a), matrix_to_quat(b), 0.5f);
    EXPECT_LT(max_difference(quat_to_matrix(q), axis_angle_to_matrix({{0, 0, 1}, kPi / 3.0f})),
              1e-6f);
    // The endpoints are the inputs.
    EXPECT_EQ(lerp_matrices(a, b, 0.0f), a);
    EXPECT_EQ(lerp_matrices(a, b, 1.0f), b);
}

}  // namespace
}  // namespace zraster
