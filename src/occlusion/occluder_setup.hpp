// Occluder triangle setup: clip-space triangle -> clipped, culled, projected OccluderTriangles
// whose coverage and depth bounds are conservative (occluder_setup.cpp explains the margins).
#pragma once
#include <zraster/occlusion_buffer.hpp>

#include <glm/glm.hpp>

#include "occlusion/occlusion_kernel.hpp"

namespace zraster::detail {

// A triangle clipped against the near plane and the guard band is a polygon of at most 8
// vertices: at most 6 pieces.
inline constexpr int kMaxOccluderPieces = 6;

// Appends the pieces of clip-space triangle (a, b, c) that cover pixel centers of a
// width x height viewport to `out`; returns how many (0 when culled, non-finite, degenerate,
// outside the view or between pixel centers).
int setup_occluder(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c, int width,
                   int height, const OccluderOptions& options, OccluderTriangle* out);

// Which edges of triangle `triangle` (bit k: from corner k to corner k + 1) are interior edges of
// a mesh: the previous or the next triangle of the index list holds the same edge reversed and
// faces the same way (both vertices sets in front of the eye, w > 0). Pixel centers on such an
// edge belong to one of the two triangles in any rasterizer, so the setup covers them from both
// sides instead of leaving a seam. Quads as two triangles, strips and fans are found; other
// meshes keep their margins.
std::uint32_t interior_edges(const OccluderSource& source, std::size_t triangle);

}  // namespace zraster::detail
