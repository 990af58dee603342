// Blended surfaces (AlphaMode::Blend) in the z-buffer path. A tile first resolves and shades its
// opaque and alpha-tested surfaces as usual (blended triangles are set aside, in bin order);
// then each blended triangle is drawn again over the tile: every fragment in front of the
// opaque depth is shaded and kept, and each pixel's fragments are composited over the opaque
// color, farthest first ("over", Porter & Duff 1984), as the A-buffer composites its lists.
// Fragments are ordered by depth, then by content (alpha, color), then by instance and
// triangle: the image does not depend on the order the triangles were submitted in, and since
// a tile's pixels are its own, not on the thread count either. Blended fragments write no
// depth, ids or normals.
#pragma once
#include <zraster/depth_buffer.hpp>
#include <zraster/raster.hpp>

#include "render/blend_scratch.hpp"
#include "render/frame.hpp"

#include <cstdint>

namespace zraster::detail {

struct BlendCounts {
    std::uint64_t fragments = 0;  // composited
    std::uint64_t pixels = 0;     // with at least one
};

// The tile [x0, x1) x [y0, y1) whose depths are `depth` (tile rows of kTileStride)
// and whose color is already in `targets.color`.
struct BlendTile {
    const Frame& frame;
    const DepthBuffer& codec;
    CompareFunc compare;
    const TargetViews& targets;
    const float* depth;
    int x0, y0, x1, y1;
};

// Draws scratch.triangles over the tile and composites their fragments into the color target.
BlendCounts composite_blended(const BlendTile& tile, BlendScratch& scratch);

}  // namespace zraster::detail
