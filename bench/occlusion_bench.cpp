// OcclusionBuffer micro-benchmarks (Google Benchmark, one thread).
//
// The occluder workload is Masked Software Occlusion Culling's classic fill-rate test
// (msoc_workload.hpp).
//
// Reported counters: ns_per_triangle (occluder renders) and ns_per_test (rectangle and box
// tests), both per item, single thread. Run: build/occlusion_bench [--benchmark_filter=...]
// (ZRASTER_BENCH_AVX2=1: the AVX2 kernels on an AVX-512 machine).
#include <zraster/camera.hpp>
#include <zraster/occlusion_buffer.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "benchmark_main.hpp"
#include "msoc_workload.hpp"

namespace {

using zraster::OcclusionBuffer;
using zraster::OcclusionResult;
using zraster::bench::kHeight;
using zraster::bench::kTriangles;
using zraster::bench::kWidth;
using zraster::bench::msoc_workload;
using zraster::bench::SplitMix64;
using zraster::bench::Workload;

// Seconds per item, printed with an SI prefix ("41.5n" is 41.5 ns).
void set_per_item(benchmark::State& state, const char* name, double items_per_iteration) {
    state.counters[name] =
        benchmark::Counter(items_per_iteration, benchmark::Counter::kIsIterationInvariantRate |
                                                    benchmark::Counter::kInvert);
}

void occluders(benchmark::State& state, bool simd) {
    const Workload& w = msoc_workload();
    OcclusionBuffer buffer(kWidth, kHeight);
    buffer.set_simd(simd);
    for (auto _ : state) {
        state.PauseTiming();
        buffer.clear();
        state.ResumeTiming();
        buffer.render_occluders(std::span<const glm::vec4>(w.clip), w.indices);
        benchmark::ClobberMemory();
    }
    state.SetLabel(simd ? OcclusionBuffer::simd_target() : "scalar reference");
    state.counters["rasterized"] = static_cast<double>(buffer.occluder_triangles_rasterized());
    set_per_item(state, "ns_per_triangle", kTriangles);
}

void BM_OccluderRender_MSOC_100k(benchmark::State& state) {
    occluders(state, true);
}
BENCHMARK(BM_OccluderRender_MSOC_100k)->Unit(benchmark::kMillisecond);

void BM_OccluderRender_MSOC_100k_Scalar(benchmark::State& state) {
    occluders(state, false);
}
BENCHMARK(BM_OccluderRender_MSOC_100k_Scalar)->Unit(benchmark::kMillisecond);

// The same triangles as object positions (w = 1) with an identity matrix: adds the transform.
void BM_OccluderRender_MSOC_100k_Matrix(benchmark::State& state) {
    const Workload& w = msoc_workload();
    OcclusionBuffer buffer(kWidth, kHeight);
    for (auto _ : state) {
        state.PauseTiming();
        buffer.clear();
        state.ResumeTiming();
        buffer.render_occluders(std::span<const glm::vec3>(w.ndc), w.indices, glm::mat4(1.0f));
        benchmark::ClobberMemory();
    }
    set_per_item(state, "ns_per_triangle", kTriangles);
}
BENCHMARK(BM_OccluderRender_MSOC_100k_Matrix)->Unit(benchmark::kMillisecond);

void BM_Clear(benchmark::State& state) {
    OcclusionBuffer buffer(kWidth, kHeight);
    for (auto _ : state) {
        buffer.clear();
        benchmark::ClobberMemory();
    }
}
BENCHMARK(BM_Clear)->Unit(benchmark::kMicrosecond);

// A buffer holding the MSOC workload (dense, random depths).
const OcclusionBuffer& filled_buffer() {
    static const OcclusionBuffer buffer = [] {
        const Workload& w = msoc_workload();
        OcclusionBuffer b(kWidth, kHeight);
        b.render_occluders(std::span<const glm::vec4>(w.clip), w.indices);
        return b;
    }();
    return buffer;
}

// A wall at NDC depth 0 over the whole screen: every rectangle behind it is tested in full
// (the worst case: no early exit), every rectangle in front of it stops at its first tile.
const OcclusionBuffer& wall_buffer() {
    static const OcclusionBuffer buffer = [] {
        OcclusionBuffer b(kWidth, kHeight);
        const std::vector<glm::vec4> quad = {
            {-1, -1, 0, 1}, {1, -1, 0, 1}, {1, 1, 0, 1}, {-1, 1, 0, 1}};
        const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
        b.render_occluders(std::span<const glm::vec4>(quad), indices);
        return b;
    }();
    return buffer;
}

struct Rect {
    glm::vec2 lo, hi;
    float depth;
};

// Random rectangles of side `pixels` (square) anywhere on screen, depths in [lo, hi].
std::vector<Rect> random_rects(int pixels, double lo, double hi, std::uint64_t seed) {
    SplitMix64 rng{seed};
    std::vector<Rect> rects(4096);
    const double sx = 2.0 * pixels / kWidth, sy = 2.0 * pixels / kHeight;
    for (Rect& r : rects) {
        const double x = rng.uniform(-1.0, 1.0 - sx), y = rng.uniform(-1.0, 1.0 - sy);
        r.lo = glm::vec2(x, y);
        r.hi = glm::vec2(x + sx, y + sy);
        r.depth = static_cast<float>(rng.uniform(lo, hi));
    }
    return rects;
}

void rect_tests(benchmark::State& state, const OcclusionBuffer& buffer, double lo, double hi) {
    const std::vector<Rect> rects = random_rects(static_cast<int>(state.range(0)), lo, hi, 7);
    std::size_t i = 0, occluded = 0, tests = 0;
    for (auto _ : state) {
        const Rect& r = rects[i++ & (rects.size() - 1)];
        const OcclusionResult result = buffer.test_rect(r.lo, r.hi, r.depth);
        occluded += result == OcclusionResult::Occluded;
        ++tests;
        benchmark::DoNotOptimize(result);
    }
    state.counters["occluded_fraction"] = tests ? double(occluded) / double(tests) : 0.0;
    set_per_item(state, "ns_per_test", 1.0);
}

void BM_TestRect_BehindWall(benchmark::State& state) {
    rect_tests(state, wall_buffer(), 0.6, 0.9);
}
BENCHMARK(BM_TestRect_BehindWall)->Arg(16)->Arg(64)->Arg(128)->Arg(256);

void BM_TestRect_InFrontOfWall(benchmark::State& state) {
    rect_tests(state, wall_buffer(), 0.1, 0.4);
}
BENCHMARK(BM_TestRect_InFrontOfWall)->Arg(64);

void BM_TestRect_MSOCBuffer(benchmark::State& state) {
    rect_tests(state, filled_buffer(), 0.0, 1.0);
}
BENCHMARK(BM_TestRect_MSOCBuffer)->Arg(16)->Arg(64);

// Unit boxes seen through a 60-degree perspective camera, 20 to 60 units away, behind a wall
// 10 units in front of the camera (all occluded) or in front of it (all visible).
void box_tests(benchmark::State& state, bool behind) {
    const zraster::Camera camera = [] {
        zraster::Camera c;
        c.eye = {0, 0, 0};
        c.target = {0, 0, -1};
        c.near = 0.5;
        c.far = 200.0;
        return c;
    }();
    const glm::mat4 view_projection = camera.view_projection(double(kWidth) / kHeight);
    OcclusionBuffer buffer(kWidth, kHeight);
    const std::vector<glm::vec3> wall = {
        {-100, -100, -10}, {100, -100, -10}, {100, 100, -10}, {-100, 100, -10}};
    const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
    buffer.render_occluders(std::span<const glm::vec3>(wall), indices, view_projection);
    SplitMix64 rng{11};
    std::vector<glm::mat4> to_clip(4096);
    for (glm::mat4& m : to_clip) {
        const double z = behind ? rng.uniform(-60.0, -20.0) : rng.uniform(-9.0, -3.0);
        const double spread = -z * 0.5;
        const glm::vec3 at(rng.uniform(-spread, spread), rng.uniform(-spread * 0.5, spread * 0.5),
                           z);
        glm::mat4 model(1.0f);
        model[3] = glm::vec4(at, 1.0f);
        m = view_projection * model;
    }
    const zraster::Bounds3f box{glm::vec3(-0.5f), glm::vec3(0.5f)};
    std::size_t i = 0, occluded = 0, tests = 0;
    for (auto _ : state) {
        const OcclusionResult result = buffer.test_box(box, to_clip[i++ & 4095]);
        occluded += result == OcclusionResult::Occluded;
        ++tests;
        benchmark::DoNotOptimize(result);
    }
    state.counters["occluded_fraction"] = tests ? double(occluded) / double(tests) : 0.0;
    set_per_item(state, "ns_per_test", 1.0);
}

void BM_TestBox_BehindWall(benchmark::State& state) {
    box_tests(state, true);
}
BENCHMARK(BM_TestBox_BehindWall);

void BM_TestBox_InFrontOfWall(benchmark::State& state) {
    box_tests(state, false);
}
BENCHMARK(BM_TestBox_InFrontOfWall);

}  // namespace

// (ZRASTER_BENCH_AVX2=1: the AVX2 kernels; see benchmark_main.hpp.)
int main(int argc, char** argv) {
    return zraster::bench::run_benchmarks(argc, argv);
}
