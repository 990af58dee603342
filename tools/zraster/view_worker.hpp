// The viewer's render thread: frames are drawn here so that a slow one (painter's algorithm on a
// large mesh) never stops the window from taking input. The window asks for a frame, keeps
// showing the last finished one, and takes the new one when it is done. One frame at a time; a
// request made while one is drawn waits, and a newer request replaces it.
#pragma once
#include <zraster/debug_view.hpp>
#include <zraster/render.hpp>
#include <zraster/scene.hpp>
#include <zraster/visibility.hpp>

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "render_arguments.hpp"

namespace zraster::cli {

struct FrameRequest {
    RenderArguments arguments;
    DebugView view = DebugView::None;
    std::uint64_t serial = 0;  // ViewState::serial() of the state it shows
};

struct FrameResult {
    std::uint64_t serial = 0;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // empty when the frame failed
    RenderStats stats;
    DebugView view = DebugView::None;  // the debug view drawn (the pipeline's frames only)
    std::size_t polygons = 0;          // painter's, BSP, Warnock: after projection or in the tree
    double render_ms = 0.0;            // wall time of the whole frame, options included
    std::string error;                 // why the frame failed (a limit, a refused option)
};

// The options of one viewer frame, and the frame drawn as `zraster render` draws it (the
// pipeline's frames through a Renderer kept from frame to frame, which draws the same images).
class FrameDrawer {
  public:
    FrameDrawer(const Scene& scene, std::span<const glm::vec3> world)
        : scene_(scene), world_(world) {}
    FrameResult draw(const FrameRequest& request);

  private:
    const Scene& scene_;
    std::span<const glm::vec3> world_;
    Renderer renderer_;
};

class FrameWorker {
  public:
    FrameWorker(const Scene& scene, std::span<const glm::vec3> world);
    ~FrameWorker();  // waits for the frame being drawn
    FrameWorker(const FrameWorker&) = delete;
    FrameWorker& operator=(const FrameWorker&) = delete;

    void request(FrameRequest request);
    // The finished frame not yet taken, if any.
    std::optional<FrameResult> take();
    // A request is pending or being drawn, or its frame is not taken yet.
    bool busy() const;

  private:
    void run();

    FrameDrawer drawer_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<FrameRequest> pending_;
    std::optional<FrameResult> finished_;
    bool drawing_ = false, stopping_ = false;
    std::thread thread_;  // last: starts once the members above exist
};

}  // namespace zraster::cli
