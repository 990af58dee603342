// The per-block visibility kernel of the tile rasterizer: coverage by edge functions, depth
// test and write, and the triangle reference plus perspective-correct barycentrics of every
// fragment that passes, into tile-local buffers (deferred shading reads them afterwards).
//
// Two implementations with bit-identical results: a scalar reference and a SIMD one (Google
// Highway, the instruction set picked at run time: AVX-512, AVX2, SSE4, NEON, scalar). The
// arithmetic is the same in both, operation by operation (no FMA: -ffp-contract=off), and a test
// compares them on random triangles.
#pragma once
#include <zraster/depth_buffer.hpp>
#include <zraster/raster.hpp>

#include <cstdint>

namespace zraster::detail {

inline constexpr std::uint32_t kNoTriangle = 0xffffffffu;

// Tile-local buffers with row stride kStride and padding, so a vector may run past the end of
// a row (into the next row or the padding) without leaving the buffer.
struct TileBuffers {
    static constexpr int kStride = 64;
    static constexpr int kPixels = kStride * kStride + 32;
    alignas(64) float depth[kPixels];  // D32F depth, or the D24/D16 unorm code as a float
    alignas(64) std::uint32_t ref[kPixels];
    alignas(64) float b1[kPixels];
    alignas(64) float b2[kPixels];
    // Hierarchical z: per 8x8 block (row-major, kStride / 8 per row), the farthest depth stored
    // in it (render/hierarchical_z.hpp).
    static constexpr int kBlocksPerRow = kStride / 8;
    alignas(64) float farthest[kBlocksPerRow * kBlocksPerRow];
};

// One block of at most 8 pixels wide (any height) of one triangle.
struct BlockJob {
    // Edge function values at the block's first pixel (x0, y0), and their steps per pixel in
    // x and in y. Exact: the caller checks that every value inside the block fits in 32 bits.
    std::int32_t e[3];
    std::int32_t step_x[3];
    std::int32_t step_y[3];
    bool full = false;               // all pixels covered: skip the edge tests
    int x0 = 0, y0 = 0;              // tile-local position of the block's first pixel
    int width = 0, height = 0;       // width <= 8
    int plane_dx = 0, plane_dy = 0;  // (x0, y0) relative to the triangle's plane origin
    const TriangleSetup* setup = nullptr;
    bool perspective = true;
    CompareFunc compare = CompareFunc::Less;
    bool write_depth = true;
    bool attributes = true;    // store the triangle reference (off: depth only)
    bool barycentrics = true;  // ... and the barycentrics (needs the setup's q, p1, p2 planes)
    std::uint32_t ref = 0;
};

// Returns the number of fragments that passed the depth test. D32F only.
int visibility_block(const BlockJob& job, TileBuffers& tile);
int visibility_block_scalar(const BlockJob& job, TileBuffers& tile);

// The farthest depth stored in the 8x8 block (block_x, block_y) of the tile: the largest when
// `largest`, else the smallest. Exact (a max/min over the stored values).
float block_farthest_depth(const TileBuffers& tile, int block_x, int block_y, bool largest);
float block_farthest_depth_scalar(const TileBuffers& tile, int block_x, int block_y, bool largest);

// Name of the instruction set the dispatcher picked (for reports).
const char* visibility_kernel_target();

}  // namespace zraster::detail
