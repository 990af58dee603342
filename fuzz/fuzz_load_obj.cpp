// libFuzzer target: load_scene on OBJ with its MTL material libraries (the work directory holds
// t.mtl and t.png), then the loaded scene through the whole pipeline at 24x16.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    zraster::fuzz::fuzz_load(data, size, ".obj");
    return 0;
}
