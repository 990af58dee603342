// The occlusion buffer's storage and its kernels: setting up occluder triangles
// (occluder_setup_kernel.cpp), rasterizing them into the tiles (occluder_raster_kernel.cpp), and
// the coarse levels and rectangle tests (occlusion_query_kernel.cpp). Each kernel has a SIMD
// version (Google Highway, dispatched at run time) and a scalar reference twin with the same
// operations in the same order; tests compare the two bit for bit.
#pragma once
#include <hwy/aligned_allocator.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace zraster::detail {

inline constexpr int kOcclusionTileWidth = 16;  // pixels: one bit each in a row mask
inline constexpr std::uint32_t kOcclusionFullMask =
    kOcclusionTileWidth == 32 ? ~0u : (1u << kOcclusionTileWidth) - 1u;
inline constexpr int kOcclusionTileHeight = 16;  // pixel rows: one SIMD lane each
inline constexpr float kEmptyNearDepth = 0.0f;   // identity of the working layer's max
inline constexpr float kClearFarDepth = 1.0f;    // the far plane

// The pixel rows of the buffer, in column strips one tile wide. For each pixel row of a strip:
// the coverage mask of the working (near) layer and the two depth bounds. Invariants, for every
// pixel p of row y (true_depth = nearest occluder depth at p's center, 1 where none):
//   true_depth(p) <= far_depth[y]
//   true_depth(p) <= near_depth[y]   when bit p of mask[y] is set
//   mask[y] != kOcclusionFullMask (a full mask is folded into far_depth at once), near_depth[y] <=
//   far_depth[y]
// Rows are contiguous within a strip, so the 16 rows from any y are one vector: a triangle up to
// 16 rows tall is one vector per strip wherever it starts (with tiles of fixed rows, about half of
// the 9-row triangles of a typical occluder mesh straddle two). Tiles (16 x 16) remain the unit
// of the coarse levels and of the rectangle test.
// Each strip has this many rows past its last tile row, for whole-vector loads from any row.
inline constexpr int kStripPaddingRows = kOcclusionTileHeight;
inline std::size_t strip_row_count(int tiles_y) {
    return static_cast<std::size_t>(tiles_y) * kOcclusionTileHeight + kStripPaddingRows;
}

// An occluder triangle ready for the tiles (made by setup_occluder in occluder_setup.cpp for
// triangles that need clipping; the rasterizer reads them from an OccluderBatch, below). Pixel
// row y (center y + 0.5) covers
// the columns px with
//   max_k(left_x[k] + (y - y0) * left_step[k]) < px + 0.5 < min_k(right_x[k] + (y - y0) *
//   right_step[k])
// where the edge lines are already moved inwards by their error margin; an edge on the other
// side (or horizontal) is -kNoEdge (left) or +kNoEdge (right) with step 0. With
//   d(y, xe) = ((z_origin + z_dy * ((y - y0) + z_ky)) + z_bias) + z_dx * ((xe - x0) + z_kx),
// the depth bound of the covered pixels of row y within a tile is the smaller of
// min(d(y, xe), z_max) for the extreme covered column xe of the row (the last one when
// z_dx > 0, else the first) and d(y, xt) for the tile's extreme column xt in that direction.
// Edges per side: a triangle's edges going down are on one side and those going up on the
// other, so a side has at most two (horizontal edges are left to the row range). An unused
// slot holds -kNoEdge (left) or +kNoEdge (right), or repeats the side's other edge.
inline constexpr int kEdgeSlots = 2;
struct OccluderTriangle {
    int x0 = 0, x1 = -1, y0 = 0, y1 = -1;  // pixel bounding box, inclusive, inside the viewport
    float left_x[kEdgeSlots], left_step[kEdgeSlots];
    float right_x[kEdgeSlots], right_step[kEdgeSlots];
    float z_origin, z_dx, z_dy, z_kx, z_ky, z_bias, z_max;
};
inline constexpr float kNoEdge = 1e30f;

// Occluder triangles to set up: clip-space positions and three indices per triangle.
struct OccluderSource {
    const float* clip = nullptr;  // x, y, z, w per vertex
    std::size_t vertex_count = 0;
    const std::uint32_t* indices = nullptr;
    std::size_t triangle_count = 0;
    int width = 0, height = 0;
    bool cull_back = true, cull_front = false;
    bool front_face_clockwise = false;
    float subpixel_margin = 0.0f;  // OccluderOptions::subpixel_margin
};

