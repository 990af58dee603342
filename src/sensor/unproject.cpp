// Point clouds from z images: each measured pixel's sample ray followed to its depth.
#include <zraster/depth_camera.hpp>
#include <zraster/error.hpp>

#include "sensor/pixel_rays.hpp"

#include <cmath>

namespace zraster {

PointCloud unproject(const Camera& camera, int width, int height, std::span<const float> z,
                     std::span<const std::uint8_t> rgba, std::span<const glm::vec3> normals) {
    sensor::check_image_span("z", z.size(), width, height);
    if (!rgba.empty()) sensor::check_image_span("rgba", rgba.size() / 4, width, height);
    if (!rgba.empty() && rgba.size() % 4 != 0)
        throw InputError("rgba", "must hold 4 bytes per pixel");
    if (!normals.empty()) sensor::check_image_span("normals", normals.size(), width, height);
    const sensor::PixelRays rays(camera, width, height);
    const glm::dmat4 eye_to_world = camera.camera_to_world(CameraConvention::OpenGL);
    PointCloud cloud;
    std::size_t count = 0;
    for (const float value : z) count += value > 0.0f && std::isfinite(value);
    cloud.positions.reserve(count);
    cloud.pixels.reserve(count);
    if (!rgba.empty()) cloud.colors.reserve(count * 3);
    if (!normals.empty()) cloud.normals.reserve(count);
    for (int py = 0; py < height; ++py) {
        for (int px = 0; px < width; ++px) {
            const std::size_t i = std::size_t(py) * std::size_t(width) + std::size_t(px);
            if (!(z[i] > 0.0f) || !std::isfinite(z[i])) continue;
            const glm::dvec3 eye = rays.eye_point(px, py, double(z[i]));
            cloud.positions.push_back(glm::vec3(glm::dvec3(eye_to_world * glm::dvec4(eye, 1.0))));
            cloud.pixels.push_back(static_cast<std::uint32_t>(i));
            if (!rgba.empty())
                cloud.colors.insert(cloud.colors.end(), &rgba[i * 4], &rgba[i * 4 + 3]);
            if (!normals.empty()) cloud.normals.push_back(normals[i]);
        }
    }
    return cloud;
}

}  // namespace zraster
