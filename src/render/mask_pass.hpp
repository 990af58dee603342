// Alpha-tested triangles (AlphaMode::Mask) on the block traversal. The visibility kernel finds
// a triangle's fragments in front of the tile's depths (coverage, depth test, barycentrics) in
// a side buffer; each is alpha-tested there, before anything is written; the fragments kept
// are then written to the tile as the kernel writes its own (depth, triangle reference, and the
// barycentrics, the interpolated attributes or, forward, the lit color). The scalar traversal
// (rasterize_scalar) alpha-tests the same fragments the same way: images are bit-identical.
#pragma once
#include <cstdint>
#include <memory>

#include "raster/visibility_kernel.hpp"
#include "render/tile_context.hpp"
#include "render/tile_traversal.hpp"

namespace zraster::detail {

// A tile buffer for the side passes (alpha-tested and blended triangles): its refs are
// kNoTriangle between passes, which leave them so.
std::unique_ptr<TileBuffers> make_side_buffer();

// Draws the alpha-tested triangle `t` into `tile` (with `side` as the side buffer). Returns the
// fragments kept; counts the discarded ones in c.counts.alpha_discarded.
std::uint64_t rasterize_masked(TileContext& c, const TileTriangle& t, TileBuffers& tile,
                               TileBuffers& side);

}  // namespace zraster::detail
