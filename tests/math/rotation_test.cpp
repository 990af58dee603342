#include <zraster/rotation.hpp>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>
#include <string>

#include "math/rotation_test_util.hpp"

namespace zraster {
namespace {

using test::kPi;
using test::max_difference;
constexpr EulerOrder kOrders[] = {EulerOrder::XYZ, EulerOrder::XZY, EulerOrder::YXZ,
                                  EulerOrder::YZX, EulerOrder::ZXY, EulerOrder::ZYX};

// The axes (0 = x) in the order they are applied, read from the enumerator's name.
std::string name_of(EulerOrder order) {
    switch (order) {
        case EulerOrder::XYZ:
            return "XYZ";
        case EulerOrder::XZY:
            return "XZY";
        case EulerOrder::YXZ:
            return "YXZ";
        case EulerOrder::YZX:
            return "YZX";
        case EulerOrder::ZXY:
            return "ZXY";
        case EulerOrder::ZYX:
            return "ZYX";
    }
    return "?";
}
int axis_applied(EulerOrder order, int step) {
    return name_of(order)[step] - 'X';
}

glm::mat3 glm_rotation(float angle, const glm::vec3& axis) {
    return glm::mat3(glm::rotate(glm::mat4(1.0f), angle, axis));
}

// q and -q are the same rotation.
float quat_distance(const glm::quat& a, const glm::quat& b) {
    return std::min(glm::length(glm::vec4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w)),
                    glm::length(glm::vec4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w)));
}

const glm::vec3 kUnit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

TEST(Euler, MatrixAppliesTheFirstAxisFirst) {
    for (EulerOrder order : kOrders) {
        glm::vec3 angles(0.3f, -1.1f, 2.2f);
        glm::mat3 expected(1.0f);
        for (int step = 0; step < 3; ++step) {
            const int axis = axis_applied(order, step);
            expected = glm_rotation(angles[axis], kUnit[axis]) * expected;
        }
        EXPECT_LT(max_difference(euler_to_matrix(angles, order), expected), 1e-6f)
            << name_of(order);
    }
    // Right-handed: 90 degrees about z takes x to y.
    const glm::vec3 x_rotated = euler_to_matrix({0.0f, 0.0f, kPi / 2}, EulerOrder::XYZ) * kUnit[0];
    EXPECT_NEAR(x_rotated.y, 1.0f, 1e-7f);
}

TEST(Euler, EveryOrderRoundTripsMatrixToEulerToMatrix) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> outer(-kPi, kPi),
        middle(-kPi / 2 + 0.01f, kPi / 2 - 0.01f);
    for (EulerOrder order : kOrders) {
        for (int trial = 0; trial < 500; ++trial) {
            glm::vec3 angles;
            angles[axis_applied(order, 0)] = outer(rng);
            angles[axis_applied(order, 1)] = middle(rng);
            angles[axis_applied(order, 2)] = outer(rng);
            const glm::mat3 m = euler_to_matrix(angles, order);
            const glm::vec3 back = matrix_to_euler(m, order);
            EXPECT_LT(max_difference(euler_to_matrix(back, order), m), 1e-5f) << name_of(order);
            // Away from the lock the triple is unique within these ranges.
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], angles[k], 2e-4f) << name_of(order);
        }
    }
}

TEST(Euler, NearGimbalLockStillRoundTrips) {
    // The matrix goes through float products with an unrelated rotation, as a caller's would, so
    // every entry carries rounding noise of about 1e-7. Near the lock the first and third angles
    // are then each known only to noise / cos(b); computed independently (both from atan2 of
    // entries of size cos(b)) their errors do not cancel and the matrix is off by up to 1e-3.
    const glm::mat3 noise = glm_rotation(1.234f, glm::normalize(glm::vec3(1, 2, 3)));
    for (EulerOrder order : kOrders) {
        for (float off : {1e-2f, 1e-3f, 1e-4f, 1e-5f, 0.0f}) {
            for (float sign : {1.0f, -1.0f}) {
                glm::vec3 angles;
                angles[axis_applied(order, 0)] = 0.8f;
                angles[axis_applied(order, 1)] = sign * (kPi / 2 - off);
                angles[axis_applied(order, 2)] = -2.5f;
                glm::mat3 m(1.0f);
                for (int step = 0; step < 3; ++step) {
                    const int axis = axis_applied(order, step);
                    m = glm_rotation(angles[axis], kUnit[axis]) * m;
                }
                m = noise * (glm::transpose(noise) * m);
                EXPECT_LT(max_difference(euler_to_matrix(matrix_to_euler(m, order), order), m),
                          1e-5f)
                    << name_of(order) << " off " << off;
            }
        }
    }
}

