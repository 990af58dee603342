// Occluder triangle setup: clip-space triangle -> clipped, culled, projected OccluderTriangles
// whose coverage and depth bounds are conservative (occluder_setup.cpp explains the margins).
#pragma once
#include <zraster/occlusion_buffer.hpp>

#include <glm/glm.hpp>

#include <cstdint>

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

// Sets up triangle `triangle` of `source` through setup_occluder (the setup kernels' path for
// triangles that need clipping) and writes its pieces to `out` from index n on; returns the
// index past them.
std::size_t append_clipped_occluder(const OccluderSource& source, std::size_t triangle,
                                    OccluderBatch& out, std::size_t n);

// Which edges of triangle `triangle` (bit k: from corner k to corner k + 1) are interior edges of
// a mesh: the previous or the next triangle of the index list holds the same edge reversed and
// faces the same way (both vertices sets in front of the eye, w > 0). Pixel centers on such an
// edge belong to one of the two triangles in any rasterizer, so the setup covers them from both
// sides instead of leaving a seam. Quads as two triangles, strips and fans are found; other
// meshes keep their margins.
// (Inline: it runs for every triangle, and most have no shared edge.)
int orientation(const OccluderSource& source, const std::uint32_t* triangle);
// Bit k set when edge k of triangle t (corner k to corner k + 1) appears reversed in u.
inline std::uint32_t reversed_edges(const std::uint32_t* t, const std::uint32_t* u) {
    // Where each corner of t sits in u (3: absent).
    int at[3];
    for (int k = 0; k < 3; ++k) at[k] = t[k] == u[0] ? 0 : t[k] == u[1] ? 1 : t[k] == u[2] ? 2 : 3;
    std::uint32_t bits = 0;
    for (int k = 0; k < 3; ++k) {
        const int a = at[k], b = at[(k + 1) % 3];
        // t goes a -> b; u must go b -> a, i.e. a follows b in u.
        if (a < 3 && b < 3 && a == (b + 1) % 3) bits |= 1u << k;
    }
    return bits;
}

inline std::uint32_t interior_edges(const OccluderSource& s, std::size_t triangle) {
    const std::uint32_t* t = s.indices + 3 * triangle;
    std::uint32_t shared = 0;
    int self = 2;  // not computed yet
    for (int side = 0; side < 2; ++side) {
        const std::size_t other = side == 0 ? triangle - 1 : triangle + 1;
        if (other >= s.triangle_count) continue;  // also catches triangle - 1 wrapping around
        const std::uint32_t* u = s.indices + 3 * other;
        const std::uint32_t found = reversed_edges(t, u);
        if (!found) continue;
        if (u[0] >= s.vertex_count || u[1] >= s.vertex_count || u[2] >= s.vertex_count) continue;
        if (self == 2) self = orientation(s, t);
        if (self != 0 && orientation(s, u) == self) shared |= found;
    }
    return shared;
}

}  // namespace zraster::detail
