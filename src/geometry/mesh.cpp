#include <zraster/mesh.hpp>

namespace zraster {

void update_bounds(Mesh& mesh) {
    mesh.bounds = Bounds3f::of(mesh.positions);
}

}  // namespace zraster
