// When a frame's target rows are written with non-temporal stores (target_streaming.hpp).
#include "render/target_streaming.hpp"

#include <algorithm>
#include <fstream>
#include <string>

namespace zraster::detail {

namespace {

// The largest cache of CPU 0 as Linux describes it (sysfs), or 32 MiB. (glibc's
// sysconf(_SC_LEVEL3_CACHE_SIZE) said 320 MiB on a VM whose L3 is 32 MiB.)
std::size_t last_level_cache_bytes() {
    std::size_t largest = 0;
    for (int index = 0; index < 8; ++index) {
        const std::string path =
            "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index) + "/size";
        std::ifstream file(path);
        std::size_t value = 0;
        char unit = 0;  // "32768K": K, M or G, or none (bytes)
        if (!(file >> value)) continue;
        file >> unit;
        const std::size_t scale = unit == 'K'   ? std::size_t{1} << 10
                                  : unit == 'M' ? std::size_t{1} << 20
                                  : unit == 'G' ? std::size_t{1} << 30
                                                : 1;
        largest = std::max(largest, value * scale);
    }
    return largest > 0 ? largest : std::size_t{32} << 20;
}

}  // namespace

std::size_t& streaming_threshold() {
    static std::size_t threshold = last_level_cache_bytes();
    return threshold;
}

// Whether a frame writes its targets with non-temporal stores. When the frame's bins and
// vertices push the targets out of the last-level cache before the next frame, each target row
// is read from memory before it is written, and the deferred shader's stores wait behind those
// (sphere:1000000 Phong: raster -0.75 ms AVX-512, -1.05 ms AVX2 streamed). When they all fit,
// the rows are still cached from the last frame and streaming them costs the memory bandwidth
// (bunny: raster +0.5-0.7 ms streamed).
bool stream_targets(const Frame& frame, std::size_t target_bytes) {
    const FrameVertices& v = frame.vertices;
    const std::size_t vertex_bytes = v.screen.size() * sizeof(ScreenVertex) +
                                     v.outcode.size() * sizeof(std::uint32_t) +
                                     (v.world.size() + v.normal.size()) * sizeof(glm::vec3);
    return frame.bin_bytes + vertex_bytes + target_bytes > streaming_threshold();
}

}  // namespace zraster::detail