TEST(Euler, GimbalLockLosesADegreeOfFreedom) {
    // XYZ = Rz(c) Ry(b) Rx(a). At b = +90 degrees Ry maps the x axis to -z, so a rotation about x
    // before it equals one about -z after it: (a, 90, c) and (a + d, 90, c + d) are the same
    // rotation. At b = -90 the x axis goes to +z and the signs are opposite.
    const float a = 0.4f, c = -1.3f, d = 0.9f;
    const glm::mat3 up = euler_to_matrix({a, kPi / 2, c}, EulerOrder::XYZ);
    EXPECT_LT(max_difference(euler_to_matrix({a + d, kPi / 2, c + d}, EulerOrder::XYZ), up), 1e-5f);
    EXPECT_GT(max_difference(euler_to_matrix({a + d, kPi / 2, c - d}, EulerOrder::XYZ), up), 0.1f);
    const glm::mat3 down = euler_to_matrix({a, -kPi / 2, c}, EulerOrder::XYZ);
    EXPECT_LT(max_difference(euler_to_matrix({a + d, -kPi / 2, c - d}, EulerOrder::XYZ), down),
              1e-5f);
    EXPECT_GT(max_difference(euler_to_matrix({a + d, -kPi / 2, c + d}, EulerOrder::XYZ), down),
              0.1f);
    // Away from the lock the same change is a different rotation.
    EXPECT_GT(max_difference(euler_to_matrix({a + d, 1.0f, c + d}, EulerOrder::XYZ),
                             euler_to_matrix({a, 1.0f, c}, EulerOrder::XYZ)),
              0.1f);

    // The same holds for every order: one of the two sign choices leaves the matrix unchanged.
    for (EulerOrder order : kOrders) {
        for (float middle : {kPi / 2, -kPi / 2}) {
            const int i = axis_applied(order, 0), j = axis_applied(order, 1),
                      k = axis_applied(order, 2);
            glm::vec3 base, plus, minus;
            base[i] = a, base[j] = middle, base[k] = c;
            plus[i] = a + d, plus[j] = middle, plus[k] = c + d;
            minus[i] = a + d, minus[j] = middle, minus[k] = c - d;
            const glm::mat3 m = euler_to_matrix(base, order);
            const float dp = max_difference(euler_to_matrix(plus, order), m);
            const float dm = max_difference(euler_to_matrix(minus, order), m);
            EXPECT_LT(std::min(dp, dm), 1e-5f) << name_of(order);
            EXPECT_GT(std::max(dp, dm), 0.1f) << name_of(order);

            // matrix_to_euler sets the first angle to 0 and reproduces the matrix.
            const glm::vec3 back = matrix_to_euler(m, order);
            EXPECT_EQ(back[i], 0.0f) << name_of(order);
            EXPECT_NEAR(back[j], middle, 1e-3f) << name_of(order);
            EXPECT_LT(max_difference(euler_to_matrix(back, order), m), 1e-5f) << name_of(order);
        }
    }
}

TEST(Euler, QuaternionAgreesWithMatrix) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> angle(-kPi, kPi);
    for (EulerOrder order : kOrders) {
        for (int trial = 0; trial < 100; ++trial) {
            const glm::vec3 angles(angle(rng), angle(rng), angle(rng));
            EXPECT_LT(max_difference(quat_to_matrix(euler_to_quat(angles, order)),
                                     euler_to_matrix(angles, order)),
                      1e-5f)
                << name_of(order);
        }
    }
}

TEST(AxisAngle, RodriguesEqualsGlmRotate) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> component(-1.0f, 1.0f), angle(0.0f, kPi);
    for (int trial = 0; trial < 500; ++trial) {
        const glm::vec3 axis =
            glm::normalize(glm::vec3(component(rng), component(rng), component(rng)));
        const AxisAngle aa{axis, angle(rng)};
        EXPECT_LT(max_difference(axis_angle_to_matrix(aa), glm_rotation(aa.angle, axis)), 1e-6f);
        const glm::mat3 r = axis_angle_to_matrix(aa);
        EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f);
        // The axis is fixed.
        EXPECT_LT(glm::length(r * axis - axis), 1e-6f);
    }
}

