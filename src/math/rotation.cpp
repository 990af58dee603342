// Rotation representations and conversions.
//  - Euler (Tait-Bryan) angles: Shoemake 1994, "Euler Angle Conversion" (Graphics Gems IV): one
//    formula for all six orders, relabelling the axes and flipping signs for the odd orders.
//  - Axis-angle: Rodrigues 1840; unit quaternions: Hamilton 1843, Shoemake 1985 ("Animating
//    Rotation with Quaternion Curves").
//  - Matrix to quaternion: Shepperd 1978, "Quaternion from Rotation Matrix" (pick the largest of
//    w, x, y, z first so that the square root is never of a small, cancelling number).
// Everything is computed in double and rounded to float once at the end.
#include <zraster/rotation.hpp>

#include <algorithm>
#include <cmath>

namespace zraster {

namespace {

// The axes in the order they are applied (first, second, third) and the parity of that
// permutation: +1 for the cyclic orders XYZ, YZX, ZXY, -1 for the others.
struct Axes {
    int i, j, k;
    double parity;
};

Axes axes_of(EulerOrder order) {
    switch (order) {
        case EulerOrder::XYZ:
            return {0, 1, 2, 1.0};
        case EulerOrder::YZX:
            return {1, 2, 0, 1.0};
        case EulerOrder::ZXY:
            return {2, 0, 1, 1.0};
        case EulerOrder::XZY:
            return {0, 2, 1, -1.0};
        case EulerOrder::YXZ:
            return {1, 0, 2, -1.0};
        case EulerOrder::ZYX:
            return {2, 1, 0, -1.0};
    }
    return {0, 1, 2, 1.0};
}

glm::dmat3 axis_rotation(int axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // the plane rotated, a towards b
    glm::dmat3 m(1.0);                                 // m[column][row]
    m[a][a] = c;
    m[b][b] = c;
    m[a][b] = s;
    m[b][a] = -s;
    return m;
}

glm::dquat axis_quat(int axis, double angle) {
    glm::dquat q;
    q.w = std::cos(angle / 2.0);
    q.x = q.y = q.z = 0.0;
    q[axis] = std::sin(angle / 2.0);  // q[0] is x (GLM stores x, y, z, w)
    return q;
}

glm::dquat matrix_to_dquat(const glm::dmat3& m) {
    // m[column][row]; the diagonal and the (anti)symmetric parts of the off-diagonal pairs.
    const double trace = m[0][0] + m[1][1] + m[2][2];
    glm::dquat q;
    if (trace >= m[0][0] && trace >= m[1][1] && trace >= m[2][2]) {
        const double r = std::sqrt(1.0 + trace);  // 2|w|, the largest component
        const double s = 0.5 / r;
        q.w = 0.5 * r;
        q.x = (m[1][2] - m[2][1]) * s;
        q.y = (m[2][0] - m[0][2]) * s;
        q.z = (m[0][1] - m[1][0]) * s;
    } else if (m[0][0] >= m[1][1] && m[0][0] >= m[2][2]) {
        const double r = std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        const double s = 0.5 / r;
        q.x = 0.5 * r;
        q.w = (m[1][2] - m[2][1]) * s;
        q.y = (m[1][0] + m[0][1]) * s;
        q.z = (m[2][0] + m[0][2]) * s;
    } else if (m[1][1] >= m[2][2]) {
        const double r = std::sqrt(1.0 - m[0][0] + m[1][1] - m[2][2]);
        const double s = 0.5 / r;
        q.y = 0.5 * r;
        q.w = (m[2][0] - m[0][2]) * s;
        q.x = (m[1][0] + m[0][1]) * s;
        q.z = (m[2][1] + m[1][2]) * s;
    } else {
        const double r = std::sqrt(1.0 - m[0][0] - m[1][1] + m[2][2]);
        const double s = 0.5 / r;
        q.z = 0.5 * r;
        q.w = (m[0][1] - m[1][0]) * s;
        q.x = (m[2][0] + m[0][2]) * s;
        q.y = (m[2][1] + m[1][2]) * s;
    }
    if (q.w < 0.0) q = -q;  // q and -q are the same rotation; w >= 0 gives angles in [0, pi]
    return glm::normalize(q);
}

AxisAngle dquat_to_axis_angle(glm::dquat q) {
    q = glm::normalize(q);
    if (q.w < 0.0) q = -q;
    const glm::dvec3 v(q.x, q.y, q.z);
    const double s = glm::length(v);
    AxisAngle aa;
    // atan2 keeps full precision at both ends, where acos(w) or asin(|v|) would not.
    aa.angle = float(2.0 * std::atan2(s, q.w));
    if (s > 0.0) aa.axis = glm::vec3(v / s);  // else: no rotation, any axis (the default z)
    return aa;
}

}  // namespace

glm::mat3 euler_to_matrix(const glm::vec3& angles, EulerOrder order) {
    const Axes a = axes_of(order);
    return glm::mat3(axis_rotation(a.k, angles[a.k]) * axis_rotation(a.j, angles[a.j]) *
                     axis_rotation(a.i, angles[a.i]));
}

glm::vec3 matrix_to_euler(const glm::mat3& mf, EulerOrder order) {
    const Axes ax = axes_of(order);
    const int i = ax.i, j = ax.j, k = ax.k;
    const double p = ax.parity;
    const glm::dmat3 dm(mf);
    // e(row, column) of M = R_k(c) R_j(b) R_i(a). For XYZ: e(k,i) = -sin b,
    // (e(k,j), e(k,k)) = cos b (sin a, cos a), (e(i,i), e(j,i)) = cos b (cos c, sin c).
    auto e = [&](int row, int column) { return dm[column][row]; };
    const double cos_b = std::hypot(e(i, i), e(j, i));
    const double b = std::atan2(-p * e(k, i), cos_b);
    // At gimbal lock only a - c (or a + c) is defined: a = 0 and c takes the whole rotation. The
    // threshold is a few float ulps: the entries of a float rotation are no better than that.
    const double a = cos_b < 1e-6 ? 0.0 : std::atan2(p * e(k, j), e(k, k));
    // c from R_k(c) = M R_i(a)^T R_j(b)^T, so that c is consistent with the a found (this stays
    // accurate near the lock, where c from e(i,i), e(j,i) alone would be noise over cos b).
    const double sa = std::sin(a), ca = std::cos(a);
    const double c = std::atan2(sa * e(i, k) - p * ca * e(i, j), ca * e(j, j) - p * sa * e(j, k));
    glm::vec3 out;
    out[i] = float(a);
    out[j] = float(b);
    out[k] = float(c);
    return out;
}

glm::mat3 axis_angle_to_matrix(const AxisAngle& aa) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(aa.axis));
    const double s = std::sin(double(aa.angle)), c = std::cos(double(aa.angle));
    // K v = n x v; columns of K are n x e_x, n x e_y, n x e_z.
    const glm::dmat3 k(0.0, n.z, -n.y,  // column 0
                       -n.z, 0.0, n.x,  // column 1
                       n.y, -n.x, 0.0);
    return glm::mat3(glm::dmat3(1.0) + s * k + (1.0 - c) * (k * k));
}

