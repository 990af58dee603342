// FNV-1a 64 (Fowler, Noll, Vo) over the triangles' corner positions in draw order, as
// docs/bench-scenes.md defines it: it identifies the drawn geometry independently of vertex
// indexing.
#include <zraster/scenes.hpp>

#include <bit>

namespace zraster {

std::uint64_t geometry_hash(const Mesh& mesh) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (const std::uint32_t index : mesh.indices) {
        const glm::vec3& p = mesh.positions[index];
        for (const float coordinate : {p.x, p.y, p.z}) {
            // Little-endian bytes whatever the host's byte order.
            const auto bits = std::bit_cast<std::uint32_t>(coordinate);
            for (int byte = 0; byte < 4; ++byte)
                hash = (hash ^ ((bits >> (8 * byte)) & 0xffu)) * 0x100000001b3ull;
        }
    }
    return hash;
}

}  // namespace zraster
