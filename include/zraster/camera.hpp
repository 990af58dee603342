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
#include <zraster/export.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <span>

namespace zraster {

enum class ClipDepthRange {
    NegativeOneToOne,  // OpenGL: -w <= z <= w
    ZeroToOne,         // Direct3D / reversed-Z: 0 <= z <= w
};

// gluLookAt: rows (s, -s.eye), (u, -u.eye), (-f, f.eye) with f = normalize(target - eye),
// s = normalize(cross(f, up)), u = cross(s, f).
ZRASTER_API glm::dmat4 look_at(const glm::dvec3& eye, const glm::dvec3& target,
                               const glm::dvec3& up);

// gluPerspective (clip z in [-w, w]). fovy in radians, aspect = width / height.
ZRASTER_API glm::dmat4 perspective(double fovy, double aspect, double near, double far);
// Infinite far plane (clip z in [-w, w]), the limit of perspective() as far -> infinity.
ZRASTER_API glm::dmat4 perspective_infinite(double fovy, double aspect, double near);
// Reversed-Z (clip z in [0, w]): near -> 1, far -> 0.
ZRASTER_API glm::dmat4 perspective_reversed_z(double fovy, double aspect, double near, double far);
// Reversed-Z with an infinite far plane: depth = near / -z_eye.
ZRASTER_API glm::dmat4 perspective_reversed_z_infinite(double fovy, double aspect, double near);
// glOrtho (clip z in [-w, w]).
ZRASTER_API glm::dmat4 orthographic(double left, double right, double bottom, double top,
                                    double near, double far);
// Orthographic with reversed-Z (clip z in [0, w]): near -> 1, far -> 0.
ZRASTER_API glm::dmat4 orthographic_reversed_z(double left, double right, double bottom, double top,
                                               double near, double far);

// Pinhole intrinsics for an image of width x height pixels: focal lengths fx, fy and principal
// point (cx, cy) in pixels, with the clip distances near and far along the view axis. The pixel
// convention of (u, v) and (cx, cy) is a CameraConvention's (below).
struct Intrinsics {
    double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
    int width = 0, height = 0;
    double near = 0.0, far = 0.0;
};

// The conventions of a camera's axes and of its pixel coordinates, window coordinates being
// zraster's (raster.hpp: pixel (px, py) of row py from the top has its center at
// (px + 0.5, py + 0.5)).
//  - OpenCV: camera x right, y down, z forward. (X, Y, Z) projects to
//    u = fx X / Z + cx, v = fy Y / Z + cy, pixel centers at integers with v = 0 the top row:
//    window x = u + 0.5, window y (top down) = v + 0.5.
//  - OpenGL: camera x right, y up, looking down -z. (X, Y, Z) projects to
//    window x = fx X / -Z + cx, window y measured from the bottom = fy Y / -Z + cy: pixel
//    centers at half-integers, the bottom row's at y = 0.5.
enum class CameraConvention { OpenCV, OpenGL };

struct ZRASTER_API Camera {
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

    // Set by from_matrices() and from_intrinsics(): the view matrix, in place of look_at(eye,
    // target, up). Those factories also set eye, target (eye + view direction) and up from it for
    // reading; while given_view is set, changing them has no effect.
    std::optional<glm::dmat4> given_view;
    // Set by from_matrices(): the projection as given, in place of everything that
    // projection_matrix() otherwise computes (projection, fovy_degrees, ortho_height, near, far,
    // infinite_far; the factory sets those for reading, near and far NaN where the matrix's depth
    // depends on more than eye z). reversed_z states only the matrix's depth direction, for the
    // default compare and clear value.
    struct GivenProjection {
        glm::dmat4 matrix{1.0};
        ClipDepthRange range = ClipDepthRange::NegativeOneToOne;
    };
    std::optional<GivenProjection> given_projection;
    // Set by from_intrinsics(): a pinhole lens in place of fovy_degrees. The camera's near, far,
    // reversed_z and infinite_far apply as for a fovy camera (from_intrinsics copies near and far
    // there; the copies in `intrinsics` are not used).
    struct Pinhole {
        Intrinsics intrinsics;
        CameraConvention convention = CameraConvention::OpenCV;
    };
    std::optional<Pinhole> pinhole;

