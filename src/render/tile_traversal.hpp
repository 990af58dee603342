// Finding a triangle's pixels in a tile and depth-testing them: the block traversal with the
// visibility kernel (hierarchical z, small triangles as one job) and the scalar reference path.
#pragma once
#include <zraster/raster.hpp>

#include <cstdint>

#include "raster/visibility_kernel.hpp"
#include "render/frame.hpp"
#include "render/tile_context.hpp"

namespace zraster::detail {

// A small triangle at most this many pixels wide in the tile is one kernel job
// (rasterize_blocks, JobWindow).
inline constexpr int kSingleJobColumns = 32;

// One triangle as the traversal draws it.
struct TileTriangle {
    const Chunk& chunk;
    const TriangleRef& ref;
    const TriangleSetup& setup;
    std::uint32_t id;  // its triangle reference (tile_layout.hpp), stored per pixel
    // Tagged shading: the corner attributes the kernel interpolates (null: untagged), a clipped
    // piece's corner weights (or null), and shading forward the SIMD shader's constants.
    const CornerAttributes* corners = nullptr;
    const glm::vec3* piece = nullptr;
    const PhongConstants* shade_constants = nullptr;
};

// What the kernel jobs of all triangles in a tile share.
BlockJob shared_job(const TilePlan& plan);

// The scalar reference path for one triangle over [x0, x1) x [y0, y1) of the tile: any depth
// format, the depth test off, coverage counts, forward shading, the alpha test. Returns the
// fragments that passed.
std::uint64_t rasterize_scalar(TileContext& c, const TileTriangle& t, TileBuffers& tile, int x0,
                               int y0, int x1, int y1);

// The block traversal of one triangle over the tile: 8x8 blocks classified by their corners,
// then the visibility kernel on the covered and partly covered ones (edges too long for 32-bit
// lanes: rasterize_scalar on that block). Returns the fragments that passed.
std::uint64_t rasterize_blocks(TileContext& c, const TileTriangle& t, TileBuffers& tile);

}  // namespace zraster::detail
