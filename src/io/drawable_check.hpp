// A loaded scene must have something to draw: a file whose every triangle has zero area (all
// corners repeated or collinear, or placed by a transform that flattens them) would render an
// empty image without a word.
#pragma once
#include <zraster/scene.hpp>

#include <string>

namespace zraster::io {

// Throws InputError(file, ...) when no triangle of any instance has a nonzero area as placed.
void check_some_triangle_has_area(const Scene& scene, const std::string& file);

}  // namespace zraster::io
