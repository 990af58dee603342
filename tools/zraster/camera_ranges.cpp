#include "camera_ranges.hpp"

#include <fmt/format.h>

#include <cmath>

namespace zraster::cli {

std::string position_problem(const glm::dvec3& p) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(p[i]) || std::abs(p[i]) > kMaxPosition)
            return fmt::format("{} is beyond the +-1e32 a camera or light may use", p[i]);
    return "";
}

std::string direction_problem(const glm::dvec3& d) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(d[i]) || std::abs(d[i]) > kMaxDirectionComponent)
            return fmt::format("{} is beyond the +-1e30 a direction may use", d[i]);
    if (!(glm::length(d) >= kMinDirectionLength))
        return "the direction is zero (or shorter than 1e-30)";
    return "";
}

std::string fovy_problem(double degrees) {
    if (!(degrees >= kMinFovy && degrees <= kMaxFovy))
        return fmt::format("must be in 0.001..179.999 degrees, not {}", degrees);
    return "";
}

std::string distance_problem(double distance) {
    if (!(distance >= kMinDistance && distance <= kMaxDistance))
        return fmt::format("must be in 1e-20..1e30 scene units, not {}", distance);
    return "";
}

std::string orbit_problem(const glm::dvec3& orbit) {
    if (!(std::abs(orbit.x) <= kMaxAzimuth))
        return fmt::format("azimuth must be in -1e6..1e6 degrees, not {}", orbit.x);
    if (!(std::abs(orbit.y) <= 90.0))
        return fmt::format("elevation must be in -90..90 degrees, not {}", orbit.y);
    if (!(orbit.z > 0.0 && orbit.z <= kMaxOrbitDistance))
        return fmt::format("distance must be in (0, 1e6] scene radii, not {}", orbit.z);
    return "";
}

std::string intrinsics_problem(const glm::dvec4& k) {
    static const char* const kNames[] = {"fx", "fy", "cx", "cy"};
    for (int i = 0; i < 4; ++i) {
        const bool focal = i < 2;
        if (focal && !(k[i] >= 1e-3 && k[i] <= 1e9))
            return fmt::format("{} must be in 0.001..1e9 pixels, not {}", kNames[i], k[i]);
        if (!focal && !(std::abs(k[i]) <= 1e9))
            return fmt::format("{} must be within +-1e9 pixels, not {}", kNames[i], k[i]);
    }
    return "";
}

std::string pose_problem(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up) {
    if (glm::length(target - eye) == 0.0) return "the eye and the target are the same point";
    if (glm::length(glm::cross(target - eye, up)) == 0.0)
        return "the up direction is parallel to the view direction (from the eye to the target)";
    return "";
}

}  // namespace zraster::cli
