// The state the back end's stages share while drawing tiles: the frame's decisions (TilePlan,
// made once per frame and read-only during the tile pass) and one tile's rectangle and counts
// (TileContext, private to the thread drawing it).
#pragma once
#include <zraster/depth_buffer.hpp>
#include <zraster/render.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "render/frame.hpp"
#include "render/hierarchical_z.hpp"
#include "render/shade_fragment.hpp"
#include "render/stream_lines.hpp"

namespace zraster::detail {

// How a frame's pixels get their color and normal.
enum class ShadingPath {
    None,  // no color or normal target: depth (and ids) only
    // Each fragment is shaded as it passes the depth test, on the scalar traversal
    // (ShadingStrategy::Forward without tagged shading).
    ScalarForward,
    // Visibility first (triangle reference and barycentrics per pixel), then each visible pixel
    // shaded once, pixel by pixel.
    Deferred,
    // Deferred, and the visibility kernel interpolates the attributes of SIMD Phong instances'
    // triangles (their shade tag), whose pixels are then shaded a row at a time; the others'
    // pixel by pixel.
    TaggedDeferred,
    // The visibility kernel lights SIMD Phong instances' fragments as they pass
    // (ShadingStrategy::Forward with tagged shading); the others' pixels are shaded deferred.
    TaggedForward,
};

// How a triangle's pixels in a tile are found.
enum class Traversal {
    Blocks,  // 8x8 blocks classified by their corners, the visibility kernel on the rest
    Scalar,  // pixel by pixel, any depth format, depth test off, coverage counts
};

ShadingPath choose_shading_path(const RenderOptions& options, const FrameTargets& targets,
                                bool tagged_shading);
Traversal choose_traversal(const RenderOptions& options, const FrameTargets& targets,
                           ShadingPath shading);

// What every tile of a frame draws with.
struct TilePlan {
    const Frame& frame;
    const FrameTargets& targets;
    const DepthBuffer& codec;  // encodes/decodes the depth format
    CompareFunc compare;
    ShadingPath shading;
    Traversal traversal;
    bool simd;             // the SIMD kernels (else their scalar twins)
    HierarchicalZ hiz;     // per-block depth bounds in use (block traversal, depth writes on)
    bool stream_targets;   // rows go to the targets with non-temporal stores
    bool alpha_instances;  // some instance is alpha-tested or blended (Frame::alpha_instances)
    // The hiz debug view's per-block counts (Frame::hiz_block_counts); null in other frames.
    std::uint32_t* hiz_block_counts = nullptr;

    bool shades() const { return shading != ShadingPath::None; }
    bool tagged() const {
        return shading == ShadingPath::TaggedDeferred || shading == ShadingPath::TaggedForward;
    }
    // Pixels shaded after visibility is resolved (all but ScalarForward's, when shading).
    bool resolves_then_shades() const {
        return shading != ShadingPath::None && shading != ShadingPath::ScalarForward;
    }

    // Copies a row into a target.
    void write_row(void* to, const void* from, std::size_t bytes) const {
        if (stream_targets)
            stream_copy(to, from, bytes);
        else
            std::memcpy(to, from, bytes);
    }
};

// Hierarchical z and small triangles (one kernel job each): their bound refreshes cost about
// what the kernel spends on such a job, so they are not made (their writes leave the bounds
// stale, still valid), and their tests stop in a tile where fewer than half of the first 64
// hid their job. Larger triangles keep both: behind large occluders their blocks are what
// hierarchical z saves. (docs/architecture.md has the measurements.)
struct SmallJobsHiz {
    static constexpr int kJudgeAfter = 64;
    int tests = 0, hidden = 0;
    bool worth_testing() const { return tests < kJudgeAfter || 2 * hidden >= tests; }
};

// What a tile counts while it is drawn.
struct TileCounts {
    std::uint64_t passed = 0;          // fragments that passed the depth (and alpha) test
    std::uint64_t shaded_forward = 0;  // ... and were shaded as they passed
    std::uint64_t blocks_hidden = 0;   // blocks skipped by hierarchical z
    std::uint64_t alpha_discarded = 0;
    // Blocks whose bound is nearer than the clear depth: until one is, no hierarchical z test
    // can hide anything and none is made (a mesh of small triangles rarely covers a whole
    // block in one write).
    int bounded_blocks = 0;
    SmallJobsHiz small_jobs;
    bool untagged = false;  // a triangle without a shade tag was drawn (tagged paths)
};

// One tile being drawn: [x0, x1) x [y0, y1) of the image.
struct TileContext {
    const TilePlan& plan;
    int x0, y0, x1, y1;
    TileCounts counts;
};

// Writes a shaded fragment to the color and normal targets (those given).
void write_shaded(const TilePlan& plan, const ShadedFragment& fragment, int px, int py);

}  // namespace zraster::detail
