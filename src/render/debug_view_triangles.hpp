// What the front end made of each triangle of a frame (TriangleViewFlag), looked up by a
// pixel's instance and primitive ids: the backfaces and clipped views read the facing and the
// clipping the pipeline itself decided, not a recomputation of them.
#pragma once
#include <cstdint>

#include "render/frame.hpp"

namespace zraster::detail {

// Fills frame.debug_view's frame_instance and triangle_flags from the frame's refs.
void record_triangles(Frame& frame);

// The frame instance drawing scene instance `instance_id` (null: none, or -1).
const FrameInstance* frame_instance_of(const Frame& frame, std::int32_t instance_id);

// The flags of a pixel's triangle (0 for an empty pixel).
std::uint8_t triangle_flags_of(const Frame& frame, std::int32_t instance_id,
                               std::int32_t primitive_id);

}  // namespace zraster::detail
