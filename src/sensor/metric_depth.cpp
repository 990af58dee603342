// Metric depth (z along the optical axis) of a rendered depth image: the projection's depth
// mapping inverted per pixel, as linear_depth does.
#include <zraster/depth_camera.hpp>
#include <zraster/error.hpp>

#include "sensor/pixel_rays.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace zraster {

void metric_depth(const Camera& camera, float clear_depth, std::span<const float> window_depth,
                  std::span<float> z) {
    if (window_depth.size() != z.size())
        throw InputError("z", "holds " + std::to_string(z.size()) + " values, window_depth " +
                                  std::to_string(window_depth.size()));
    const sensor::DepthAxis axis(camera);
    // Pixel by pixel, in pieces on the caller's oneTBB arena: each value depends on its pixel
    // alone, so the image is the same for any number of threads.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, z.size(), 16384),
                      [&](const tbb::blocked_range<std::size_t>& pixels) {
                          for (std::size_t i = pixels.begin(); i < pixels.end(); ++i) {
                              const float depth = window_depth[i];
                              // The clear value is what no fragment wrote: no surface, no
                              // measurement. (A surface at an infinite far plane would be
                              // infinitely far too: also nothing to measure.)
                              const double metric = depth == clear_depth ? 0.0 : axis.z_of(depth);
                              z[i] = std::isfinite(metric) ? static_cast<float>(metric) : 0.0f;
                          }
                      });
}

}  // namespace zraster
