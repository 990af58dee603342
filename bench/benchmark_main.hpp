// The main() of the Google Benchmark suites: ZRASTER_BENCH_AVX2=1 runs the AVX2 kernels on an
// AVX-512 machine (what a machine without AVX-512 would run; Intel's published MSOC figures
// are for AVX2).
#pragma once
#include <benchmark/benchmark.h>
#include <hwy/targets.h>

#include <cstdlib>

namespace zraster::bench {

inline int run_benchmarks(int argc, char** argv) {
    if (const char* avx2 = std::getenv("ZRASTER_BENCH_AVX2"); avx2 != nullptr && *avx2 == '1')
        hwy::DisableTargets(HWY_AVX2 - 1);  // the targets better than AVX2
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

}  // namespace zraster::bench
