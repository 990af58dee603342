// A frame with a debug view (RenderOptions::view): the auxiliary frames the view is painted
// from, then the frame itself exactly as without the view (depth, normals and ids unchanged),
// then its color target replaced by the picture. Frames without a view never come here, so the
// view costs them nothing; a view's frame costs one to three frames more.
#include <zraster/render.hpp>

#include <cstddef>

#include "render/debug_view_paint.hpp"
#include "render/debug_view_triangles.hpp"
#include "render/frame.hpp"
#include "render/target_sizing.hpp"

namespace zraster::detail {
namespace {

// Draws the auxiliary frames `view` is painted from into the scratch targets.
void draw_auxiliary_frames(Frame& frame, const SceneView& scene, std::string_view source,
                           const RenderOptions& options) {
    DebugViewScratch& s = frame.debug_view;
    s.options = options;
    s.options.view = DebugView::None;
    s.options.edges = RenderOptions::Edges::None;
    RenderStats ignored;
    if (options.view == DebugView::Overdraw) {
        // Every fragment rasterized counts: the depth test off, nothing hidden. Drawn first: its
        // budget (RenderLimits::max_covered_samples) then refuses a frame before any is drawn.
        s.options.depth_test = false;
        const TargetViews counts = size_targets(s.overdraw, options, {.coverage = true});
        draw_frame(frame, scene, source, s.options, counts, false, ignored);
        s.options.depth_test = options.depth_test;
    }
    const TargetViews visible = size_targets(s.visible, options, {.normal = true, .ids = true});
    draw_frame(frame, scene, source, s.options, visible, false, ignored);
    if (options.view == DebugView::ZFight && options.depth_format != DepthFormat::D32F) {
        s.options.depth_format = DepthFormat::D32F;
        const TargetViews ids = size_targets(s.reference, options, {.ids = true});
        draw_frame(frame, scene, source, s.options, ids, false, ignored);
    }
}

// Frame::hiz_block_counts for the duration of one frame, zeroed first.
class HizCounting {
  public:
    HizCounting(Frame& frame, const RenderOptions& options) : frame_(frame) {
        const std::size_t tiles_x = std::size_t((options.width + kTileSize - 1) / kTileSize);
        const std::size_t tiles_y = std::size_t((options.height + kTileSize - 1) / kTileSize);
        const std::size_t blocks =
            tiles_x * tiles_y * std::size_t(kBlocksPerTileRow * kBlocksPerTileRow);
        frame.debug_view.hiz_blocks.assign(blocks, 0);
        frame.hiz_block_counts = frame.debug_view.hiz_blocks.data();
    }
    ~HizCounting() { frame_.hiz_block_counts = nullptr; }
    HizCounting(const HizCounting&) = delete;
    HizCounting& operator=(const HizCounting&) = delete;

  private:
    Frame& frame_;
};

}  // namespace

void draw_debug_view(Frame& frame, const SceneView& scene, std::string_view source,
                     const RenderOptions& options, const TargetViews& targets, bool kept,
                     RenderStats& stats) {
    draw_auxiliary_frames(frame, scene, source, options);
    if (options.view == DebugView::HiZ) {
        const HizCounting counting(frame, options);
        draw_frame(frame, scene, source, options, targets, kept, stats);
    } else {
        draw_frame(frame, scene, source, options, targets, kept, stats);
    }
    record_triangles(frame);
    stats.view_scale = paint_debug_view(options.view, ViewInputs{frame, targets, stats.camera});
    // The color target no longer holds what the kept tiles' record says.
    frame.cleared_tiles.valid = false;
}

}  // namespace zraster::detail
