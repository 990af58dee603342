// Binning (binning.hpp).
#include "render/binning.hpp"

#include <zraster/error.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "memory/huge_pages.hpp"
#include "platform/memory_size.hpp"
#include "raster/bounding_box_pixels.hpp"
#include "render/shade_fragment.hpp"
#include "render/stream_lines.hpp"

namespace zraster::detail {
namespace {

// Writes a chunk's records at their final places (Frame::bin_run_offsets).
void write_bins(Frame& frame, std::size_t chunk_index) {
    const Chunk& chunk = frame.chunks[chunk_index];
    const std::size_t tiles = std::size_t(frame.tiles_x) * std::size_t(frame.tiles_y);
    const std::size_t chunks = frame.chunks.size();
    const std::size_t record = frame.bin_record_bytes;
    // The chunk's runs in a scratch buffer laid out like them (each on a cache line), kept
    // from chunk to chunk so it stays in cache (the slot's: sized for the largest chunk).
    SlotScratch& slot = frame.slot();
    std::vector<std::size_t>& run_start = slot.run_start;
    std::vector<std::size_t>& cursor = slot.cursor;
    std::size_t bytes = 0;
    for (std::size_t t = 0; t < tiles; ++t) {
        run_start[t] = cursor[t] = bytes;
        bytes += whole_lines(chunk.bin_counts[t] * record);
    }
    std::byte* scratch = align_to_cache_line(slot.bin_storage.data());
    for (std::uint32_t i = 0; i < chunk.refs.size(); ++i) {
        const TriangleRef& r = chunk.refs[i];
        // The first bin's record is written in place, the others copy it (a struct built on
        // the stack and copied out stalls on store forwarding).
        const std::byte* first = nullptr;
        for (int ty = r.tile_y0; ty <= r.tile_y1; ++ty)
            for (int tx = r.tile_x0; tx <= r.tile_x1; ++tx) {
                std::size_t& at = cursor[std::size_t(ty * frame.tiles_x + tx)];
                std::byte* to = scratch + at;
                at += record;
                if (first != nullptr) {
                    // (Sizes the compiler knows: a copy of a run-time size is a library call.)
                    if (record == bin_record_bytes(true))
                        std::memcpy(to, first, bin_record_bytes(true));
                    else
                        std::memcpy(to, first, sizeof(BinEntry));
                    continue;
                }
                first = to;
                BinEntry& entry = *reinterpret_cast<BinEntry*>(to);
                for (std::size_t k = 0; k < 3; ++k)
                    entry.vertices[k] = frame.screen_vertex(chunk, r, k);
                entry.ref = i | (r.piece == TriangleRef::kNotClipped ? 0 : BinEntry::kClippedPiece);
                if (frame.tagged_shading)
                    corner_attributes(frame, r,
                                      *reinterpret_cast<CornerAttributes*>(to + sizeof(BinEntry)));
            }
    }
    std::byte* records = frame.bin_records();
    for (std::size_t t = 0; t < tiles; ++t)
        if (cursor[t] != run_start[t])
            stream_lines(records + frame.bin_run_offsets[t * chunks + chunk_index],
                         scratch + run_start[t],
                         whole_lines(cursor[t] - run_start[t]) / kCacheLine);
    stream_fence();
}

// The runs' places from the chunks' counts: tile-major, chunks in order inside a tile, each
// run on a cache line.
void bin_offsets(Frame& frame) {
    const std::size_t tiles = std::size_t(frame.tiles_x) * std::size_t(frame.tiles_y);
    const std::size_t chunks = frame.chunks.size();
    const std::size_t record = frame.bin_record_bytes;
    frame.bin_run_offsets.resize(tiles * chunks);
    frame.bin_run_counts.resize(tiles * chunks);
    frame.tile_bin_counts.resize(tiles);
    // Each loop over tiles writes only its tile's slots: in parallel unless the table is small
    // (then two parallel loops cost more than they save).
    const auto over_tiles = [&](const auto& body) {
        if (tiles * chunks < (std::size_t{1} << 15))
            for (std::size_t t = 0; t < tiles; ++t) body(t);
        else
            tbb::parallel_for(std::size_t{0}, tiles, body);
    };
    // Per tile first (its runs' counts, in the tile-major table), then the tiles' bases, then
    // the runs' places.
    std::vector<std::size_t>& tile_bytes = frame.tile_bytes;
    tile_bytes.resize(tiles);
    over_tiles([&](std::size_t t) {
        std::size_t bytes = 0, count = 0;
        for (std::size_t c = 0; c < chunks; ++c) {
            const std::uint32_t n = frame.chunks[c].bin_counts[t];
            frame.bin_run_counts[t * chunks + c] = n;
            bytes += whole_lines(n * record);
            count += n;
        }
        tile_bytes[t] = bytes;
        frame.tile_bin_counts[t] = count;
    });
    std::vector<std::size_t>& tile_base = frame.tile_base;
    tile_base.assign(tiles + 1, 0);
    for (std::size_t t = 0; t < tiles; ++t) tile_base[t + 1] = tile_base[t] + tile_bytes[t];
    over_tiles([&](std::size_t t) {
        std::size_t at = tile_base[t];
        for (std::size_t c = 0; c < chunks; ++c) {
            frame.bin_run_offsets[t * chunks + c] = at;
            at += whole_lines(frame.bin_run_counts[t * chunks + c] * record);
        }
    });
    // Grown empty (nothing of the old records is worth copying, and new storage is advised),
    // never shrunk (a smaller frame then a larger one would zero the difference again).
    if (tile_base[tiles] > frame.options->limits.max_bin_bytes)
        throw LimitExceeded(
            "", "max_bin_bytes",
            "binning needs " + std::to_string(tile_base[tiles]) +
                " bytes of tile records (triangles times the tiles each covers), more than the "
                "limit of " +
                std::to_string(frame.options->limits.max_bin_bytes) +
                " (RenderLimits::max_bin_bytes): large triangles drawn over each other many "
                "times, or a frame too large for them");
    // Within a budget raised past the machine: refused before the allocation the system would
    // refuse, naming what to lower. (Asked only past the default budget: no system calls in the
    // frames of a view or a benchmark.)
    if (tile_base[tiles] > RenderLimits{}.max_bin_bytes &&
        tile_base[tiles] > platform::usable_memory_bytes())
        throw InputError("", "binning needs " + std::to_string(tile_base[tiles]) +
                                 " bytes of tile records, more than the memory this process may "
                                 "use (max_bin_bytes raised past it): lower --size or --aa, or "
                                 "--max-bin-bytes to what this machine holds");
    frame.bin_bytes = tile_base[tiles];
    const std::size_t bytes = tile_base[tiles] + kCacheLine;
    if (bytes > frame.bin_storage.capacity()) frame.bin_storage = {};
    if (bytes > frame.bin_storage.size()) memory::resize_on_huge_pages(frame.bin_storage, bytes);
}

// Without the depth test nothing is hidden: every fragment of every triangle is rasterized and
// shaded (--view overdraw's count, --no-depth-test); blended (transparent) triangles write no
// depth, so none hides another. A few large triangles drawn over each other many times are then
// minutes of work (and, blended, per-tile fragment lists of GB) in bins of a few hundred MB.
// Counted per triangle here, once per frame, never in the per-pixel loops; frames with the depth
// test and no transparent instance skip it.
void check_covered_samples(const Frame& frame) {
    const RenderOptions& options = *frame.options;
    const bool every = !options.depth_test;
    if (!every && !frame.alpha_instances) return;
    std::vector<std::uint64_t> per_chunk(frame.chunks.size(), 0);
    tbb::parallel_for(std::size_t{0}, frame.chunks.size(), [&](std::size_t c) {
        const Chunk& chunk = frame.chunks[c];
        std::uint64_t sum = 0;
        for (const TriangleRef& r : chunk.refs) {
            if (!every && frame.instances[r.instance].alpha != AlphaMode::Blend) continue;
            const ScreenVertex& a = frame.screen_vertex(chunk, r, 0);
            const ScreenVertex& b = frame.screen_vertex(chunk, r, 1);
            const ScreenVertex& d = frame.screen_vertex(chunk, r, 2);
            sum += bounding_box_pixels(std::min({a.x, b.x, d.x}), std::min({a.y, b.y, d.y}),
                                       std::max({a.x, b.x, d.x}), std::max({a.y, b.y, d.y}),
                                       options.width, options.height);
        }
        per_chunk[c] = sum;
    });
    std::uint64_t total = 0;
    for (const std::uint64_t n : per_chunk) total += n;
    detail::check_covered_samples(
        total, options.limits.max_covered_samples,
        every ? "with the depth test off (--view overdraw, --no-depth-test), the frame rasterizes "
                "every triangle whole"
              : "the frame's blended (transparent) triangles are rasterized whole (they write no "
                "depth: none hides another)");
}

}  // namespace

void bin_triangles(Frame& frame) {
    check_covered_samples(frame);
    bin_offsets(frame);
    // Every slot's scratch sized for the largest chunk before any takes one.
    std::size_t largest_chunk = 0;
    for (const Chunk& c : frame.chunks) largest_chunk = std::max(largest_chunk, c.bin_bytes);
    const std::size_t tiles = std::size_t(frame.tiles_x) * std::size_t(frame.tiles_y);
    for (SlotScratch& slot : frame.slots) {
        slot.run_start.resize(tiles);
        slot.cursor.resize(tiles);
        if (slot.bin_storage.size() < largest_chunk + kCacheLine)
            slot.bin_storage.resize(largest_chunk + kCacheLine);
    }
    tbb::parallel_for(std::size_t{0}, frame.chunks.size(),
                      [&](std::size_t c) { write_bins(frame, c); });
}

}  // namespace zraster::detail
