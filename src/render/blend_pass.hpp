// Blended surfaces (AlphaMode::Blend) in the z-buffer path. A tile first resolves and shades its
// opaque and alpha-tested surfaces as usual (blended triangles are set aside, in bin order);
// then each blended triangle is drawn again over the tile: every fragment in front of the
// opaque depth is shaded and kept, and each pixel's fragments are composited over the opaque
// color, farthest first ("over", Porter & Duff 1984), as the A-buffer composites its lists.
// On the block traversal the visibility kernel finds (and, for SIMD Phong instances, lights)
// the fragments in a side buffer, and the kernels of blend_kernels.hpp keep them in per-pixel
// slots and composite them a vector of pixels at a time.
// Fragments are ordered by depth, then by content (alpha, color), then by instance and
// triangle: the image does not depend on the order the triangles were submitted in, and since
// a tile's pixels are its own, not on the thread count either. Blended fragments write no
// depth, ids or normals.
#pragma once
#include <zraster/depth_buffer.hpp>
#include <zraster/raster.hpp>

#include "render/blend_scratch.hpp"
#include "render/frame.hpp"
#include "render/tile_context.hpp"

#include <cstdint>

namespace zraster::detail {

struct BlendCounts {
    std::uint64_t fragments = 0;  // composited
    std::uint64_t pixels = 0;     // with at least one
};

// Draws scratch.triangles over the tile `c`, whose buffers `tile` hold the opaque depths (as
// stored) and whose color is already in the color target, and composites their fragments
// there. `side`: a side buffer (mask_pass.hpp's make_side_buffer).
BlendCounts composite_blended(const TileContext& c, const TileBuffers& tile, TileBuffers& side,
                              BlendScratch& scratch);

}  // namespace zraster::detail
