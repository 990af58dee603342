// The layouts the back end's stages share: screen tiles, the 8x8 blocks inside them, the tile
// buffers' rows, and the 32-bit triangle reference a tile stores per pixel. One place for the
// numbers, with the assertions that tie them together.
#pragma once
#include <zraster/clip.hpp>
#include <zraster/precision.hpp>

#include <cstddef>
#include <cstdint>

namespace zraster::detail {

// Screen tiles of kTileSize x kTileSize pixels: the unit of binning and of the back end's
// parallelism (a tile owns its pixels).
inline constexpr int kTileSize = 64;
// Blocks of kBlockSize x kBlockSize pixels inside a tile: accepted or rejected whole by their
// corners, and the cells of hierarchical z.
inline constexpr int kBlockSize = 8;
inline constexpr int kBlocksPerTileRow = kTileSize / kBlockSize;
// Row stride of the tile buffers (TileBuffers): one tile row per buffer row.
inline constexpr int kTileStride = kTileSize;

static_assert(kTileSize % kBlockSize == 0, "blocks tile a tile exactly");
static_assert(kTileStride >= kTileSize, "a tile row fits a buffer row");
static_assert(kMaxViewport / kTileSize <= 256, "tile coordinates fit a byte (TriangleRef)");

// The pixel (x, y) of a tile, as an index into its buffers.
constexpr std::size_t tile_index(int x, int y) {
    return static_cast<std::size_t>(y * kTileStride + x);
}

// A pixel's triangle reference: chunk << kChunkLocalBits | index of the ref in the chunk.
// kNoTriangle marks pixels nothing covers.
inline constexpr std::uint32_t kNoTriangle = 0xffffffffu;
inline constexpr int kChunkLocalBits = 20;
inline constexpr std::uint32_t kChunkLocalMask = (std::uint32_t{1} << kChunkLocalBits) - 1;
// The front end's chunks: at most kMaxChunks per frame, of at most kMaxChunkTriangles triangles
// (assemble_and_bin sizes them), so at most kMaxFrameTriangles triangles a frame.
inline constexpr std::size_t kMaxChunks = 4000;
inline constexpr std::size_t kMinChunkTriangles = 4096;
inline constexpr std::size_t kMaxChunkTriangles = 65536;
inline constexpr std::size_t kMaxFrameTriangles = kMaxChunks * kMaxChunkTriangles;
// Homogeneous clipping makes at most this many pieces of a triangle (a convex polygon of at most
// kMaxClippedVertices corners, fanned).
inline constexpr std::size_t kMaxPiecesPerTriangle = kMaxClippedVertices - 2;

static_assert(kMaxChunkTriangles * kMaxPiecesPerTriangle <= kChunkLocalMask,
              "every ref of a chunk has a local index");
static_assert(((kMaxChunks - 1) << kChunkLocalBits | kChunkLocalMask) < kNoTriangle,
              "no reference is kNoTriangle");
static_assert(kMaxChunks <= (std::size_t{1} << (32 - kChunkLocalBits)), "chunks fit the top bits");

constexpr std::uint32_t triangle_reference(std::uint32_t chunk, std::uint32_t local) {
    return chunk << kChunkLocalBits | local;
}
constexpr std::uint32_t reference_chunk(std::uint32_t reference) {
    return reference >> kChunkLocalBits;
}
constexpr std::uint32_t reference_local(std::uint32_t reference) {
    return reference & kChunkLocalMask;
}

}  // namespace zraster::detail
