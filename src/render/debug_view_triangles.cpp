// Per-triangle records for the debug views (debug_view_triangles.hpp).
#include "render/debug_view_triangles.hpp"

#include <algorithm>
#include <cstddef>

namespace zraster::detail {

void record_triangles(Frame& frame) {
    DebugViewScratch& s = frame.debug_view;
    s.frame_instance.assign(frame.scene->instances.size(), -1);
    for (std::size_t i = 0; i < frame.instances.size(); ++i)
        s.frame_instance[frame.instances[i].scene_instance] = static_cast<std::int32_t>(i);
    s.triangle_flags.assign(frame.instance_first_triangle.back(), 0);
    for (const Chunk& chunk : frame.chunks)
        for (const TriangleRef& ref : chunk.refs) {
            std::uint8_t& flags =
                s.triangle_flags[frame.instance_first_triangle[ref.instance] + ref.primitive];
            flags |= kTriangleBinned;
            if (!ref.front_facing) flags |= kTriangleBack;
            if (ref.piece != TriangleRef::kNotClipped) flags |= kTriangleClipped;
        }
}

const FrameInstance* frame_instance_of(const Frame& frame, std::int32_t instance_id) {
    const std::vector<std::int32_t>& map = frame.debug_view.frame_instance;
    if (instance_id < 0 || std::size_t(instance_id) >= map.size()) return nullptr;
    const std::int32_t i = map[std::size_t(instance_id)];
    return i < 0 ? nullptr : &frame.instances[std::size_t(i)];
}

std::uint8_t triangle_flags_of(const Frame& frame, std::int32_t instance_id,
                               std::int32_t primitive_id) {
    const FrameInstance* fi = frame_instance_of(frame, instance_id);
    if (fi == nullptr || primitive_id < 0) return 0;
    const auto i = std::size_t(fi - frame.instances.data());
    const std::size_t at = frame.instance_first_triangle[i] + std::size_t(primitive_id);
    return at < frame.instance_first_triangle[i + 1] ? frame.debug_view.triangle_flags[at] : 0;
}

}  // namespace zraster::detail
