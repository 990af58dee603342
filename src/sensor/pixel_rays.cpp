// The projection inverted per pixel and along the depth axis (pixel_rays.hpp).
#include "sensor/pixel_rays.hpp"

#include <zraster/error.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace zraster::sensor {

void check_image_span(const char* name, std::size_t size, int width, int height) {
    if (width < 1 || height < 1)
        throw InputError(name, "the image size must be at least 1x1, not " + std::to_string(width) +
                                   "x" + std::to_string(height));
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    if (size != pixels)
        throw InputError(name, "holds " + std::to_string(size) +
                                   " values, not width * height = " + std::to_string(pixels));
}

namespace {

// Whether the projection's z and w rows ignore eye x and y (so depth is a function of z alone,
// what linear_depth needs).
void check_depth_rows(const glm::dmat4& p) {
    if (p[0][2] != 0.0 || p[1][2] != 0.0 || p[0][3] != 0.0 || p[1][3] != 0.0)
        throw InputError("camera", "its projection's depth depends on more than eye z");
}

}  // namespace

DepthAxis::DepthAxis(const Camera& camera) {
    const glm::dmat4 p = camera.projection_matrix(1.0);  // z and w rows do not use the aspect
    check_depth_rows(p);
    a_ = p[2][2];
    b_ = p[3][2];
    c_ = p[2][3];
    e_ = p[3][3];
    zero_to_one_ = camera.clip_depth_range() == ClipDepthRange::ZeroToOne;
}

double DepthAxis::z_of(double window) const {
    const double z_ndc = zero_to_one_ ? window : 2.0 * window - 1.0;
    const double denominator = z_ndc * c_ - a_;
    if (denominator == 0.0) return std::numeric_limits<double>::infinity();  // infinite far
    return -((b_ - z_ndc * e_) / denominator);
}

double DepthAxis::window_of(double z) const {
    const double eye_z = -z;
    const double z_ndc = (a_ * eye_z + b_) / (c_ * eye_z + e_);
    return zero_to_one_ ? z_ndc : 0.5 * z_ndc + 0.5;
}

double DepthAxis::z_resolution(double z, DepthFormat format, double steps) const {
    const double window = window_of(z);
    double step = 0.0;
    switch (format) {
        case DepthFormat::D32F: {
            const float w = static_cast<float>(window);
            step =
                std::max(double(std::nextafter(w, 2.0f)) - double(w), std::abs(window) * 0x1.0p-24);
            break;
        }
        case DepthFormat::D24:
            step = 1.0 / double((1u << 24) - 1u);
            break;
        case DepthFormat::D16:
            step = 1.0 / 65535.0;
            break;
    }
    // Either side of the window depth, as far as it stays a depth; the larger change.
    double resolution = 0.0;
    for (const double side : {window - steps * step, window + steps * step}) {
        if (side < 0.0 || side > 1.0) continue;
        const double other = z_of(side);
        if (std::isfinite(other)) resolution = std::max(resolution, std::abs(other - z));
    }
    return resolution;
}

PixelRays::PixelRays(const Camera& camera, int width, int height)
    : projection_(camera.projection_matrix(double(width) / double(height))),
      width_(width),
      height_(height),
      orthographic_(camera.is_orthographic()) {
    check_depth_rows(projection_);
    const glm::dmat2 xy(projection_[0][0], projection_[0][1], projection_[1][0], projection_[1][1]);
    if (!(std::abs(glm::determinant(xy)) > 0.0))
        throw InputError("camera", "its projection maps eye x and y to a line");
    inverse_xy_ = glm::inverse(xy);
}

// The sample point in normalized device coordinates, as to_screen maps them (raster.hpp), and
// the projection's x and y rows solved for eye x and y at eye z = -z.
double PixelRays::column_term(int px, double z) const {
    const glm::dmat4& p = projection_;
    const double ndc_x = (double(px) + 0.5) / width_ * 2.0 - 1.0;
    const double eye_z = -z;
    const double w = p[2][3] * eye_z + p[3][3];
    return ndc_x * w - p[2][0] * eye_z - p[3][0];
}

double PixelRays::row_term(int py, double z) const {
    const glm::dmat4& p = projection_;
    const double ndc_y = 1.0 - (double(py) + 0.5) / height_ * 2.0;
    const double eye_z = -z;
    const double w = p[2][3] * eye_z + p[3][3];
    return ndc_y * w - p[2][1] * eye_z - p[3][1];
}

glm::dvec3 PixelRays::eye_point_of_terms(double column, double row, double z) const {
    const glm::dvec2 xy = inverse_xy_ * glm::dvec2(column, row);
    return {xy.x, xy.y, -z};
}

glm::dvec3 PixelRays::eye_point(int px, int py, double z) const {
    return eye_point_of_terms(column_term(px, z), row_term(py, z), z);
}

bool PixelRays::window_of(const glm::dvec3& eye, glm::dvec2& window) const {
    const glm::dvec4 clip = projection_ * glm::dvec4(eye, 1.0);
    if (!(clip.w > 0.0)) return false;
    window.x = (clip.x / clip.w + 1.0) * 0.5 * width_;
    window.y = (1.0 - clip.y / clip.w) * 0.5 * height_;
    return true;
}

}  // namespace zraster::sensor
