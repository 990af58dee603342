// The last-level cache's size (cache_size.hpp).
#include "platform/cache_size.hpp"

#include <algorithm>
#include <fstream>
#include <string>

namespace zraster::platform {
namespace {

constexpr std::size_t kUnknownCacheBytes = std::size_t{32} << 20;

std::size_t probe_last_level_cache_bytes() {
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
    return largest > 0 ? largest : kUnknownCacheBytes;
}

}  // namespace

std::size_t last_level_cache_bytes() {
    static const std::size_t bytes = probe_last_level_cache_bytes();
    return bytes;
}

}  // namespace zraster::platform
