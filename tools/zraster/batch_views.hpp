// The views `zraster batch` renders of each file: the camera flags' one view, N views on an orbit
// around the object (--views N --elevation E), or the cameras of a JSON file (--views-json; the
// schema is in docs/batch.md). Each view is a set of `zraster render` camera flags, so that a view
// is exactly the frame `zraster render` draws with those flags.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render_arguments.hpp"

namespace zraster::cli {

struct BatchView {
    std::string suffix;  // of the outputs' names: "" for the single view, else "_v00", "_v01", ...
    // The `zraster render` flags this view sets (empty or unset: the command's own value).
    std::string orbit, eye, target, up, intrinsics, size;
    std::optional<double> fovy, near, far;
    std::optional<double> ortho_height;  // set: --ortho --ortho-height
    bool infinite_far = false;
};

// The command's own camera, no suffix.
std::vector<BatchView> single_view();

// `count` views (1..1000) at azimuths 360 * i / count degrees, `elevation` degrees (-90..90),
// at the distance where the bounding sphere fills the vertical field of view (`fovy`, 60 when
// unset): --orbit AZIMUTH,ELEVATION,1/sin(fovy/2). Throws InputError naming --views or
// --elevation.
std::vector<BatchView> orbit_views(int count, double elevation, std::optional<double> fovy);

// The views of a --views-json file: an array of cameras (or one camera), each
//   {"eye": [x,y,z], "target": [x,y,z], "up"?: [x,y,z], "fovy"?, "near"?, "far"?}, or
//   {"orbit": [azimuth, elevation, distance in radii], "fovy"?, "near"?, "far"?}, or
//   what --camera-json writes: {"K": 3x3, "camera_to_world": 4x4 (OpenCV), "width", "height",
//   "near", "far" (null: infinite), "convention"?: "opencv"}.
// Throws InputError naming the file, the camera's index and the field.
std::vector<BatchView> read_views_json(const std::filesystem::path& path);

// `base` with the view's flags set.
RenderArguments with_view(const RenderArguments& base, const BatchView& view);

}  // namespace zraster::cli
