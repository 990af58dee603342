// Whether a frame writes its target rows with non-temporal stores (stream_lines.hpp), and the
// working-set size past which it does.
#pragma once
#include "render/frame.hpp"

#include <cstddef>

namespace zraster::detail {

// True when the frame's bins, vertices and targets (target_bytes) exceed
// Frame::streaming_threshold: the targets will not be in the cache at the next frame, so writing
// them past it is cheaper.
bool stream_targets(const Frame& frame, std::size_t target_bytes);

}  // namespace zraster::detail
