// Projection matrices: gluPerspective and glOrtho (OpenGL 1.0 reference pages), their infinite-far
// limits (Everitt and Kilgard 2002, "Practical and Robust Stenciled Shadow Volumes") and
// reversed-Z variants (Reed 2015, "Depth Precision Visualized").
// Matrices are column-major: m[column][row].
#include <zraster/camera.hpp>

#include <cmath>

namespace zraster {

namespace {

// The x and y rows shared by every perspective variant. 1 / tan rather than cot so that the
// result is bit-for-bit the one of docs/bench-scenes.md's reference harness.
glm::dmat4 perspective_xy(double fovy, double aspect) {
    const double t = 1.0 / std::tan(fovy / 2.0);
    glm::dmat4 m(0.0);
    m[0][0] = t / aspect;
    m[1][1] = t;
    m[2][3] = -1.0;  // w_clip = -z_eye
    return m;
}

}  // namespace

glm::dmat4 perspective(double fovy, double aspect, double near, double far) {
    glm::dmat4 m = perspective_xy(fovy, aspect);
    m[2][2] = (far + near) / (near - far);
    m[3][2] = 2.0 * far * near / (near - far);
    return m;
}

glm::dmat4 perspective_infinite(double fovy, double aspect, double near) {
    // far -> infinity in perspective(): (f + n) / (n - f) -> -1 and 2fn / (n - f) -> -2n.
    glm::dmat4 m = perspective_xy(fovy, aspect);
    m[2][2] = -1.0;
    m[3][2] = -2.0 * near;
    return m;
}

glm::dmat4 perspective_reversed_z(double fovy, double aspect, double near, double far) {
    // z_clip = A z_eye + B with w_clip = -z_eye; z_eye = -near -> 1, z_eye = -far -> 0.
    glm::dmat4 m = perspective_xy(fovy, aspect);
    m[2][2] = near / (far - near);
    m[3][2] = far * near / (far - near);
    return m;
}

glm::dmat4 perspective_reversed_z_infinite(double fovy, double aspect, double near) {
    // The limit far -> infinity of perspective_reversed_z(): A -> 0, B -> near.
    glm::dmat4 m = perspective_xy(fovy, aspect);
    m[2][2] = 0.0;
    m[3][2] = near;
    return m;
}

glm::dmat4 orthographic(double left, double right, double bottom, double top, double near,
                        double far) {
    glm::dmat4 m(1.0);
    m[0][0] = 2.0 / (right - left);
    m[1][1] = 2.0 / (top - bottom);
    m[2][2] = -2.0 / (far - near);
    m[3][0] = -(right + left) / (right - left);
    m[3][1] = -(top + bottom) / (top - bottom);
    m[3][2] = -(far + near) / (far - near);
    return m;
}

glm::dmat4 orthographic_reversed_z(double left, double right, double bottom, double top,
                                   double near, double far) {
    glm::dmat4 m = orthographic(left, right, bottom, top, near, far);
    // z_ndc = A z_eye + B with z_eye = -near -> 1, z_eye = -far -> 0.
    m[2][2] = 1.0 / (far - near);
    m[3][2] = far / (far - near);
    return m;
}

}  // namespace zraster