// Constants of the float setup (occluder_setup.cpp explains the margins).
namespace occluder_setup {
constexpr float kGuardPixels = 4096.0f;  // window coordinates stay within 4096 px of the screen
constexpr float kMarginBase = 0x1p-14f, kMarginPerCoordinate = 0x1p-21f;
constexpr float kHorizontal = 0x1p-10f;  // |dy| below this: the row range bounds the edge
constexpr float kDepthSlack = 0x1p-20f, kHugeGradient = 1e30f, kMaxW = 1e30f;
enum Field {
    kLeftX,
    kLeftStep = kLeftX + kEdgeSlots,
    kRightX = kLeftStep + kEdgeSlots,
    kRightStep = kRightX + kEdgeSlots,
    kZOrigin = kRightStep + kEdgeSlots,
    kZDx,
    kZDy,
    kZKx,
    kZKy,
    kZBias,
    kZMax,
    kFloatFields
};
}  // namespace occluder_setup

// At most this many triangles per setup call; each may give up to 6 pieces (clipped).
inline constexpr std::size_t kSetupGroup = 64;
inline constexpr std::size_t kSetupOutput = kSetupGroup * 6;

// Set-up triangles as the rasterizer reads them: one array per field (the fields of
// OccluderTriangle, float ones indexed by occluder_setup::Field), so that the SIMD setup
// writes a whole vector of triangles per field with one compress and store. Room for one
// vector past kSetupOutput: the stores write whole vectors.
struct OccluderBatch {
    static constexpr std::size_t kCapacity = kSetupOutput + 16;
    alignas(64) std::int32_t x0[kCapacity], x1[kCapacity], y0[kCapacity], y1[kCapacity];
    alignas(64) float field[occluder_setup::kFloatFields][kCapacity];

    void set(std::size_t i, const OccluderTriangle& t) {
        namespace k = occluder_setup;
        x0[i] = t.x0;
        x1[i] = t.x1;
        y0[i] = t.y0;
        y1[i] = t.y1;
        for (int e = 0; e < kEdgeSlots; ++e) {
            field[k::kLeftX + e][i] = t.left_x[e];
            field[k::kLeftStep + e][i] = t.left_step[e];
            field[k::kRightX + e][i] = t.right_x[e];
            field[k::kRightStep + e][i] = t.right_step[e];
        }
        field[k::kZOrigin][i] = t.z_origin;
        field[k::kZDx][i] = t.z_dx;
        field[k::kZDy][i] = t.z_dy;
        field[k::kZKx][i] = t.z_kx;
        field[k::kZKy][i] = t.z_ky;
        field[k::kZBias][i] = t.z_bias;
        field[k::kZMax][i] = t.z_max;
    }
};

// Sets up triangles [first, first + count) (count <= kSetupGroup) into `out`, in order; returns
// how many triangles were written. Triangles inside the guard band and in front of the
// near plane are set up in float, many at a time; the others go through setup_occluder.
std::size_t setup_occluders(const OccluderSource& source, std::size_t first, std::size_t count,
                            OccluderBatch& out);
std::size_t setup_occluders_scalar(const OccluderSource& source, std::size_t first,
                                   std::size_t count, OccluderBatch& out);

// z_dx times the tile's extreme column in the direction the depth grows (relative to x0, plus
// z_kx): added to a row's depth it bounds the plane over that row of the tile.
inline float tile_depth_step(float z_dx, float z_kx, int x0, int tx) {
    const int column = tx * kOcclusionTileWidth + (z_dx > 0.0f ? kOcclusionTileWidth - 1 : 0);
    return z_dx * (static_cast<float>(column - x0) + z_kx);
}

struct TileGrid {
    // Row y of strip tx is element tx * strip_rows + y of each array (64-byte aligned, strip_rows
    // a whole number of tiles: a tile's rows are aligned vectors).
    std::uint32_t* mask = nullptr;
    float* far_depth = nullptr;
    float* near_depth = nullptr;
    std::size_t strip_rows = 0;
    // Two coarse levels per tile, side by side (coarse[2 i] and coarse[2 i + 1] for tile i: a
    // rectangle test reads both from one cache line), refreshed after each render call:
    //  - the smallest depth bound of its pixels: a rectangle touching a tile whose smallest
    //    bound is not in front of it is visible at once;
    //  - the largest far_depth of its rows: a tile the rectangle covers entirely is settled by
    //    one comparison when it is in front.
    float* coarse = nullptr;
    // The largest depth bound of each 8x8 pixel block (a tile's quarter), block rows of
    // 2 * tiles_x blocks, refreshed with the coarse levels. Exact, not rounded: a rectangle
    // covering a block whose largest bound is not in front of it is visible, the answer the
    // pixels would give, read from 1/32 of the tiles' memory.
    float* block_max = nullptr;
    int tiles_x = 0, tiles_y = 0;
    int width = 0, height = 0;  // pixels
};
// Index of row y of strip tx in the arrays of a TileGrid.
inline std::size_t row_index(const TileGrid& grid, int tx, int y) {
    return static_cast<std::size_t>(tx) * grid.strip_rows + static_cast<std::size_t>(y);
}

