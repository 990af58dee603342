// What the machine's caches are, as the operating system describes them. The engine does not
// look itself: the Renderer is handed the figure (RendererConfig) and a default from here.
#pragma once
#include <cstddef>

namespace zraster::platform {

// The largest cache of CPU 0 as Linux describes it (sysfs), or 32 MiB where it says nothing.
// (glibc's sysconf(_SC_LEVEL3_CACHE_SIZE) said 320 MiB on a VM whose L3 is 32 MiB.) Probed
// once per process.
std::size_t last_level_cache_bytes();

}  // namespace zraster::platform
