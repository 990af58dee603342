// A loaded scene must have something to draw: a file whose every triangle has zero area (all
// corners repeated or collinear, or placed by a transform that flattens them) would render an
// empty image without a word.
#pragma once
#include <zraster/mesh_view.hpp>
#include <zraster/scene.hpp>

#include <string>

namespace zraster::io {

// Throws InputError(file, ...) when no triangle of any instance has a nonzero area as placed.
void check_some_triangle_has_area(const Scene& scene, const std::string& file);
// The same over views (the Python module's scenes of the caller's arrays), `name` naming the
// scene; a scene of no triangles at all is refused too, as the loaders refuse such files.
// Triangles with an index past the vertices are passed over (the renderer refuses them).
void check_some_triangle_has_area(const SceneView& scene, const std::string& name);

}  // namespace zraster::io
