// The per-block visibility kernel of the tile rasterizer: coverage by edge functions, depth
// test and write, and the triangle reference plus perspective-correct barycentrics of every
// fragment that passes, into tile-local buffers (deferred shading reads them afterwards). For
// triangles the SIMD Phong shader draws, the kernel interpolates the world position and normal
// right away instead (the deferred pass then reads them without gathering the triangle's data),
// or, shading forward, lights those fragments right away.
//
// Two implementations with bit-identical results: a scalar reference and a SIMD one (Google
// Highway, the instruction set picked at run time: AVX-512, AVX2, SSE4, NEON, scalar). The
// arithmetic is the same in both, operation by operation (no FMA: -ffp-contract=off), and a test
// compares them on random triangles.
#pragma once
#include <zraster/depth_buffer.hpp>
#include <zraster/raster.hpp>

#include <cstdint>

#include "raster/setup_lanes.hpp"
#include "raster/tile_layout.hpp"
#include "shade/phong_kernel.hpp"

namespace zraster::detail {

// Tile-local buffers with row stride kTileStride (tile_layout.hpp) and padding, so a vector may
// run past the end of a row (into the next row or the padding) without leaving the buffer.
struct TileBuffers {
    // (The kernel reads and writes back up to three rows below the tile's last, unchanged.)
    static constexpr int kPixels = kTileStride * kTileSize + 3 * kTileStride + 32;
    alignas(64) float depth[kPixels];  // D32F depth, or the D24/D16 unorm code as a float
    alignas(64) std::uint32_t ref[kPixels];
    alignas(64) float b1[kPixels];
    alignas(64) float b2[kPixels];
    // Interpolated world normal (not yet unit) and world position, where shade_tag != 0.
    alignas(64) float nx[kPixels], ny[kPixels], nz[kPixels];
    alignas(64) float wx[kPixels], wy[kPixels], wz[kPixels];
    // 0: shade from ref and barycentrics; else the SIMD Phong constants' index + 1 in the low
    // bits and kShadeFlip where the normal is negated (a back face lit two-sided).
    alignas(64) std::uint32_t shade_tag[kPixels];
    // RGBA8 of the pixels shaded forward (BlockJob::shade_constants), background elsewhere.
    alignas(64) std::uint32_t color[kPixels];
    // Hierarchical z: per block (row-major, kBlocksPerTileRow per row), the farthest depth
    // stored in it (render/hierarchical_z.hpp).
    alignas(64) float farthest[kBlocksPerTileRow * kBlocksPerTileRow];
};

inline constexpr std::uint32_t kShadeFlip = 0x80000000u;

// A triangle's corner attributes for interpolation in the kernel, as the deferred shader would
// interpolate them: b = (1 - b1 - b2, b1, b2), remapped by a clipped piece's corner weights
// (`piece` below: the three corners' weights, or null), then attribute = (a0 b.x + a1 b.y) +
// a2 b.z. (The piece travels apart: a bin entry carries these 76 bytes for every triangle,
// and pieces are rare.)
struct CornerAttributes {
    glm::vec3 world[3], normal[3];
    std::uint32_t tag = 0;  // written to TileBuffers::shade_tag
};

// The scalar forms of that interpolation (the kernel does the same operations in lanes).
inline glm::vec3 interpolation_weights(const glm::vec3* piece, float b1, float b2) {
    glm::vec3 b{1.0f - b1 - b2, b1, b2};
    if (piece != nullptr) b = b.x * piece[0] + b.y * piece[1] + b.z * piece[2];
    return b;
}
inline glm::vec3 interpolate_corners(const glm::vec3 corner[3], const glm::vec3& b) {
    return corner[0] * b.x + corner[1] * b.y + corner[2] * b.z;
}
// Stores a pixel's interpolated normal and position (the scalar paths).
inline void store_interpolated(const CornerAttributes& a, const glm::vec3* piece, float b1,
                               float b2, TileBuffers& tile, std::size_t at) {
    const glm::vec3 w = interpolation_weights(piece, b1, b2);
    const glm::vec3 n = interpolate_corners(a.normal, w);
    const glm::vec3 p = interpolate_corners(a.world, w);
    tile.nx[at] = n.x;
    tile.ny[at] = n.y;
    tile.nz[at] = n.z;
    tile.wx[at] = p.x;
    tile.wy[at] = p.y;
    tile.wz[at] = p.z;
}

// The plane equations the kernel evaluates: TriangleSetup's (q, p1, p2 for perspective-correct
// barycentrics, l1, l2 for screen-linear ones; only those the job asks for need be set).
struct JobPlanes {
    PlaneEquation depth, q, p1, p2, l1, l2;
};

// A rectangle of one triangle's pixels inside a tile: a block of the traversal (at most
// kBlockSize square), or a small triangle's single job (at most JobWindow::max_columns wide,
// any height). Wider rows are taken a vector at a time.
struct BlockJob {
    // Edge function values at the block's first pixel (x0, y0), and their steps per pixel in
    // x and in y. Exact: the caller checks that every value inside the block fits in 32 bits.
    std::int32_t e[3];
    std::int32_t step_x[3];
    std::int32_t step_y[3];
    bool full = false;   // all pixels covered: skip the edge tests
    int x0 = 0, y0 = 0;  // tile-local position of the block's first pixel
    int width = 0, height = 0;
    int plane_dx = 0, plane_dy = 0;  // (x0, y0) relative to the triangle's plane origin
    JobPlanes planes;
    bool perspective = true;
    CompareFunc compare = CompareFunc::Less;
    bool write_depth = true;
    bool attributes = true;    // store the triangle reference (off: depth only)
    bool barycentrics = true;  // ... and the barycentrics (needs the setup's q, p1, p2 planes)
    // With barycentrics on: the shade tag (0 without corners), and with corners the
    // interpolated attributes instead of the barycentrics.
    const CornerAttributes* corners = nullptr;
    const glm::vec3* piece = nullptr;  // a clipped piece's corner weights, or null
    // Forward shading (with corners): the fragments that pass are lit right away with these
    // constants (the SIMD Phong shader's), their color written to TileBuffers::color instead of
    // the interpolated attributes; the shade tag is still written.
    const PhongConstants* shade_constants = nullptr;
    std::uint32_t ref = 0;
};

// Returns the number of fragments that passed the depth test. D32F only.
int visibility_block(const BlockJob& job, TileBuffers& tile);
int visibility_block_scalar(const BlockJob& job, TileBuffers& tile);

// The scalar twin of the kernel's forward shading (forward_shading_scalar.cpp): the corner
// attributes interpolated at (b1, b2) as store_interpolated does, lit, as RGBA8.
std::uint32_t shade_interpolated_scalar(const PhongConstants& constants,
                                        const CornerAttributes& corners, const glm::vec3* piece,
                                        float b1, float b2);

// Set-up lanes whose triangles are single jobs (setup_lanes with a JobWindow: small triangles,
// one kernel job each), with what their jobs need beyond the setup. The tile rasterizer spent
// about as long filling a TriangleSetup and a BlockJob for each small triangle, in scalar
// code, as the kernel spent on it; the lanes already hold those values.
struct LaneJobs {
    const SetupLanes* lanes = nullptr;
    std::uint32_t ref[kSetupLanes];
    const CornerAttributes* corners[kSetupLanes];
    const glm::vec3* piece[kSetupLanes];
    const PhongConstants* shade_constants[kSetupLanes];
};
struct LaneJobsDone {
    int next = 0;  // the first lane not run: not a single job, or the count
    std::uint64_t passed = 0;
    std::uint64_t passed_shaded = 0;  // of those, by lanes with shade constants
};
// Lane `lane`'s job into `job` (the fields all lanes share are left as they are); false if the
// lane is not a single job.
[[gnu::always_inline]] inline bool fill_lane_job(const LaneJobs& jobs, int lane, BlockJob& job) {
    const SetupLanes& l = *jobs.lanes;
    if (!l.single_job[lane]) return false;
    for (int k = 0; k < 3; ++k) {
        job.e[k] = l.job_e[k][lane];
        job.step_x[k] = l.job_step_x[k][lane];
        job.step_y[k] = l.job_step_y[k][lane];
    }
    job.full = false;
    job.x0 = l.job_x0[lane];
    job.y0 = l.job_y0[lane];
    job.width = l.job_width[lane];
    job.height = l.job_height[lane];
    job.plane_dx = l.job_plane_dx[lane];
    job.plane_dy = l.job_plane_dy[lane];
    const auto plane = [&](int p) {
        return PlaneEquation{l.plane_a[p][lane], l.plane_b[p][lane], l.plane_c[p][lane]};
    };
    job.planes.depth = plane(SetupLanes::kDepth);
    if (job.barycentrics && job.perspective) {
        job.planes.q = plane(SetupLanes::kQ);
        job.planes.p1 = plane(SetupLanes::kP1);
        job.planes.p2 = plane(SetupLanes::kP2);
    } else if (job.barycentrics) {
        job.planes.l1 = plane(SetupLanes::kL1);
        job.planes.l2 = plane(SetupLanes::kL2);
    }
    job.ref = jobs.ref[lane];
    job.corners = jobs.corners[lane];
    job.piece = jobs.piece[lane];
    job.shade_constants = jobs.shade_constants[lane];
    return true;
}

// Runs lanes first, first + 1, ... (below count) while they are single jobs, each with
// run_job(job) returning its passed fragments: visibility_lanes and its scalar twin.
template <class RunJob>
[[gnu::always_inline]] inline LaneJobsDone run_lane_jobs(const LaneJobs& jobs, int first, int count,
                                                         const BlockJob& shared,
                                                         const RunJob& run_job) {
    LaneJobsDone done;
    BlockJob job = shared;
    for (int lane = first; lane < count; ++lane) {
        if (!fill_lane_job(jobs, lane, job)) {
            done.next = lane;
            return done;
        }
        const auto passed = static_cast<std::uint64_t>(run_job(job));
        done.passed += passed;
        if (job.shade_constants != nullptr) done.passed_shaded += passed;
    }
    done.next = count;
    return done;
}

// Runs lanes first, first + 1, ... (below count) while they are single jobs, each as
// visibility_block would run that job: `shared` gives what all lanes share (the depth test,
// perspective, write_depth, attributes, barycentrics), the lanes the rest.
LaneJobsDone visibility_lanes(const LaneJobs& jobs, int first, int count, const BlockJob& shared,
                              TileBuffers& tile);
LaneJobsDone visibility_lanes_scalar(const LaneJobs& jobs, int first, int count,
                                     const BlockJob& shared, TileBuffers& tile);

// The farthest depth stored in the 8x8 block (block_x, block_y) of the tile: the largest when
// `largest`, else the smallest. Exact (a max/min over the stored values).
float block_farthest_depth(const TileBuffers& tile, int block_x, int block_y, bool largest);
float block_farthest_depth_scalar(const TileBuffers& tile, int block_x, int block_y, bool largest);

// Name of the instruction set the dispatcher picked (for reports).
const char* visibility_kernel_target();

}  // namespace zraster::detail
