// The extension module zraster._zraster: zraster's scenes, cameras and Renderer for Python, with
// numpy arrays in and out (docs/python.md). The package zraster/__init__.py re-exports it.
#include <zraster/version.hpp>

#include "binding.hpp"
#include "depth_outputs.hpp"

PYBIND11_MODULE(_zraster, m) {
    using namespace zraster::python;
    m.doc() =
        "zraster: an exact, fast CPU rasterizer. Scenes from files or numpy arrays, rendered "
        "into numpy arrays (color, depth, normals, ids).";
    m.attr("__version__") = zraster::kVersionString;
    bind_errors(m);
    bind_material(m);
    bind_mesh(m);
    bind_scene(m);
    bind_camera(m);
    bind_renderer(m);
    bind_depth_camera(m);
    bind_batch(m);
}
