// A debug view's picture (debug_view.hpp), painted into the color target from what the view's
// frame left: the auxiliary frames' targets and the per-triangle records (Frame::debug_view),
// the frame's bins, and the shaded image itself for the views that tint it. Serial and
// arithmetic on exact inputs only, so the picture is the same for any thread count.
#pragma once
#include <zraster/camera.hpp>
#include <zraster/debug_view.hpp>
#include <zraster/render.hpp>

#include "render/frame.hpp"

namespace zraster::detail {

struct ViewInputs {
    const Frame& frame;  // as the view's frame left it (record_triangles done)
    const TargetViews& targets;
    const Camera& camera;  // the frame's
};

// Replaces targets.color with the picture of `view`; returns its color scale's ends.
DebugViewScale paint_debug_view(DebugView view, const ViewInputs& in);

}  // namespace zraster::detail
