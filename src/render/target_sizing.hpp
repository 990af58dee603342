// Sizing a RenderTargets for a frame: the Renderer's own targets and the debug views' auxiliary
// frames are both kept from frame to frame and sized the same way.
#pragma once
#include <zraster/render.hpp>

namespace zraster::detail {

// The arrays a frame fills besides depth, which it always fills.
struct WantedTargets {
    bool color = false, normal = false, ids = false, coverage = false;
};

// The arrays the options ask for (color_target, normal_target, id_targets, coverage_counts).
WantedTargets wanted_targets(const RenderOptions& options);

// `targets` sized for the options' image with depth and the wanted arrays (the others emptied,
// their memory kept), as views. The tiles zero the coverage counts.
TargetViews size_targets(RenderTargets& targets, const RenderOptions& options,
                         WantedTargets wanted);

}  // namespace zraster::detail
