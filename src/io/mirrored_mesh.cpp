#include "io/mirrored_mesh.hpp"

#include <utility>

namespace zraster::io {

Mesh with_winding_reversed(const Mesh& mesh) {
    Mesh out = mesh;
    out.name = mesh.name + " (mirrored)";
    for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3)
        std::swap(out.indices[t + 1], out.indices[t + 2]);
    return out;
}

}  // namespace zraster::io