    // A camera from a view matrix (world -> right-handed eye space looking down -z, affine) and a
    // projection matrix whose clip z spans `range`; reversed_z: the projection maps near to window
    // depth 1 (the default compare becomes GREATER, the clear value 0). The projection's last row
    // must be (0, 0, -c, 0) (perspective: w = -c z_eye) or (0, 0, 0, c) (orthographic), c > 0, so
    // that the center of projection is the eye (perspective: the x and y rows have no constant
    // term) or the projection direction is -z (orthographic: they have no z term). Throws
    // InputError (naming the matrix) for non-finite or singular matrices and other last rows.
    static Camera from_matrices(const glm::dmat4& view, const glm::dmat4& projection,
                                ClipDepthRange range, bool reversed_z = false);
    // A pinhole camera (CameraConvention above) posed by camera_to_world, the camera's axes and
    // position in world space in `convention` (the inverse of the view matrix; OpenCV's axes are
    // turned into OpenGL's eye space by flipping y and z). Depth is standard (window depth in
    // [0, 1], near -> 0) unless reversed_z is set on the result; far = +infinity sets
    // infinite_far. The Renderer refuses an image size other than k.width x k.height. Throws
    // InputError (naming the field) for non-finite values (bar that far), fx or fy <= 0, width or
    // height < 1, not 0 < near < far, and a non-finite, non-affine or singular pose.
    static Camera from_intrinsics(const Intrinsics& k, const glm::dmat4& camera_to_world,
                                  CameraConvention convention = CameraConvention::OpenCV);

    glm::dmat4 view() const;
    // aspect = width / height; ignored by cameras from matrices and intrinsics.
    glm::dmat4 projection_matrix(double aspect) const;
    ClipDepthRange clip_depth_range() const {
        if (given_projection) return given_projection->range;
        return reversed_z ? ClipDepthRange::ZeroToOne : ClipDepthRange::NegativeOneToOne;
    }
    // P * V rounded as docs/bench-scenes.md does it: V and P rounded to float, multiplied in
    // double, rounded to float. Using this everywhere makes zraster and the llvmpipe harness agree.
    glm::mat4 view_projection(double aspect) const;

    // The eye in world space: eye, or the origin of the inverse view matrix.
    glm::dvec3 position() const;
    // The unit view direction in world space: normalize(target - eye), or eye-space -z through the
    // inverse view matrix. Lighting's view axis (towards the viewer) is its negation.
    glm::dvec3 view_direction() const;
    bool is_orthographic() const;

    // fx, fy, cx, cy of this camera for an image of width x height pixels, in `convention`, with
    // its near and far (far is infinity with infinite_far). Exactly the intrinsics given to
    // from_intrinsics() for the same size and convention. Throws InputError for an orthographic
    // camera and for projections that are no pinhole (skew, or x and y rows that depend on the
    // other axis).
    Intrinsics intrinsics(int width, int height,
                          CameraConvention convention = CameraConvention::OpenCV) const;
    // The pose in `convention`: the inverse of the view matrix, its y and z axes (columns 1, 2)
    // negated for OpenCV.
    glm::dmat4 camera_to_world(CameraConvention convention = CameraConvention::OpenCV) const;
};

// Throws InputError (naming the field) when `camera` cannot render a width x height image:
// non-finite or degenerate look-at parameters, field of view, near and far, non-finite or singular
// matrices, intrinsics out of range or for another image size.
ZRASTER_API void check_camera(const Camera& camera, int width, int height);

// Metric depth of a window depth: the distance along the view axis (eye-space -z) of the points
// the camera maps to it, for standard, reversed-Z and infinite-far perspective and orthographic
// projections (the inverse of the projection's z and w rows; +infinity at an infinite far
// plane). Throws InputError for a projection whose depth depends on eye-space x or y.
ZRASTER_API double linear_depth(const Camera& camera, double window_depth);

// The coordinates a camera may use: fit_camera frames points within +-kMaxCoordinate, and
// check_camera takes an eye and target within +-kMaxCameraCoordinate (a fitted camera stands a
// few radii out). The pipeline's matrices and clip coordinates are single precision, whose range
// ends at 3.4e38; a camera fitted around coordinates near that end overflowed it and drew
// nothing. (Vertices beyond are not refused: far from the view they are simply culled.)
inline constexpr double kMaxCoordinate = 1e30;
inline constexpr double kMaxCameraCoordinate = 1e32;

// The benchmark framing (docs/bench-scenes.md): center = middle of the axis-aligned box of the
// points, radius = max |p - center| (double), fovy = 60 degrees, eye = center + dist *
// normalize(1, 1, 2) with dist = radius / sin(fovy / 2), up = +y, near = dist - 1.01 r,
// far = dist + 1.01 r.
// An empty or degenerate point set (radius 0) gets radius 1. Throws InputError (naming no file)
// when a finite point lies beyond kMaxCoordinate.
ZRASTER_API Camera fit_camera(std::span<const glm::vec3> world_points, double fovy_degrees = 60.0);

// A camera circling `target` at `distance`: azimuth around +y from +z towards +x, elevation above
// the xz plane (degrees). near/far are left for the caller.
ZRASTER_API Camera orbit_camera(const glm::dvec3& target, double distance, double azimuth_degrees,
                                double elevation_degrees, double fovy_degrees = 60.0);

// Normals transform by the inverse-transpose of the upper 3x3 of the model-view matrix (it keeps
// them perpendicular to surfaces under non-uniform scale).
ZRASTER_API glm::mat3 normal_matrix(const glm::mat4& model_view);

}  // namespace zraster
