// zraster's OcclusionBuffer and Intel's Masked Software Occlusion Culling (MSOC) side by side
// in one process, on MSOC's fill-rate workload (msoc_workload.hpp): rounds alternate between
// the two, and each figure is a median over the rounds. Built by scripts/msoc_compare.sh
// against an MSOC source tree the script fetches (MSOC's code never enters this repository)
// and an installed zraster; not part of the build.
//
//   occluders: clear, then render the 100k triangles (clip-space input, one thread);
//   rectangles: 4096 random 16 and 64 px screen rectangles at random depths against the
//     buffer holding the workload, per test.
#include <zraster/occlusion_buffer.hpp>

#include <hwy/targets.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "MaskedOcclusionCulling.h"
#include "msoc_workload.hpp"

namespace {

using zraster::bench::kHeight;
using zraster::bench::kTriangles;
using zraster::bench::kWidth;
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

template <class F>
double seconds(F&& f) {
    const auto start = Clock::now();
    f();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Rect {
    float x0, y0, x1, y1, depth;  // NDC, and NDC depth in [0, 1]
};

std::vector<Rect> random_rects(int pixels) {
    zraster::bench::SplitMix64 rng{7};
    std::vector<Rect> rects(4096);
    const double sx = 2.0 * pixels / kWidth, sy = 2.0 * pixels / kHeight;
    for (Rect& r : rects) {
        const double x = rng.uniform(-1.0, 1.0 - sx), y = rng.uniform(-1.0, 1.0 - sy);
        r = {float(x), float(y), float(x + sx), float(y + sy), float(rng.uniform(0.0, 1.0))};
    }
    return rects;
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
    // The AVX2 kernels on both sides (what machines without AVX-512 run).
    hwy::DisableTargets(HWY_AVX2 - 1);
    const zraster::bench::Workload& w = zraster::bench::msoc_workload();

    zraster::OcclusionBuffer ours(kWidth, kHeight);
    MaskedOcclusionCulling* msoc = MaskedOcclusionCulling::Create(MaskedOcclusionCulling::AVX2);
    if (msoc->GetImplementation() != MaskedOcclusionCulling::AVX2) {
        std::fprintf(stderr, "msoc_compare: MSOC did not pick its AVX2 path on this machine\n");
        return 1;
    }
    msoc->SetResolution(kWidth, kHeight);
    // (The workload's w is at least 1: nothing is near-clipped.)
    msoc->SetNearClipPlane(0.5f);
    const float* vertices = &w.clip[0].x;

    std::vector<double> ours_ms, msoc_ms;
    for (int round = 0; round < rounds + 1; ++round) {  // (round 0: warm-up)
        ours.clear();
        const double a =
            seconds([&] { ours.render_occluders(std::span<const glm::vec4>(w.clip), w.indices); });
        msoc->ClearBuffer();
        const double b = seconds([&] {
            msoc->RenderTriangles(vertices, w.indices.data(), kTriangles, nullptr,
                                  MaskedOcclusionCulling::BACKFACE_CW);
        });
        if (round > 0) {
            ours_ms.push_back(a * 1e3);
            msoc_ms.push_back(b * 1e3);
        }
    }
    // Both drew the workload: one-pixel rectangles far behind it are hidden where a triangle
    // covers the pixel (about 1 - e^-2.4 = 91% of the screen: 5M triangle pixels on 2M).
    int ours_hidden = 0, msoc_hidden = 0;
    zraster::bench::SplitMix64 rng{3};
    for (int i = 0; i < 1000; ++i) {
        const int px = int(rng.uniform(0, kWidth)), py = int(rng.uniform(0, kHeight));
        const float x0 = 2.0f * float(px) / kWidth - 1.0f, x1 = x0 + 2.0f / kWidth;
        const float y1 = 1.0f - 2.0f * float(py) / kHeight, y0 = y1 - 2.0f / kHeight;
        ours_hidden +=
            ours.test_pixel_rect(px, py, px, py, 0.9999f) == zraster::OcclusionResult::Occluded;
        msoc_hidden += msoc->TestRect(x0, y0, x1, y1, 1e6f) == MaskedOcclusionCulling::OCCLUDED;
    }
    std::printf("machine: zraster kernels %s, MSOC AVX2\n",
                zraster::OcclusionBuffer::simd_target());
    std::printf(
        "occluders, 100k triangles, median of %d: zraster %.3f ms, MSOC %.3f ms, "
        "MSOC / zraster %.2f\n",
        rounds, median(ours_ms), median(msoc_ms), median(msoc_ms) / median(ours_ms));
    std::printf(
        "  (one-pixel rectangles far behind, of 1000: %d hidden by zraster's, %d by MSOC's)\n",
        ours_hidden, msoc_hidden);

    for (const int pixels : {16, 64}) {
        const std::vector<Rect> rects = random_rects(pixels);
        std::vector<double> ours_ns, msoc_ns;
        int ours_occluded = 0, msoc_occluded = 0;
        for (int round = 0; round < rounds + 1; ++round) {
            int a_hidden = 0, b_hidden = 0;
            const double a = seconds([&] {
                for (const Rect& r : rects)
                    a_hidden += ours.test_rect({r.x0, r.y0}, {r.x1, r.y1}, r.depth) ==
                                zraster::OcclusionResult::Occluded;
            });
            // MSOC takes the rectangle's nearest w: with the workload's depths that is the
            // same ordering as NDC depth (w from 1 to 4), mapped as the workload maps them.
            const double b = seconds([&] {
                for (const Rect& r : rects)
                    b_hidden += msoc->TestRect(r.x0, r.y0, r.x1, r.y1, 1.0f + 3.0f * r.depth) ==
                                MaskedOcclusionCulling::OCCLUDED;
            });
            if (round > 0) {
                ours_ns.push_back(a * 1e9 / double(rects.size()));
                msoc_ns.push_back(b * 1e9 / double(rects.size()));
            }
            ours_occluded = a_hidden;
            msoc_occluded = b_hidden;
        }
        std::printf(
            "rectangles %d px, median of %d: zraster %.1f ns, MSOC %.1f ns a test "
            "(occluded: %d and %d of %zu)\n",
            pixels, rounds, median(ours_ns), median(msoc_ns), ours_occluded, msoc_occluded,
            rects.size());
    }
    MaskedOcclusionCulling::Destroy(msoc);
    return 0;
}
