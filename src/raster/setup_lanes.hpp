// Triangle setup of eight triangles at a time, from their snapped vertices stored one array per
// field, with results bit for bit those of setup_triangle (include/zraster/raster.hpp).
//
// The tile rasterizer sets up every bin entry, and one at a time that was a fifth of a frame of
// small triangles: about 100 cycles of scalar double arithmetic, mostly one long dependency
// chain (the divide, then the planes). In lanes the chains of eight triangles overlap.
//
// Every integer the setup computes is exact in double when the snapped coordinates are below
// kSetupLanesCoordinateLimit in magnitude (products below 2^51), so the SIMD version computes
// the edge functions in double lanes too; a lane beyond that limit, or one setup_triangle would
// reject, is marked for the scalar setup.
//
// Two implementations with identical results: a SIMD one (Google Highway, the instruction set
// picked at run time) and the scalar reference, which calls setup_triangle per lane.
#pragma once
#include <zraster/raster.hpp>

#include <cstddef>
#include <cstdint>

namespace zraster::detail {

inline constexpr int kSetupLanes = 8;
inline constexpr std::int32_t kSetupLanesCoordinateLimit = 1 << 24;

// Eight triangles' vertices, one array per field and corner ([corner][lane]).
struct VertexLanes {
    std::int32_t x[3][kSetupLanes], y[3][kSetupLanes];
    float z[3][kSetupLanes], inv_w[3][kSetupLanes];
    float window_x[3][kSetupLanes], window_y[3][kSetupLanes];

    ScreenVertex vertex(int corner, int lane) const {
        return {x[corner][lane],     y[corner][lane],        z[corner][lane],
                inv_w[corner][lane], window_x[corner][lane], window_y[corner][lane]};
    }
    void set_vertex(int corner, int lane, const ScreenVertex& v) {
        x[corner][lane] = v.x;
        y[corner][lane] = v.y;
        z[corner][lane] = v.z;
        inv_w[corner][lane] = v.inv_w;
        window_x[corner][lane] = v.window_x;
        window_y[corner][lane] = v.window_y;
    }
};

// The part of the image a tile rasterizes, [x0, x1) x [y0, y1), and the widest triangle (in
// pixel columns inside it) that it runs as a single kernel job: setup_lanes computes those jobs
// in lanes too (see SetupLanes::single_job).
struct JobWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int max_columns = 0;
};

// A single job's triangle has its vertices less than this far apart (subpixels) each way: then
// its edge values fit 32 bits anywhere near it (|E| <= 2^22 * 65 * 2 < 2^30).
inline constexpr std::int32_t kSingleJobExtent = 64 * kSubpixelScale;

// The setups of eight triangles, one array per TriangleSetup field.
struct SetupLanes {
    enum Plane { kDepth, kQ, kP1, kP2, kL1, kL2, kPlanes };
    std::int32_t min_x[kSetupLanes], min_y[kSetupLanes], max_x[kSetupLanes], max_y[kSetupLanes];
    std::int64_t edge_a[3][kSetupLanes], edge_b[3][kSetupLanes], edge_c[3][kSetupLanes];
    float plane_a[kPlanes][kSetupLanes], plane_b[kPlanes][kSetupLanes],
        plane_c[kPlanes][kSetupLanes];
    std::int32_t front_facing[kSetupLanes];
    // 1 where the lane was left to the scalar setup (see above): its other fields are unset.
    std::int32_t scalar[kSetupLanes];
    // With a JobWindow: 1 where the lane's triangle is a single job there (set up in lanes,
    // vertices less than kSingleJobExtent apart each way, its pixels in the window at most
    // max_columns wide and at least one), and that job (visibility_kernel.hpp's BlockJob): its
    // first pixel (x0, y0) = the box of covered pixel centers' corner clipped to the window,
    // relative to the window and (plane_dx, plane_dy) to the setup's plane origin (min_x,
    // min_y); its size; the edge functions there and their steps.
    std::int32_t single_job[kSetupLanes];
    std::int32_t job_x0[kSetupLanes], job_y0[kSetupLanes];
    std::int32_t job_width[kSetupLanes], job_height[kSetupLanes];
    std::int32_t job_plane_dx[kSetupLanes], job_plane_dy[kSetupLanes];
    std::int32_t job_e[3][kSetupLanes], job_step_x[3][kSetupLanes], job_step_y[3][kSetupLanes];
};

// Sets up lanes [0, count) of `in` (the planes settings asks for: depth always, q, p1, p2
// with barycentric_planes, l1, l2 with screen_linear_planes too), and their single jobs in
// `window` unless it is null (then single_job and the job fields are unset).
void setup_lanes(const VertexLanes& in, int count, const SetupSettings& settings, SetupLanes& out,
                 const JobWindow* window = nullptr);
void setup_lanes_scalar(const VertexLanes& in, int count, const SetupSettings& settings,
                        SetupLanes& out, const JobWindow* window = nullptr);

// setup_triangle on lane `lane`'s vertices.
SetupResult setup_lane_scalar(const VertexLanes& in, int lane, const SetupSettings& settings,
                              TriangleSetup& t);

// Lane `lane` as a TriangleSetup: from `lanes` unless it was left to the scalar setup, which
// then runs here. Returns what setup_triangle returns. (Inline: called once per bin entry, and
// the caller's loop keeps what it can in registers.)
inline SetupResult load_setup(const VertexLanes& in, const SetupLanes& lanes, int lane,
                              const SetupSettings& settings, TriangleSetup& t) {
    if (lanes.scalar[lane]) return setup_lane_scalar(in, lane, settings, t);
    for (std::size_t k = 0; k < 3; ++k) {
        t.x[k] = in.x[k][lane];
        t.y[k] = in.y[k][lane];
        t.edge_a[k] = lanes.edge_a[k][lane];
        t.edge_b[k] = lanes.edge_b[k][lane];
        t.edge_c[k] = lanes.edge_c[k][lane];
    }
    t.min_x = lanes.min_x[lane];
    t.min_y = lanes.min_y[lane];
    t.max_x = lanes.max_x[lane];
    t.max_y = lanes.max_y[lane];
    t.front_facing = lanes.front_facing[lane] != 0;
    const auto plane = [&](int p) {
        return PlaneEquation{lanes.plane_a[p][lane], lanes.plane_b[p][lane],
                             lanes.plane_c[p][lane]};
    };
    t.depth = plane(SetupLanes::kDepth);
    if (!settings.barycentric_planes) return SetupResult::Visible;
    t.q = plane(SetupLanes::kQ);
    t.p1 = plane(SetupLanes::kP1);
    t.p2 = plane(SetupLanes::kP2);
    if (!settings.screen_linear_planes) return SetupResult::Visible;
    t.l1 = plane(SetupLanes::kL1);
    t.l2 = plane(SetupLanes::kL2);
    return SetupResult::Visible;
}

// Name of the instruction set the dispatcher picked (for reports and tests).
const char* setup_lanes_target();

}  // namespace zraster::detail
