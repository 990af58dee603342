// libFuzzer target: load_scene on glTF 2.0, both forms: an input starting with the GLB magic
// "glTF" is written as .glb (binary container), anything else as .gltf (JSON; external buffers
// t.bin and images t.png resolve in the work directory, data: URIs anywhere). Then the loaded
// scene through the whole pipeline at 24x16.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    zraster::fuzz::fuzz_load(data, size, binary ? ".glb" : ".gltf");
    return 0;
}
