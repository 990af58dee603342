// When a frame's target rows are written with non-temporal stores (target_streaming.hpp).
#include "render/target_streaming.hpp"

namespace zraster::detail {

// Whether a frame writes its targets with non-temporal stores. When the frame's bins and
// vertices push the targets out of the last-level cache before the next frame, each target row
// is read from memory before it is written, and the deferred shader's stores wait behind those.
// When they all fit, the rows are still cached from the last frame and streaming them only
// costs memory bandwidth. (docs/architecture.md has the measurements.)
bool stream_targets(const Frame& frame, std::size_t target_bytes) {
    const FrameVertices& v = frame.vertices;
    const std::size_t vertex_bytes = v.screen.size() * sizeof(ScreenVertex) +
                                     v.outcode.size() * sizeof(std::uint32_t) +
                                     (v.world.size() + v.normal.size()) * sizeof(glm::vec3);
    return frame.bin_bytes + vertex_bytes + target_bytes > frame.streaming_threshold;
}

}  // namespace zraster::detail