AxisAngle matrix_to_axis_angle(const glm::mat3& m) {
    // Through the quaternion: the angle from the trace alone is ill-conditioned near 0 and pi.
    return dquat_to_axis_angle(matrix_to_dquat(glm::dmat3(m)));
}

glm::quat axis_angle_to_quat(const AxisAngle& aa) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(aa.axis));
    const double half = double(aa.angle) / 2.0, s = std::sin(half);
    glm::quat q;
    q.w = float(std::cos(half));
    q.x = float(n.x * s);
    q.y = float(n.y * s);
    q.z = float(n.z * s);
    return q;
}

AxisAngle quat_to_axis_angle(const glm::quat& q) {
    return dquat_to_axis_angle(glm::dquat(q));
}

glm::mat3 quat_to_matrix(const glm::quat& q) {
    return glm::mat3(glm::mat3_cast(glm::normalize(glm::dquat(q))));
}

glm::quat matrix_to_quat(const glm::mat3& m) {
    return glm::quat(matrix_to_dquat(glm::dmat3(m)));
}

glm::quat euler_to_quat(const glm::vec3& angles, EulerOrder order) {
    const Axes a = axes_of(order);
    return glm::quat(axis_quat(a.k, angles[a.k]) * axis_quat(a.j, angles[a.j]) *
                     axis_quat(a.i, angles[a.i]));
}

}  // namespace zraster
