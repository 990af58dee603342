// The working memory of blend_pass.hpp, which each thread slot keeps from tile to tile.
#pragma once
#include <zraster/raster.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace zraster::detail {

// A blended triangle met in a tile's bins: its chunk, its index among the chunk's refs and its
// setup.
struct BlendTriangle {
    std::uint32_t chunk = 0;
    std::uint32_t ref = 0;
    TriangleSetup setup;
};

struct BlendFragment {
    std::uint32_t pixel = 0;  // index in the tile, row-major over its width
    std::uint32_t next = 0;   // the pixel's next fragment (a list, newest first)
    float depth = 0.0f;       // as stored (the depth format's code)
    float alpha = 0.0f;       // in (0, 1]
    std::uint32_t rgba = 0;   // shaded, RGBA8 as the color target holds it
    std::uint32_t instance = 0, primitive = 0;
};

// A slot's working memory for its tiles' blended surfaces, kept from tile to tile.
struct BlendScratch {
    std::vector<BlendTriangle> triangles;
    std::vector<BlendFragment> fragments;
    std::vector<std::uint32_t> head;  // per pixel of the tile: its newest fragment
    std::vector<std::uint32_t> list;  // one pixel's fragments, sorted
};

}  // namespace zraster::detail
