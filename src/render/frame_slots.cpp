// The frame's per-thread working memory (Frame::slots, frame.hpp): one slot per thread of the
// arena a frame runs in.
#include <tbb/task_arena.h>

#include <memory>

#include "render/frame.hpp"

namespace zraster::detail {

void prepare_slots(Frame& frame) {
    const auto slots = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
    if (frame.slots.size() < slots) frame.slots.resize(slots);
    // A kept frame's slots get their tile buffers now, whichever threads later take tiles (a
    // one-shot frame's are made as its threads first need them).
    if (frame.cluster_cache.kept)
        for (SlotScratch& slot : frame.slots)
            if (!slot.tile) slot.tile = std::make_unique<TileBuffers>();
}

SlotScratch& Frame::slot() {
    return slots[static_cast<std::size_t>(tbb::this_task_arena::current_thread_index())];
}

}  // namespace zraster::detail
