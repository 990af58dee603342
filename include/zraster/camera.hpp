// Cameras and projections, with OpenGL's conventions: right-handed eye space looking down -z,
// clip-space x, y in [-w, w], window origin at the bottom left for the projection itself (the
// renderer's images are stored top row first).
//
// Depth conventions:
//  - Standard (OpenGL): clip z in [-w, w], window depth = 0.5 * z/w + 0.5; near -> 0, far -> 1.
//  - Reversed-Z: clip z in [0, w] and window depth = z/w with near -> 1, far -> 0; used with a
//    float depth buffer and the GREATER test it spreads float precision evenly over distance
//    (Reed 2015, "Depth Precision Visualized").
#pragma once
#include <zraster/bounds.hpp>

#include <glm/glm.hpp>

#include <span>

namespace zraster {

enum class ClipDepthRange {
    NegativeOneToOne,  // OpenGL: -w <= z <= w
    ZeroToOne,         // Direct3D / reversed-Z: 0 <= z <= w
};

// gluLookAt: rows (s, -s.eye), (u, -u.eye), (-f, f.eye) with f = normalize(target - eye),
// s = normalize(cross(f, up)), u = cross(s, f).
glm::dmat4 look_at(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up);

// gluPerspective (clip z in [-w, w]). fovy in radians, aspect = width / height.
glm::dmat4 perspective(double fovy, double aspect, double near, double far);
// Infinite far plane (clip z in [-w, w]), the limit of perspective() as far -> infinity.
glm::dmat4 perspective_infinite(double fovy, double aspect, double near);
// Reversed-Z (clip z in [0, w]): near -> 1, far -> 0.
glm::dmat4 perspective_reversed_z(double fovy, double aspect, double near, double far);
// Reversed-Z with an infinite far plane: depth = near / -z_eye.
glm::dmat4 perspective_reversed_z_infinite(double fovy, double aspect, double near);
// glOrtho (clip z in [-w, w]).
glm::dmat4 orthographic(double left, double right, double bottom, double top, double near,
                        double far);
// Orthographic with reversed-Z (clip z in [0, w]): near -> 1, far -> 0.
glm::dmat4 orthographic_reversed_z(double left, double right, double bottom, double top,
                                   double near, double far);

struct Camera {
    enum class Projection { Perspective, Orthographic };

    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    Projection projection = Projection::Perspective;
    double fovy_degrees = 60.0;  // perspective
    double ortho_height = 2.0;   // orthographic: height of the view volume in world units
    double near = 0.1;
    double far = 100.0;
    bool reversed_z = false;
    bool infinite_far = false;

    glm::dmat4 view() const;
    glm::dmat4 projection_matrix(double aspect) const;
    ClipDepthRange clip_depth_range() const {
        return reversed_z ? ClipDepthRange::ZeroToOne : ClipDepthRange::NegativeOneToOne;
    }
    // P * V rounded as docs/bench-scenes.md does it: V and P rounded to float, multiplied in
    // double, rounded to float. Using this everywhere makes zraster and the llvmpipe harness agree.
    glm::mat4 view_projection(double aspect) const;
};

// The benchmark framing (docs/bench-scenes.md): center = middle of the axis-aligned box of the
// points, radius = max |p - center| (double), fovy = 60 degrees, eye = center + dist *
// normalize(1, 1, 2) with dist = radius / sin(fovy / 2), up = +y, near = dist - 1.01 r,
// far = dist + 1.01 r.
// An empty or degenerate point set (radius 0) gets radius 1.
Camera fit_camera(std::span<const glm::vec3> world_points, double fovy_degrees = 60.0);

// A camera circling `target` at `distance`: azimuth around +y from +z towards +x, elevation above
// the xz plane (degrees). near/far are left for the caller.
Camera orbit_camera(const glm::dvec3& target, double distance, double azimuth_degrees,
                    double elevation_degrees, double fovy_degrees = 60.0);

// Normals transform by the inverse-transpose of the upper 3x3 of the model-view matrix (it keeps
// them perpendicular to surfaces under non-uniform scale).
glm::mat3 normal_matrix(const glm::mat4& model_view);

}  // namespace zraster
