// Streaming a tile's bin records: the runs of every chunk in order (Frame::bin_run_offsets), a
// batch of up to kSetupLanes records at a time for the lane setup, with the records ahead
// prefetched.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "raster/setup_lanes.hpp"
#include "render/frame.hpp"

namespace zraster::detail {

// How far ahead of the record being set up the cursor prefetches. Every line of the record
// that far ahead is fetched: the runs were streamed out past the caches, and the hardware
// prefetcher stops at each 4 KiB page.
inline constexpr std::size_t kRecordPrefetchBytes = 2048;

// A batch of records and the chunk each belongs to.
struct RecordBatch {
    int count = 0;
    const std::byte* record[kSetupLanes];
    std::uint32_t chunk[kSetupLanes];

    const BinEntry& entry(int lane) const {
        return *reinterpret_cast<const BinEntry*>(record[lane]);
    }
    // The CornerAttributes after the entry (records of tagged shading).
    const CornerAttributes& corners(int lane) const {
        return *reinterpret_cast<const CornerAttributes*>(record[lane] + sizeof(BinEntry));
    }
};

class TileRecordCursor {
  public:
    TileRecordCursor(const Frame& frame, std::size_t tile_number)
        : records_(frame.bin_records()),
          record_bytes_(frame.bin_record_bytes),
          chunks_(frame.chunks.size()),
          run_offset_(frame.bin_run_offsets.data() + tile_number * chunks_),
          run_count_(frame.bin_run_counts.data() + tile_number * chunks_),
          remaining_(frame.tile_bin_counts[tile_number]) {
        next_run();
    }

    bool done() const { return remaining_ == 0; }

    // The next up to kSetupLanes records.
    void next(RecordBatch& batch) {
        batch.count = int(std::min<std::size_t>(remaining_, kSetupLanes));
        remaining_ -= std::size_t(batch.count);
        for (int lane = 0; lane < batch.count; ++lane) {
            batch.record[lane] = next_record_;
            prefetch_ahead(next_record_);
            batch.chunk[lane] = std::uint32_t(chunk_);
            if (--left_in_run_ == 0) {
                ++chunk_;
                next_run();
            } else {
                next_record_ += record_bytes_;
            }
        }
    }

  private:
    void next_run() {
        while (chunk_ < chunks_ && run_count_[chunk_] == 0) ++chunk_;
        if (chunk_ == chunks_) return;
        next_record_ = records_ + run_offset_[chunk_];
        left_in_run_ = run_count_[chunk_];
    }

    void prefetch_ahead(const std::byte* record) const {
        // (As addresses: that far ahead may be past the arena, where a pointer may not go.)
        const std::uintptr_t ahead =
            reinterpret_cast<std::uintptr_t>(record) + kRecordPrefetchBytes;
        static_assert(sizeof(BinEntry) + sizeof(CornerAttributes) <= 3 * kCacheLine);
        for (const std::size_t line :
             {std::size_t{0}, kCacheLine, 2 * kCacheLine, record_bytes_ - 1})
            __builtin_prefetch(reinterpret_cast<const void*>(ahead + line));
    }

    const std::byte* records_;
    std::size_t record_bytes_;
    std::size_t chunks_;
    const std::size_t* run_offset_;
    const std::uint32_t* run_count_;
    std::size_t remaining_;
    std::size_t chunk_ = 0, left_in_run_ = 0;
    const std::byte* next_record_ = nullptr;
};

}  // namespace zraster::detail
