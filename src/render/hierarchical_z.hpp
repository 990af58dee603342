// Hierarchical z for the tile rasterizer: each 8x8 block of a tile keeps the farthest depth
// stored in it (TileBuffers::farthest), and a triangle's part in a block is skipped before any
// per-pixel work when its nearest possible depth there cannot pass the depth test against that.
//
// The test must never skip a fragment the exact per-pixel test would keep (images stay
// bit-identical with it on or off), so the triangle's nearest depth is a lower bound of what the
// kernel computes in float, not an estimate: the plane's exact minimum over the block's corners
// (it is linear), minus a bound on the float evaluation error of (c + a*dx) + b*dy.
//
// Only the monotone compare functions have a "farthest": Less/LessEqual keep the largest stored
// depth, Greater/GreaterEqual (reversed-Z) the smallest. Stored depths only move nearer under
// them, so a bound refreshed after each write stays exact.
#pragma once
#include <zraster/depth_buffer.hpp>
#include <zraster/raster.hpp>

#include <algorithm>
#include <cmath>

namespace zraster::detail {

enum class HierarchicalZ {
    Off,      // compare functions without an order (Equal, Always, ...)
    Largest,  // Less, LessEqual: the farthest stored depth is the largest
    Smallest  // Greater, GreaterEqual: the smallest
};

inline HierarchicalZ hierarchical_z_mode(CompareFunc compare) {
    switch (compare) {
        case CompareFunc::Less:
        case CompareFunc::LessEqual:
            return HierarchicalZ::Largest;
        case CompareFunc::Greater:
        case CompareFunc::GreaterEqual:
            return HierarchicalZ::Smallest;
        default:
            return HierarchicalZ::Off;
    }
}

// True when no pixel of [dx0, dx1] x [dy0, dy1] (relative to the plane's origin) can pass
// `compare` against a block whose farthest stored depth is `farthest`.
inline bool block_hidden(const PlaneEquation& depth, int dx0, int dy0, int dx1, int dy1,
                         float farthest, CompareFunc compare) {
    const double a0 = double(depth.a) * dx0, a1 = double(depth.a) * dx1;
    const double b0 = double(depth.b) * dy0, b1 = double(depth.b) * dy1;
    const double c = depth.c;
    // Three float roundings, each at most 2^-24 relative to a partial sum bounded by this.
    const double magnitude =
        std::abs(c) + std::max(std::abs(a0), std::abs(a1)) + std::max(std::abs(b0), std::abs(b1));
    const double error = magnitude * 4e-7;
    // The kernel clamps depth to [0, 1]; clamping is monotone, so the clamped bounds bound the
    // clamped depths. NaN planes compare false: never hidden.
    const auto clamp = [](double z) { return std::min(std::max(z, 0.0), 1.0); };
    const double nearest_if_less = clamp(c + std::min(a0, a1) + std::min(b0, b1) - error);
    const double nearest_if_greater = clamp(c + std::max(a0, a1) + std::max(b0, b1) + error);
    const double f = farthest;
    switch (compare) {
        case CompareFunc::Less:
            return nearest_if_less >= f;
        case CompareFunc::LessEqual:
            return nearest_if_less > f;
        case CompareFunc::Greater:
            return nearest_if_greater <= f;
        case CompareFunc::GreaterEqual:
            return nearest_if_greater < f;
        default:
            return false;
    }
}

}  // namespace zraster::detail
