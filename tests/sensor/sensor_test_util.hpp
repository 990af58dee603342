// Scenes and cameras for the depth-camera tests: axis-aligned quads in front of a camera at the
// origin looking down -z.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>

#include <glm/glm.hpp>

#include <vector>

#include "render/render_test_util.hpp"

namespace zraster::test {

// The two counter-clockwise triangles (seen from +z) of the square [x0, x1] x [y0, y1] at z.
inline std::vector<glm::vec3> quad(float x0, float x1, float y0, float y1, float z) {
    return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y0, z}, {x1, y1, z}, {x0, y1, z}};
}

// The same square turned by `degrees` about the y axis through (0, 0, z): its normal leans
// towards +x.
inline std::vector<glm::vec3> tilted_quad(float half, float z, double degrees) {
    const double a = glm::radians(degrees);
    std::vector<glm::vec3> out;
    for (const glm::vec3& p : quad(-half, half, -half, half, 0.0f))
        out.push_back(glm::vec3(float(p.x * std::cos(a)), p.y, float(z - p.x * std::sin(a))));
    return out;
}

// A camera at the origin looking down -z with pinhole intrinsics (OpenCV, principal point at
// the image center).
inline Camera pinhole_camera(int width, int height, double focal, double near = 0.1,
                             double far = 50.0) {
    Intrinsics k;
    k.fx = k.fy = focal;
    k.cx = 0.5 * width - 0.5;
    k.cy = 0.5 * height - 0.5;
    k.width = width;
    k.height = height;
    k.near = near;
    k.far = far;
    Camera look;
    look.eye = glm::dvec3(0.0);
    look.target = glm::dvec3(0.0, 0.0, -1.0);
    return Camera::from_intrinsics(k, look.camera_to_world(CameraConvention::OpenCV));
}

inline RenderOptions options_for(const Camera& camera, int width, int height) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.camera = camera;
    o.threads = 2;
    o.cull = CullMode::None;
    return o;
}

}  // namespace zraster::test
