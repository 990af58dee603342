// What a debug view's frame (debug_view_frame.cpp) keeps between frames, inside the Frame so
// that a Renderer showing a view reuses it. Untouched by frames without a view.
#pragma once
#include <zraster/render.hpp>

#include <cstdint>
#include <vector>

namespace zraster::detail {

// Per triangle of a frame (Frame::instance_first_triangle + primitive): what the front end made
// of it.
enum TriangleViewFlag : std::uint8_t {
    kTriangleBinned = 1,   // a ref (or a clipped piece) reached the bins
    kTriangleBack = 2,     // ... facing away from the camera
    kTriangleClipped = 4,  // ... made by the homogeneous clipper
};

struct DebugViewScratch {
    RenderOptions options;    // the auxiliary frames' options
    RenderTargets visible;    // depth, normals and ids of the frame's visible surfaces
    RenderTargets overdraw;   // coverage counts with the depth test off
    RenderTargets reference;  // ids with D32F depth (zfight)
    // Per 8x8 block of the image (rows of tiles_x * 8 blocks): the triangle blocks hierarchical
    // z skipped there.
    std::vector<std::uint32_t> hiz_blocks;
    std::vector<std::uint8_t> triangle_flags;  // TriangleViewFlag bits
    std::vector<std::int32_t> frame_instance;  // per scene instance: its frame instance, or -1
};

}  // namespace zraster::detail
