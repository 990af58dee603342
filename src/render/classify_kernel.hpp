// Front-end triangle classification, many triangles at a time: for the common case (indices in
// range, all three vertices inside the view volume (x != kOutsideScreenX), snapped positions small
// enough for exact double arithmetic) it makes classify_triangle's decisions (degenerate, culled,
// no pixel center covered, or the pixel box) without a branch per triangle. Every other triangle is
// handed back as "slow" for the scalar path (clipping, bad indices, huge coordinates).
//
// Two implementations with identical output: a scalar reference and a SIMD one (Highway,
// instruction set picked at run time); a test compares them on random triangles.
#pragma once
#include <zraster/raster.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>

namespace zraster::detail {

// The x of a frame screen vertex whose outcode is not 0 (the vertex stage writes it there): far
// outside the coordinate limit below, so the classifier sends its triangles the slow way without
// reading the outcodes.
inline constexpr std::int32_t kOutsideScreenX = std::numeric_limits<std::int32_t>::min();

struct ClassifyInput {
    // 3 per triangle, from triangle first_triangle's on: the mesh's own (first_triangle 0) or a
    // widened copy of part of them (16-bit indices).
    const std::uint32_t* indices = nullptr;
    std::size_t first_triangle = 0;
    std::size_t triangle_total = 0;  // the end of the triangles `indices` holds (prefetch bound)
    std::uint32_t vertex_total = 0;  // the mesh's vertex count (indices must be below)
    std::uint32_t first_vertex = 0;  // frame index of the mesh's vertex 0
    // Frame screen vertices (FrameVertices::screen), x = kOutsideScreenX where outside.
    const ScreenVertex* screen = nullptr;
    SetupSettings settings;
};

// The triangles of one batch that need more work: visible ones with their pixel box, and slow
// ones (flag kSlow) for the scalar path. Counters for the rest.
struct ClassifyOutput {
    static constexpr std::size_t kMaxBatch = 256;
    // Room for a whole vector past the last entry: compressing stores may write that far.
    static constexpr std::size_t kCapacity = kMaxBatch + 64;
    static constexpr std::int32_t kFront = 1, kSlow = 2;
    std::uint32_t count = 0;            // entries below
    std::uint32_t triangle[kCapacity];  // mesh triangle index
    std::int32_t min_x[kCapacity], min_y[kCapacity], max_x[kCapacity], max_y[kCapacity];
    std::int32_t flags[kCapacity];  // kFront, kSlow (then the box is zero)
    std::uint64_t degenerate = 0, culled = 0, no_coverage = 0;  // accumulated
};

// Classifies mesh triangles [first, first + count), count <= kMaxBatch; out.count is reset,
// the counters accumulate. Entries keep triangle order. Frame vertex indices must fit in 31 bits
// (the SIMD version computes them in 32-bit lanes).
void classify_triangles(const ClassifyInput& in, std::size_t first, std::size_t count,
                        ClassifyOutput& out);
void classify_triangles_scalar(const ClassifyInput& in, std::size_t first, std::size_t count,
                               ClassifyOutput& out);

// Snapped coordinates at most this large (in magnitude) keep the double area exact.
inline constexpr std::int32_t kClassifyCoordinateLimit = 1 << 24;

}  // namespace zraster::detail
