// The deferred row shader: Phong lighting (shade/phong_kernel.hpp) of the tagged pixels of a
// tile row, from the attributes the visibility kernel left in the tile. The SIMD shader and its
// scalar twin agree bit for bit (tests/render/simd_kernels_test.cpp).
#pragma once
#include "raster/visibility_kernel.hpp"
#include "shade/phong_kernel.hpp"

#include <cstddef>
#include <cstdint>

namespace zraster::detail {

// Shades the pixels [at, at + count) of a tile row whose shade_tag is set (constants[tag - 1])
// from the interpolated normals and positions there, and writes them as RGBA8 (R in the low
// byte) to rgba[0, count); other pixels of rgba are left alone (rgba holds kTileStride
// values: vectors may run past count). Returns the number of pixels shaded.
int shade_tagged_row(const PhongConstants* constants, const TileBuffers& tile, std::size_t at,
                     int count, std::uint32_t* rgba);
int shade_tagged_row_scalar(const PhongConstants* constants, const TileBuffers& tile,
                            std::size_t at, int count, std::uint32_t* rgba);

}  // namespace zraster::detail
