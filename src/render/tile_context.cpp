// The frame's decisions for its tiles (tile_context.hpp).
#include "render/tile_context.hpp"

namespace zraster::detail {

ShadingPath choose_shading_path(const RenderOptions& options, const FrameTargets& targets,
                                bool tagged_shading) {
    if (!targets.color && !targets.normal) return ShadingPath::None;
    const bool forward = options.strategy == ShadingStrategy::Forward;
    if (tagged_shading) return forward ? ShadingPath::TaggedForward : ShadingPath::TaggedDeferred;
    return forward ? ShadingPath::ScalarForward : ShadingPath::Deferred;
}

Traversal choose_traversal(const RenderOptions& options, const FrameTargets& targets,
                           ShadingPath shading) {
    // The block kernel covers the common case; the rest takes the scalar reference path.
    const bool kernel = options.depth_format == DepthFormat::D32F && options.depth_test &&
                        !targets.coverage && shading != ShadingPath::ScalarForward;
    return kernel ? Traversal::Blocks : Traversal::Scalar;
}

void write_shaded(const TilePlan& plan, const ShadedFragment& fragment, int px, int py) {
    const TargetViews& t = plan.targets.views;
    if (t.color != nullptr) {
        std::uint8_t* rgba = target_row(t.color, t.color_pitch, py) + std::size_t(px) * 4;
        rgba[0] = to_unorm8(fragment.color.x);
        rgba[1] = to_unorm8(fragment.color.y);
        rgba[2] = to_unorm8(fragment.color.z);
        rgba[3] = 255;
    }
    if (t.normal != nullptr) target_row(t.normal, t.normal_pitch, py)[px] = fragment.normal;
}

}  // namespace zraster::detail
