// Viewing transform (gluLookAt), the Camera and the benchmark framing of docs/bench-scenes.md.
// The framing reproduces the reference harness (../shared/tools/glbench) bit for bit: same
// operations in the same order in double, normalization by division by the length, rounding to
// float only where it rounds.
//
// Cameras from matrices and from pinhole intrinsics (Hartley and Zisserman 2003, "Multiple View
// Geometry", 6.1: the finite projective camera K [R | t]). A pinhole's frustum is glFrustum's
// with the principal point moving its center: the x and y rows map the pixel convention's
// (u, v) to normalized device coordinates, the z row is the fovy camera's for the same depth mode.
#include <zraster/camera.hpp>
#include <zraster/error.hpp>

#include <glm/gtx/component_wise.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

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

std::string number(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Exactly singular, or so nearly that the inverse overflows.
bool singular(const glm::dmat4& m) {
    return !(std::abs(glm::determinant(m)) > 0.0) || !finite(glm::inverse(m));
}

// A view matrix or a pose: world <-> eye space, finite, affine and invertible. (Names are built
// into strings only when thrown: a kept Renderer checks its camera every frame without
// allocating.)
void check_rigid(const glm::dmat4& m, const char* name) {
    if (!finite(m)) throw InputError("", std::string(name) + " has a non-finite element");
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
        throw InputError("",
                         std::string(name) + " is not affine (its last row must be 0, 0, 0, 1)");
    if (singular(m)) throw InputError("", std::string(name) + " is singular");
}

// m[column][row]: the last row is (m[0][3], m[1][3], m[2][3], m[3][3]).
bool orthographic_matrix(const glm::dmat4& p) {
    return p[2][3] == 0.0;
}

void check_projection(const glm::dmat4& p) {
    if (!finite(p)) throw InputError("", "camera projection matrix has a non-finite element");
    const bool perspective = p[2][3] < 0.0 && p[3][3] == 0.0;
    const bool orthographic = p[2][3] == 0.0 && p[3][3] > 0.0;
    if (p[0][3] != 0.0 || p[1][3] != 0.0 || !(perspective || orthographic))
        throw InputError("",
                         "camera projection matrix: the last row must be (0, 0, -c, 0) "
                         "(perspective) or (0, 0, 0, c) (orthographic) with c > 0");
    // Otherwise the eye is not the center of projection, or -z not the direction of projection,
    // and lighting and the BSP order would use the wrong viewer.
    if (perspective && (p[3][0] != 0.0 || p[3][1] != 0.0))
        throw InputError("",
                         "camera projection matrix: a perspective projection's x and y rows "
                         "need a zero constant term (the center of projection is the eye)");
    if (orthographic && (p[2][0] != 0.0 || p[2][1] != 0.0))
        throw InputError("",
                         "camera projection matrix: an orthographic projection's x and y "
                         "rows need a zero z term (the direction of projection is -z)");
    if (singular(p)) throw InputError("", "camera projection matrix is singular");
}

// The image-plane part of the intrinsics; near and far are the camera's.
void check_lens(const Intrinsics& k) {
    const auto positive = [](const char* field, double value) {
        if (!(std::isfinite(value) && value > 0.0))
            throw InputError("", std::string("camera intrinsics ") + field +
                                     " must be finite and > 0, not " + number(value));
    };
    positive("fx", k.fx);
    positive("fy", k.fy);
    if (!std::isfinite(k.cx)) throw InputError("", "camera intrinsics cx must be finite");
    if (!std::isfinite(k.cy)) throw InputError("", "camera intrinsics cy must be finite");
    if (k.width < 1 || k.height < 1)
        throw InputError("", "camera intrinsics width and height must be >= 1, not " +
                                 std::to_string(k.width) + "x" + std::to_string(k.height));
}

// z_eye of the points at window depth `window` for a projection whose z and w rows depend on
// z_eye alone: z_ndc = (a z + b) / (c z + e), solved for z.
double eye_z(const glm::dmat4& p, ClipDepthRange range, double window) {
    const double z_ndc = range == ClipDepthRange::NegativeOneToOne ? 2.0 * window - 1.0 : window;
    const double a = p[2][2], b = p[3][2], c = p[2][3], e = p[3][3];
    const double denominator = z_ndc * c - a;
    // The far plane of an infinite projection.
    if (denominator == 0.0) return -std::numeric_limits<double>::infinity();
    return (b - z_ndc * e) / denominator;
}

bool depth_depends_on_z_only(const glm::dmat4& p) {
    return p[0][2] == 0.0 && p[1][2] == 0.0 && p[0][3] == 0.0 && p[1][3] == 0.0;
}

// The inverse of an affine matrix, affine again: its last row exactly (0, 0, 0, 1), which a
// general 4x4 inverse leaves to rounding.
glm::dmat4 affine_inverse(const glm::dmat4& m) {
    const glm::dmat3 linear = glm::inverse(glm::dmat3(m));
    glm::dmat4 out(linear);
    out[3] = glm::dvec4(-(linear * glm::dvec3(m[3])), 1.0);
    return out;
}

// The readable fields (eye, target, up) of a camera given by its view matrix.
void set_look_at_from_view(Camera& camera) {
    camera.eye = camera.position();
    camera.target = camera.eye + camera.view_direction();
    camera.up = glm::normalize(glm::dvec3(affine_inverse(*camera.given_view)[1]));
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

Camera Camera::from_matrices(const glm::dmat4& view, const glm::dmat4& projection,
                             ClipDepthRange range, bool reversed_z) {
    check_rigid(view, "camera view matrix");
    check_projection(projection);
    Camera camera;
    camera.given_view = view;
    camera.given_projection = GivenProjection{projection, range};
    camera.reversed_z = reversed_z;
    set_look_at_from_view(camera);
    // The rest for reading, as far as the matrix states it.
    const double c = orthographic_matrix(projection) ? projection[3][3] : -projection[2][3];
    if (orthographic_matrix(projection)) {
        camera.projection = Projection::Orthographic;
        camera.ortho_height = 2.0 * c / projection[1][1];
    } else {
        camera.fovy_degrees = 2.0 * std::atan(c / projection[1][1]) * 180.0 / std::numbers::pi;
    }
    if (depth_depends_on_z_only(projection)) {
        camera.near = -eye_z(projection, range, reversed_z ? 1.0 : 0.0);
        camera.far = -eye_z(projection, range, reversed_z ? 0.0 : 1.0);
        camera.infinite_far = std::isinf(camera.far);
    } else {
        camera.near = camera.far = std::numeric_limits<double>::quiet_NaN();
    }
    return camera;
}

Camera Camera::from_intrinsics(const Intrinsics& k, const glm::dmat4& camera_to_world,
                               CameraConvention convention) {
    check_lens(k);
    if (!(std::isfinite(k.near) && k.near > 0.0) || std::isnan(k.far) || !(k.far > k.near))
        throw InputError("", "camera intrinsics need 0 < near < far, not near " + number(k.near) +
                                 ", far " + number(k.far));
    check_rigid(camera_to_world, "camera_to_world");
    glm::dmat4 to_opengl_axes = camera_to_world;
    if (convention == CameraConvention::OpenCV) {
        to_opengl_axes[1] = -to_opengl_axes[1];
        to_opengl_axes[2] = -to_opengl_axes[2];
    }
    Camera camera;
    camera.given_view = affine_inverse(to_opengl_axes);
    camera.pinhole = Pinhole{k, convention};
    camera.near = k.near;
    camera.far = k.far;
    camera.infinite_far = std::isinf(k.far);
    camera.fovy_degrees = 2.0 * std::atan(0.5 * k.height / k.fy) * 180.0 / std::numbers::pi;
    set_look_at_from_view(camera);
    return camera;
}

glm::dmat4 Camera::view() const {
    return given_view ? *given_view : look_at(eye, target, up);
}

glm::dmat4 Camera::projection_matrix(double aspect) const {
    if (given_projection) return given_projection->matrix;
    if (pinhole) {
        // The z and w rows of the fovy camera with the same depth mode; fovy and aspect only
        // set the x and y rows, replaced here.
        Camera lens = *this;
        lens.pinhole.reset();
        lens.projection = Projection::Perspective;
        lens.fovy_degrees = 90.0;
        glm::dmat4 m = lens.projection_matrix(1.0);
        const Intrinsics& k = pinhole->intrinsics;
        const double w = k.width, h = k.height;
        m[0][0] = 2.0 * k.fx / w;
        m[1][1] = 2.0 * k.fy / h;
        if (pinhole->convention == CameraConvention::OpenCV) {
            m[2][0] = 1.0 - 2.0 * (k.cx + 0.5) / w;
            m[2][1] = 2.0 * (k.cy + 0.5) / h - 1.0;
        } else {
            m[2][0] = 1.0 - 2.0 * k.cx / w;
            m[2][1] = 1.0 - 2.0 * k.cy / h;
        }
        return m;
    }
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

glm::dvec3 Camera::position() const {
    if (!given_view) return eye;
    return glm::dvec3(affine_inverse(*given_view)[3]);
}

glm::dvec3 Camera::view_direction() const {
    if (!given_view) return glm::normalize(target - eye);
    return glm::normalize(-glm::dvec3(affine_inverse(*given_view)[2]));
}

bool Camera::is_orthographic() const {
    if (given_projection) return orthographic_matrix(given_projection->matrix);
    return !pinhole && projection == Projection::Orthographic;
}

Intrinsics Camera::intrinsics(int width, int height, CameraConvention convention) const {
    if (width < 1 || height < 1)
        throw InputError("", "intrinsics need an image size of at least 1x1, not " +
                                 std::to_string(width) + "x" + std::to_string(height));
    if (is_orthographic()) throw InputError("", "an orthographic camera has no pinhole intrinsics");
    Intrinsics k;
    if (pinhole && pinhole->intrinsics.width == width && pinhole->intrinsics.height == height &&
        pinhole->convention == convention) {
        k = pinhole->intrinsics;
    } else {
        const glm::dmat4 p = projection_matrix(double(width) / double(height));
        // A pinhole's x row depends on x and z only, its y row on y and z only.
        if (p[1][0] != 0.0 || p[0][1] != 0.0 || p[3][0] != 0.0 || p[3][1] != 0.0)
            throw InputError("", "the camera's projection is no pinhole (it has skew or offsets)");
        // Window x = (ndc_x + 1) w / 2 with ndc_x = (p00 x + p20 z) / (c (-z)), and the same for y
        // (window y from the bottom, which OpenCV's v counts from the top).
        const double c = -p[2][3], w = width, h = height;
        const double p20 = p[2][0] / c, p21 = p[2][1] / c;
        k.fx = 0.5 * w * p[0][0] / c;
        k.fy = 0.5 * h * p[1][1] / c;
        if (convention == CameraConvention::OpenCV) {
            k.cx = 0.5 * w * (1.0 - p20) - 0.5;
            k.cy = 0.5 * h * (1.0 + p21) - 0.5;
        } else {
            k.cx = 0.5 * w * (1.0 - p20);
            k.cy = 0.5 * h * (1.0 - p21);
        }
        k.width = width;
        k.height = height;
    }
    k.near = near;
    k.far = infinite_far ? std::numeric_limits<double>::infinity() : far;
    return k;
}

glm::dmat4 Camera::camera_to_world(CameraConvention convention) const {
    glm::dmat4 m = affine_inverse(view());
    if (convention == CameraConvention::OpenCV) {
        m[1] = -m[1];
        m[2] = -m[2];
    }
    return m;
}

void check_camera(const Camera& c, int width, int height) {
    if (c.given_view) {
        check_rigid(*c.given_view, "camera view matrix");
    } else {
        if (!finite(c.eye) || !finite(c.target) || !finite(c.up))
            throw InputError("", "camera parameters must be finite");
        for (const auto& [name, p] : {std::pair{"eye", c.eye}, std::pair{"target", c.target}})
            if (glm::compMax(glm::abs(p)) > kMaxCameraCoordinate)
                throw InputError("", std::string("camera ") + name + " (" + number(p.x) + ", " +
                                         number(p.y) + ", " + number(p.z) +
                                         ") is beyond the +-1e32 zraster supports "
                                         "(single-precision matrices)");
        if (glm::length(c.target - c.eye) == 0.0)
            throw InputError("", "camera eye and target coincide");
        if (glm::length(glm::cross(c.target - c.eye, c.up)) == 0.0)
            throw InputError("", "camera up vector is parallel to the view direction");
    }
    if (c.given_projection) {
        check_projection(c.given_projection->matrix);
        return;
    }
    // far is unused with infinite_far, and may then be infinite.
    if (!std::isfinite(c.near) || std::isnan(c.far) || (!c.infinite_far && std::isinf(c.far)) ||
        (!c.pinhole && !std::isfinite(c.fovy_degrees)))
        throw InputError("", "camera parameters must be finite");
    if (!(c.near > 0.0) || (!c.infinite_far && !(c.far > c.near)))
        throw InputError("", "camera needs 0 < near < far, not near " + number(c.near) + ", far " +
                                 number(c.far));
    if (c.pinhole) {
        const Intrinsics& k = c.pinhole->intrinsics;
        check_lens(k);
        if (k.width != width || k.height != height)
            throw InputError("", "camera intrinsics are for " + std::to_string(k.width) + "x" +
                                     std::to_string(k.height) + " but the image is " +
                                     std::to_string(width) + "x" + std::to_string(height));
    } else if (c.projection == Camera::Projection::Perspective &&
               !(c.fovy_degrees > 0.0 && c.fovy_degrees < 180.0)) {
        throw InputError("", "field of view must be in (0, 180) degrees");
    } else if (c.projection == Camera::Projection::Orthographic &&
               !(std::isfinite(c.ortho_height) && c.ortho_height > 0.0)) {
        throw InputError("", "orthographic camera needs a finite ortho_height > 0");
    }
}

double linear_depth(const Camera& camera, double window_depth) {
    const glm::dmat4 p = camera.projection_matrix(1.0);
    if (!depth_depends_on_z_only(p))
        throw InputError("", "linear_depth needs a projection whose depth depends on eye z only");
    return -eye_z(p, camera.clip_depth_range(), window_depth);
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
        const double reach = std::max(glm::compMax(glm::abs(lo)), glm::compMax(glm::abs(hi)));
        if (std::isfinite(reach) && reach > kMaxCoordinate)
            throw InputError("", "coordinates reach " + number(reach) +
                                     ", beyond the +-1e30 a camera can frame (single-precision "
                                     "matrices would overflow); scale the scene down");
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
