// `zraster explain hiz`: hierarchical z at work. The hiz view (8x8 blocks the depth bounds let
// the rasterizer skip), the tiles view (the work binning hands each tile) and the depth buffer
// the bounds come from, side by side; then the same frame drawn nearest instance first, which
// lets the near surfaces hide more of what follows.
#include <zraster/render.hpp>

#include <fmt/format.h>

#include "debug_view_legend.hpp"
#include "explain_algorithms.hpp"
#include "explain_scene.hpp"

namespace zraster::cli {
namespace {

// The frame in `view`, its legend drawn in.
RgbaImage view_picture(const Scene& scene, const RenderOptions& options, DebugView view,
                       RenderStats* stats = nullptr) {
    RenderOptions o = options;
    o.view = view;
    const RenderResult r = render(scene, o);
    RgbaImage image = color_image(r.targets);
    draw_debug_view_legend(image, view, r.stats.view_scale);
    if (stats != nullptr) *stats = r.stats;
    return image;
}

RgbaImage depth_picture(const Scene& scene, const RenderOptions& options) {
    RenderOptions o = options;
    o.color_target = false;
    return depth_image(render(scene, o).targets, depth_clear_value(o));
}

}  // namespace

void explain_hiz(const ExplainInput& in, ExplainOutput& out) {
    // The two pictures: three views side by side, then two.
    check_explain_pixels(
        1, (5 * std::uint64_t(in.options.width) + 12) * std::uint64_t(in.options.height),
        in.max_pixels, "explain hiz's two pictures");
    const auto report = [&](double fraction) {
        if (in.options.progress != nullptr)
            in.options.progress->report("explain hiz: drawing the views", fraction);
    };
    RenderOptions options = in.options;
    options.occlusion_cull = false;  // every instance reaches the rasterizer
    RenderStats stats;
    const RgbaImage hiz = view_picture(in.scene, options, DebugView::HiZ, &stats);
    report(0.25);
    const RgbaImage tiles = view_picture(in.scene, options, DebugView::Tiles);
    report(0.5);
    const RgbaImage depth = depth_picture(in.scene, options);
    report(0.75);
    out.still("hiz",
              captioned(side_by_side(side_by_side(hiz, tiles), depth),
                        fmt::format("left: blocks skipped by hierarchical z ({} triangle x "
                                    "block skips); middle: triangles binned per tile; right: "
                                    "the depth buffer (near bright)",
                                    stats.blocks_hidden)),
              "Each 8x8 block keeps the farthest depth stored in it. A triangle whose nearest "
              "depth over a block cannot pass against that bound skips the block before any "
              "per-pixel work; the test is conservative, so the image is the same without it.");

    RenderOptions front_to_back = options;
    front_to_back.instance_order = InstanceOrder::FrontToBack;
    RenderStats sorted_stats;
    const RgbaImage sorted = view_picture(in.scene, front_to_back, DebugView::HiZ, &sorted_stats);
    out.still("hiz-front-to-back",
              captioned(side_by_side(hiz, sorted),
                        fmt::format("left: submission order ({} skips); right: nearest instance "
                                    "first ({} skips)",
                                    stats.blocks_hidden, sorted_stats.blocks_hidden)),
              "Drawn nearest first, the near surfaces set the blocks' bounds before the far "
              "ones arrive, and more of the far ones are skipped (an instance's triangles keep "
              "their order).");
}

}  // namespace zraster::cli
