// Binning: a counting sort of the front end's triangle refs into screen tiles, in two passes
// around a prefix sum over (tile, chunk). The front end counts a chunk's refs per tile as it
// makes them (count_in_bins); bin_triangles then places every run and writes the records there
// (see Frame::bin_run_offsets for the layout the back end streams).
#pragma once
#include "render/frame.hpp"

#include <cstddef>

namespace zraster::detail {

// Bytes of one bin record: a BinEntry, followed with tagged shading by the triangle's
// CornerAttributes.
constexpr std::size_t bin_record_bytes(bool tagged_shading) {
    return sizeof(BinEntry) + (tagged_shading ? sizeof(CornerAttributes) : 0);
}

// Bytes rounded up to whole cache lines (every run starts on one).
constexpr std::size_t whole_lines(std::size_t bytes) {
    return (bytes + kCacheLine - 1) / kCacheLine * kCacheLine;
}

// Counts a new ref in the bins of the tiles it touches (binning's first pass, done as refs are
// made: they are still in cache).
inline void count_in_bins(const Frame& frame, const TriangleRef& r, Chunk& chunk) {
    for (int ty = r.tile_y0; ty <= r.tile_y1; ++ty)
        for (int tx = r.tile_x0; tx <= r.tile_x1; ++tx)
            ++chunk.bin_counts[std::size_t(ty * frame.tiles_x + tx)];
}

// The second pass, after every chunk counted its refs: the runs' places, then every chunk's
// records written there (in parallel over chunks).
void bin_triangles(Frame& frame);

}  // namespace zraster::detail
