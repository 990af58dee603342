// The precision limits of the exact rasterizer, in one place.
//
// Vertices are snapped to a fixed-point grid of 1/256 pixel (8 subpixel bits) after the
// viewport transform. Edge functions are then evaluated exactly in 64-bit integers, which is
// what makes the rasterizer watertight: two triangles sharing an edge compute exactly opposite
// edge values, so every pixel center on the edge is claimed by exactly one of them (top-left
// rule), never by both and never by neither.
//
// Overflow bound: window coordinates are confined to the guard band [-kGuardBand, kGuardBand]
// pixels (triangles reaching beyond it are clipped in x/y in homogeneous space first). In fixed
// point that is |x| < 2^(20+8) = 2^28, differences < 2^29, each edge-function product < 2^58
// and the sum of two < 2^59 < 2^63: no overflow in int64.
//
// The largest viewport is kMaxViewport pixels on each side; a 16384 x 16384 image plus the guard
// band stays inside the 2^20 pixel bound with room to spare.
#pragma once
#include <cstdint>

namespace zraster {

inline constexpr int kSubpixelBits = 8;
inline constexpr std::int64_t kSubpixelScale = std::int64_t{1} << kSubpixelBits;  // 256
inline constexpr int kMaxViewport = 16384;
inline constexpr double kGuardBand = double(1 << 20);  // pixels, each side of the origin

}  // namespace zraster
