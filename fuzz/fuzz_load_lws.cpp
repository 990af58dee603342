// libFuzzer target: load_scene on LightWave scenes (object loads counted and each object checked by a scan
// before Assimp; objects resolve beside the scene: o.obj is a fixture),
// then the loaded scene through the whole pipeline at 24x16.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    zraster::fuzz::fuzz_load(data, size, ".lws");
    return 0;
}
