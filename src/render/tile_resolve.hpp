// Finishing a tile: its resolved visibility to the targets (deferred shading of every visible
// pixel once, background elsewhere, depth and ids), or, for a tile nothing was drawn in, the
// cleared values.
#pragma once
#include <cstdint>

#include "raster/visibility_kernel.hpp"
#include "render/tile_context.hpp"

namespace zraster::detail {

// The targets of a tile where nothing was drawn, from rows of the cleared values (decoded
// depth, background color).
void clear_tile_targets(const TileContext& c, const float* clear_row,
                        const std::uint32_t* background_row);

// Zeroes a tile's rows of the coverage counts (they are counted up as fragments pass).
void clear_tile_counts(const TileContext& c);

// Writes a drawn tile's depth and id targets and shades its visible pixels (those not shaded
// as they passed): with tagged shading the SIMD shader colors the tagged pixels a row at a
// time, and only the others go pixel by pixel. Returns the number of pixels shaded.
std::uint64_t resolve_tile(const TileContext& c, const TileBuffers& tile,
                           const std::uint32_t* background_row);

}  // namespace zraster::detail
