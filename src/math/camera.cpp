// Viewing transform (gluLookAt), the Camera and the benchmark framing of docs/bench-scenes.md.
// The framing reproduces the reference harness (../shared/tools/glbench) bit for bit: same
// operations in the same order in double, normalization by division by the length, rounding to
// float only where it rounds.
#include <zraster/camera.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace zraster {

namespace {

// As the harness normalizes (v / |v|), not GLM's v * inversesqrt(|v|^2): the last bit differs.
glm::dvec3 normalize_by_length(const glm::dvec3& v) {
    const double length = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return {v.x / length, v.y / length, v.z / length};
}

double dot3(const glm::dvec3& a, const glm::dvec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

}  // namespace

glm::dmat4 look_at(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up) {
    const glm::dvec3 f = normalize_by_length(target - eye);
    const glm::dvec3 s = normalize_by_length(glm::cross(f, up));
    const glm::dvec3 u = glm::cross(s, f);
    glm::dmat4 m(1.0);  // m[column][row]
    for (int i = 0; i < 3; ++i) {
        m[i][0] = s[i];
        m[i][1] = u[i];
        m[i][2] = -f[i];
    }
    m[3][0] = -dot3(s, eye);
    m[3][1] = -dot3(u, eye);
    m[3][2] = dot3(f, eye);
    return m;
}

glm::dmat4 Camera::view() const {
    return look_at(eye, target, up);
}

glm::dmat4 Camera::projection_matrix(double aspect) const {
    if (projection == Projection::Orthographic) {
        // An orthographic volume has no use for an infinite far plane: infinite_far is ignored.
        const double top = ortho_height / 2.0, right = top * aspect;
        return reversed_z ? orthographic_reversed_z(-right, right, -top, top, near, far)
                          : orthographic(-right, right, -top, top, near, far);
    }
    const double fovy = radians(fovy_degrees);
    if (reversed_z) {
        return infinite_far ? perspective_reversed_z_infinite(fovy, aspect, near)
                            : perspective_reversed_z(fovy, aspect, near, far);
    }
    return infinite_far ? perspective_infinite(fovy, aspect, near)
                        : perspective(fovy, aspect, near, far);
}

glm::mat4 Camera::view_projection(double aspect) const {
    const glm::mat4 v(view()), p(projection_matrix(aspect));
    glm::mat4 out;
    // Sums from 0 in k order, as the harness does, so that the float result is the same.
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k) sum += double(p[k][r]) * double(v[c][k]);
            out[c][r] = float(sum);
        }
    }
    return out;
}

Camera fit_camera(std::span<const glm::vec3> world_points, double fovy_degrees) {
    glm::dvec3 center(0.0);
    double radius = 0.0;
    if (!world_points.empty()) {
        glm::dvec3 lo(std::numeric_limits<double>::infinity());
        glm::dvec3 hi(-std::numeric_limits<double>::infinity());
        for (const glm::vec3& p : world_points) {
            lo = glm::min(lo, glm::dvec3(p));
            hi = glm::max(hi, glm::dvec3(p));
        }
        center = (lo + hi) / 2.0;
        double r2 = 0.0;
        for (const glm::vec3& p : world_points)
            r2 = std::max(r2, dot3(glm::dvec3(p) - center, glm::dvec3(p) - center));
        radius = std::sqrt(r2);
    }
    if (!(radius > 0.0) || !std::isfinite(radius)) radius = 1.0;

    Camera cam;
    cam.projection = Camera::Projection::Perspective;
    cam.fovy_degrees = fovy_degrees;
    // dist makes the bounding sphere exactly fill the vertical field of view.
    const double dist = radius / std::sin(radians(fovy_degrees) / 2.0);
    const glm::dvec3 dir = normalize_by_length({1.0, 1.0, 2.0});
    cam.eye = {center.x + dist * dir.x, center.y + dist * dir.y, center.z + dist * dir.z};
    cam.target = center;
    cam.up = {0.0, 1.0, 0.0};
    cam.near = dist - 1.01 * radius;
    cam.far = dist + 1.01 * radius;
    return cam;
}

Camera orbit_camera(const glm::dvec3& target, double distance, double azimuth_degrees,
                    double elevation_degrees, double fovy_degrees) {
    const double az = radians(azimuth_degrees), el = radians(elevation_degrees);
    Camera cam;
    cam.fovy_degrees = fovy_degrees;
    cam.target = target;
    cam.eye = target + distance * glm::dvec3(std::cos(el) * std::sin(az), std::sin(el),
                                             std::cos(el) * std::cos(az));
    // Straight above or below, +y is parallel to the view direction and gluLookAt degenerates;
    // use the limit of the camera's up vector as the elevation approaches +-90 degrees instead.
    if (std::abs(std::cos(el)) < 1e-9) {
        const double sign = el > 0.0 ? 1.0 : -1.0;
        cam.up = -sign * glm::dvec3(std::sin(az), 0.0, std::cos(az));
    }
    return cam;
}

glm::mat3 normal_matrix(const glm::mat4& model_view) {
    // In double: the inverse of a nearly singular (strongly scaled) matrix loses digits in float.
    return glm::mat3(glm::transpose(glm::inverse(glm::dmat3(glm::mat3(model_view)))));
}

}  // namespace zraster
