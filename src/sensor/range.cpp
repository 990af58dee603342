// Range (eye to surface point) of a z image: z scaled by the length of each pixel's ray per unit
// of depth.
#include <zraster/depth_camera.hpp>

#include "sensor/pixel_rays.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <vector>

namespace zraster {

void range_from_z(const Camera& camera, int width, int height, std::span<const float> z,
                  std::span<float> range) {
    sensor::check_image_span("z", z.size(), width, height);
    sensor::check_image_span("range", range.size(), width, height);
    const sensor::PixelRays rays(camera, width, height);
    const bool orthographic = rays.orthographic();
    // The columns' part of each ray, once (its divisions are most of a pixel's cost).
    std::vector<double> columns(static_cast<std::size_t>(width));
    for (int px = 0; px < width; ++px) columns[std::size_t(px)] = rays.column_term(px, 1.0);
    // Rows in pieces on the caller's oneTBB arena: the same image for any number of threads.
    tbb::parallel_for(
        tbb::blocked_range<int>(0, height, 16), [&](const tbb::blocked_range<int>& rows) {
            for (int py = rows.begin(); py < rows.end(); ++py) {
                const double row = rays.row_term(py, 1.0);
                for (int px = 0; px < width; ++px) {
                    const std::size_t i = std::size_t(py) * std::size_t(width) + std::size_t(px);
                    if (!(z[i] > 0.0f) || orthographic) {
                        range[i] = z[i] > 0.0f ? z[i] : 0.0f;
                        continue;
                    }
                    // The ray's point at unit depth, its length the ratio range / z.
                    const double per_unit_z =
                        glm::length(rays.eye_point_of_terms(columns[std::size_t(px)], row, 1.0));
                    range[i] = static_cast<float>(double(z[i]) * per_unit_z);
                }
            }
        });
}

}  // namespace zraster
