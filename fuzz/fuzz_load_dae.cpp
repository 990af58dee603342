// libFuzzer target: load_scene on COLLADA (XML node graphs: <instance_node> expansion counted by a scan before
// Assimp),
// then the loaded scene through the whole pipeline at 24x16.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    zraster::fuzz::fuzz_load(data, size, ".dae");
    return 0;
}