// Angles across [0, pi], with extra ones near both ends where naive conversions lose precision.
std::vector<float> test_angles() {
    std::vector<float> angles = {0.0f, 1e-7f, 1e-6f, 1e-5f,       1e-4f,       1e-3f,       0.5f,
                                 1.0f, 2.0f,  3.0f,  kPi - 1e-2f, kPi - 1e-3f, kPi - 1e-4f, kPi};
    return angles;
}

TEST(AxisAngle, RoundTripsThroughQuaternionAndMatrix) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> component(-1.0f, 1.0f);
    for (int trial = 0; trial < 50; ++trial) {
        const glm::vec3 axis =
            glm::normalize(glm::vec3(component(rng), component(rng), component(rng)));
        for (float angle : test_angles()) {
            const AxisAngle aa{axis, angle};
            const glm::mat3 m = axis_angle_to_matrix(aa);
            const glm::quat q = axis_angle_to_quat(aa);
            EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
            // The two routes to the matrix agree.
            EXPECT_LT(max_difference(quat_to_matrix(q), m), 1e-6f) << angle;
            // matrix -> quat -> matrix and quat -> matrix -> quat.
            EXPECT_LT(max_difference(quat_to_matrix(matrix_to_quat(m)), m), 1e-6f) << angle;
            EXPECT_LT(quat_distance(matrix_to_quat(quat_to_matrix(q)), q), 1e-6f) << angle;

            for (const AxisAngle& back : {matrix_to_axis_angle(m), quat_to_axis_angle(q)}) {
                EXPECT_LT(max_difference(axis_angle_to_matrix(back), m), 1e-6f) << angle;
                EXPECT_GE(back.angle, 0.0f);
                EXPECT_LE(back.angle, kPi);
                EXPECT_NEAR(back.angle, angle, 2e-6f) << angle;
                EXPECT_NEAR(glm::length(back.axis), 1.0f, 1e-6f);
                if (angle >= 1e-6f) {
                    // At exactly pi, axis and -axis are the same rotation.
                    const float error =
                        angle > kPi - 1e-6f
                            ? std::min(glm::length(back.axis - axis), glm::length(back.axis + axis))
                            : glm::length(back.axis - axis);
                    EXPECT_LT(error, 1e-3f) << angle;
                }
            }
        }
    }
}

TEST(AxisAngle, IdentityHasAngleZero) {
    const AxisAngle aa = matrix_to_axis_angle(glm::mat3(1.0f));
    EXPECT_EQ(aa.angle, 0.0f);
    EXPECT_NEAR(glm::length(aa.axis), 1.0f, 1e-6f);
    const glm::quat q = matrix_to_quat(glm::mat3(1.0f));
    EXPECT_EQ(q.w, 1.0f);
    EXPECT_EQ(glm::vec3(q.x, q.y, q.z), glm::vec3(0.0f));
}

TEST(Quaternion, MatrixToQuatHandlesEveryBranchOfShepperd) {
    // Half-turns about x, y and z have trace -1: the largest component is x, y or z, not w.
    for (int axis = 0; axis < 3; ++axis) {
        const glm::mat3 m = axis_angle_to_matrix({kUnit[axis], kPi});
        const glm::quat q = matrix_to_quat(m);
        EXPECT_NEAR(std::abs(q[axis]), 1.0f, 1e-6f);
        EXPECT_LT(max_difference(quat_to_matrix(q), m), 1e-6f);
    }
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> component(-1.0f, 1.0f);
    for (int trial = 0; trial < 1000; ++trial) {
        glm::quat q;
        q.x = component(rng), q.y = component(rng), q.z = component(rng), q.w = component(rng);
        q = glm::normalize(q);
        EXPECT_LT(quat_distance(matrix_to_quat(quat_to_matrix(q)), q), 2e-6f);
        const glm::mat3 m = quat_to_matrix(q);
        EXPECT_NEAR(glm::determinant(m), 1.0f, 1e-5f);
    }
}

}  // namespace
}  // namespace zraster
