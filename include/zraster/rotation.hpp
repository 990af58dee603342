// Rotations as Euler angles, axis-angle (Rodrigues) and unit quaternions, with conversions and
// spherical linear interpolation (Shoemake 1985).
#pragma once
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <zraster/export.hpp>

namespace zraster {

// The order in which the axis rotations are applied to a vector: XYZ means first about x, then
// y, then z, i.e. the matrix Rz * Ry * Rx. Angles in radians, in the order (x, y, z).
enum class EulerOrder { XYZ, XZY, YXZ, YZX, ZXY, ZYX };

ZRASTER_API glm::mat3 euler_to_matrix(const glm::vec3& angles, EulerOrder order);
// One of the angle triples that gives m (m must be a rotation). At gimbal lock (the middle angle
// at +-90 degrees) the first angle is set to 0 and the third takes the whole remaining rotation.
ZRASTER_API glm::vec3 matrix_to_euler(const glm::mat3& m, EulerOrder order);

struct AxisAngle {
    glm::vec3 axis{0.0f, 0.0f, 1.0f};  // unit length
    float angle = 0.0f;                // radians, in [0, pi]
};

// Rodrigues' rotation formula: R = I + sin(a) K + (1 - cos(a)) K^2 with K the cross matrix of axis.
ZRASTER_API glm::mat3 axis_angle_to_matrix(const AxisAngle& aa);
ZRASTER_API AxisAngle matrix_to_axis_angle(const glm::mat3& m);

ZRASTER_API glm::quat axis_angle_to_quat(const AxisAngle& aa);
ZRASTER_API AxisAngle quat_to_axis_angle(const glm::quat& q);
ZRASTER_API glm::mat3 quat_to_matrix(const glm::quat& q);
ZRASTER_API glm::quat matrix_to_quat(const glm::mat3& m);  // Shepperd's method, numerically stable
ZRASTER_API glm::quat euler_to_quat(const glm::vec3& angles, EulerOrder order);

// Spherical linear interpolation along the shorter arc; falls back to normalized lerp when the
// quaternions are nearly parallel. The result is always a unit quaternion.
ZRASTER_API glm::quat slerp(const glm::quat& a, const glm::quat& b, float t);

// Component-wise interpolation of two matrices: NOT a rotation in general (shown by a test).
ZRASTER_API glm::mat3 lerp_matrices(const glm::mat3& a, const glm::mat3& b, float t);

}  // namespace zraster
