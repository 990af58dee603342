// The working memory of blend_pass.hpp, which each thread slot keeps from tile to tile.
#pragma once
#include <zraster/raster.hpp>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "raster/visibility_kernel.hpp"
#include "render/blend_kernels.hpp"

namespace zraster::detail {

// A blended triangle met in a tile's bins: its chunk, its index among the chunk's refs and its
// setup.
struct BlendTriangle {
    std::uint32_t chunk = 0;
    std::uint32_t ref = 0;
    TriangleSetup setup;
};

// A triangle's fragments waiting for their colors (shaded in batches).
struct PendingFragment {
    std::uint32_t pixel;
    BlendFragment fragment;
};

// A slot's working memory for its tiles' blended surfaces, kept from tile to tile.
struct BlendScratch {
    std::vector<BlendTriangle> triangles;
    // Per triangle: its instance in the scene and primitive (the order of equal depths).
    std::vector<std::uint32_t> instance, primitive;
    BlendSlots slots;
    std::vector<PendingFragment> pending;
    std::vector<BlendFragment> list;  // one pixel's fragments, when it has more than kSlots
};

}  // namespace zraster::detail
