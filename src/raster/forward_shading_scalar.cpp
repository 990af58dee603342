// The scalar twin of the visibility kernel's forward shading (see visibility_kernel.hpp).
#include "raster/visibility_kernel.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {

std::uint32_t shade_interpolated_scalar(const PhongConstants& constants,
                                        const CornerAttributes& corners, const glm::vec3* piece,
                                        float b1, float b2) {
    const glm::vec3 w = interpolation_weights(piece, b1, b2);
    const glm::vec3 n = interpolate_corners(corners.normal, w);
    const glm::vec3 p = interpolate_corners(corners.world, w);
    PhongBatch one;
    one.count = 1;
    one.nx[0] = n.x;
    one.ny[0] = n.y;
    one.nz[0] = n.z;
    one.px[0] = p.x;
    one.py[0] = p.y;
    one.pz[0] = p.z;
    one.flip[0] = (corners.tag & kShadeFlip) ? ~0u : 0u;
    shade_phong_batch_scalar(constants, one);
    return batch_rgba(one, 0);
}

}  // namespace zraster::detail
