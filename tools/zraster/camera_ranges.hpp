// The ranges of the camera and lighting numbers the command reads, from flags (--orbit, --fovy,
// --near, ...) and from --views-json files alike, so that both refuse the same values with the
// same cause (docs/limits.md lists them). Each function returns the cause, in the user's terms,
// or "" when the value is in range.
#pragma once
#include <glm/glm.hpp>

#include <string>

namespace zraster::cli {

// Positions (--eye, --target, --point-light; "eye", "target"): every coordinate within +-1e32.
inline constexpr double kMaxPosition = 1e32;
// Directions and planes (--up, --light-dir, --clip-plane): components within +-1e30, and a
// length of at least 1e-30 (anything shorter is zero once converted to float).
inline constexpr double kMaxDirectionComponent = 1e30;
inline constexpr double kMinDirectionLength = 1e-30;
// --fovy, "fovy": degrees.
inline constexpr double kMinFovy = 1e-3;
inline constexpr double kMaxFovy = 179.999;
// --near, --far, --ortho-height and their JSON fields: scene units.
inline constexpr double kMinDistance = 1e-20;
inline constexpr double kMaxDistance = 1e30;
// --orbit AZIMUTH,ELEVATION,DISTANCE: degrees, degrees within -90..90, scene radii.
inline constexpr double kMaxAzimuth = 1e6;
inline constexpr double kMaxOrbitDistance = 1e6;
// --eye without --near and --far: the near and far planes come from the scene's bounding sphere,
// at most this many radii away.
inline constexpr double kMaxEyeDistance = 1e7;

std::string position_problem(const glm::dvec3& p);
std::string direction_problem(const glm::dvec3& d);
std::string fovy_problem(double degrees);
std::string distance_problem(double distance);
std::string orbit_problem(const glm::dvec3& orbit);
// Pinhole intrinsics FX,FY,CX,CY (--intrinsics, a --views-json "K"): focal lengths of a
// thousandth of a pixel to 10^9 pixels (a field of view from 180 degrees down to 10^-6 of a degree
// at 16384 pixels), principal points within +-10^9 pixels.
std::string intrinsics_problem(const glm::dvec4& fx_fy_cx_cy);
// A look-at pose the camera can be built from: the eye away from the target, the up direction not
// along the view direction (the same tests the library's camera makes, in the command's terms).
std::string pose_problem(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up);

}  // namespace zraster::cli
