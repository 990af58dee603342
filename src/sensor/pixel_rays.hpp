// The geometry shared by the depth-camera functions: a camera's projection inverted per pixel
// (the eye-space point at a given z on a pixel's ray) and along its depth axis (window depth
// <-> z), in double.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/depth_buffer.hpp>

#include <glm/glm.hpp>

#include <span>
#include <string>

namespace zraster::sensor {

// Throws InputError(name, ...) unless `values` holds width * height elements.
void check_image_span(const char* name, std::size_t size, int width, int height);

// The projection's z and w rows, which depend on eye z alone for every camera these functions
// accept: window depth <-> z as linear_depth computes it.
class DepthAxis {
  public:
    explicit DepthAxis(const Camera& camera);
    // linear_depth(camera, window), the same operations in the same order.
    double z_of(double window) const;
    // The inverse: the window depth of the points at distance z along the axis.
    double window_of(double z) const;
    // The change of z across `steps` steps of a depth buffer of `format` at distance z: the
    // resolution the stored depth has there (for D32F a step is a float ulp of the window depth,
    // but no less than 2^-24 of it: the pipeline's float transform rounds relatively).
    double z_resolution(double z, DepthFormat format, double steps) const;

  private:
    double a_, b_, c_, e_;
    bool zero_to_one_;
};

// The eye-space point (OpenGL axes: x right, y up, looking down -z) at distance z along the axis
// on the ray through pixel (px, py)'s sample point (px + 0.5, py + 0.5), rows from the top. The
// projection maps eye x, y affinely for fixed z, so x = x0 + x1 z (likewise y) per pixel.
class PixelRays {
  public:
    PixelRays(const Camera& camera, int width, int height);
    glm::dvec3 eye_point(int px, int py, double z) const;
    // eye_point in parts, for loops over many pixels: the part of the projection's inverse that
    // depends on the column alone and on the row alone, then the point from the two (the same
    // operations as eye_point, so the same bits).
    double column_term(int px, double z) const;
    double row_term(int py, double z) const;
    glm::dvec3 eye_point_of_terms(double column, double row, double z) const;
    // Window coordinates (x right, y down, in pixels) of an eye-space point; false when it is
    // behind the center of projection.
    bool window_of(const glm::dvec3& eye, glm::dvec2& window) const;
    bool orthographic() const { return orthographic_; }

  private:
    glm::dmat4 projection_;
    glm::dmat2 inverse_xy_;  // of the projection's x and y columns restricted to x, y rows
    double width_, height_;
    bool orthographic_;
};

}  // namespace zraster::sensor