// The 16 rows of one tile (pointers into a TileGrid's arrays).
struct TileRows {
    const std::uint32_t* mask;
    const float* far_depth;
    const float* near_depth;
};
inline TileRows tile_rows(const TileGrid& grid, int tx, int ty) {
    const std::size_t at = row_index(grid, tx, ty * kOcclusionTileHeight);
    return {grid.mask + at, grid.far_depth + at, grid.near_depth + at};
}

// Owns the rows of a TileGrid (and clears them).
struct StripStorage {
    hwy::AlignedFreeUniquePtr<std::uint32_t[]> mask;
    hwy::AlignedFreeUniquePtr<float[]> depth;  // the far layers of all strips, then the near ones
    std::size_t rows = 0;                      // in all strips

    // Allocates rows for grid.tiles_x and grid.tiles_y (uninitialized) and points `grid` at them.
    void attach(TileGrid& grid) {
        grid.strip_rows = strip_row_count(grid.tiles_y);
        rows = static_cast<std::size_t>(grid.tiles_x) * grid.strip_rows;
        mask = hwy::AllocateAligned<std::uint32_t>(rows);
        depth = hwy::AllocateAligned<float>(2 * rows);
        grid.mask = mask.get();
        grid.far_depth = depth.get();
        grid.near_depth = depth.get() + rows;
    }
    // Empty: no coverage, far layers at the far plane.
    void clear() {
        std::fill_n(mask.get(), rows, 0u);
        // A tile's rows at a time: -O2 vectorizes a loop of a fixed count, not an open fill.
        float* far_depth = depth.get();
        for (std::size_t i = 0; i < rows; i += kOcclusionTileHeight)
            for (int r = 0; r < kOcclusionTileHeight; ++r) far_depth[i + r] = kClearFarDepth;
        std::fill_n(depth.get() + rows, rows, kEmptyNearDepth);
    }
};

inline constexpr int kOcclusionBlockSide = kOcclusionTileWidth / 2;
static_assert(kOcclusionTileWidth == kOcclusionTileHeight, "blocks are tile quarters");
// coarse holds this many floats past its last tile (one vector's worth).
inline constexpr std::size_t kCoarsePadding = 16;
// block_max's size: one more row of blocks and one vector past it (the rectangle test reads the
// first row of blocks it covers, or the one past them when it covers none).
inline std::size_t block_max_size(int tiles_x, int tiles_y) {
    return (2 * static_cast<std::size_t>(tiles_y) + 1) * (2 * static_cast<std::size_t>(tiles_x)) +
           kCoarsePadding;
}

// The bits of columns 0..n-1 of a row mask, n in [0, 32].
inline std::uint32_t low_bits(int n) {
    return n >= 32 ? ~0u : ~(~0u << n);
}

// Rasterizes triangles [0, count) in order.
void rasterize_occluders(const OccluderBatch& triangles, std::size_t count, TileGrid grid);
void rasterize_occluders_scalar(const OccluderBatch& triangles, std::size_t count, TileGrid grid);

// Recomputes the coarse levels and block maxima of tiles tx0..tx1, ty0..ty1 (inclusive).
void refresh_coarse_levels(TileGrid grid, int tx0, int ty0, int tx1, int ty1);
void refresh_coarse_levels_scalar(TileGrid grid, int tx0, int ty0, int tx1, int ty1);

// True when every pixel of columns x0..x1, rows y0..y1 (inclusive, inside the grid) holds a
// depth bound strictly less than `depth`.
bool rect_occluded(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth);
bool rect_occluded_scalar(const TileGrid& grid, int x0, int y0, int x1, int y1, float depth);

// A rectangle in window coordinates (x right, y down, in pixels; finite) whose nearest point has
// window depth `nearest` (finite, in front of the near plane): grown by a margin for the
// snapping of an exact rasterizer and the float error of its corners, converted to the pixels
// whose centers it may cover, and tested (`nearest` moved nearer by 2^-20). The conversion
// happens inside the kernel: one dispatch per test.
enum class WindowRectResult { kVisible, kOccluded, kOutsideView };
WindowRectResult window_rect_test(const TileGrid& grid, float xmin, float xmax, float ymin,
                                  float ymax, float nearest);
WindowRectResult window_rect_test_scalar(const TileGrid& grid, float xmin, float xmax, float ymin,
                                         float ymax, float nearest);

const char* occlusion_kernel_target();

}  // namespace zraster::detail
