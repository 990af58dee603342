#!/usr/bin/env bash
# Configures the one clang build that holds both the test suite under AddressSanitizer +
# UndefinedBehaviorSanitizer (scripts/sanitize.sh asan) and the libFuzzer targets
# (scripts/fuzz.sh): the libraries are compiled once, with the sanitizers and libFuzzer's coverage
# instrumentation (-fsanitize=fuzzer-no-link; the test executables link the sanitizer runtimes'
# no-op coverage callbacks, the fuzzers link libFuzzer). Building them twice cost CI several
# minutes on 2 cores.
#
#   bash scripts/configure-asan.sh DIR
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$1
flags="-O1 -gline-tables-only -fno-omit-frame-pointer"
flags+=" -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all"
# Highway's SSSE3 and SSE4 targets are left out of the sanitizer builds (the Release suite tests
# every kernel on every target): the kernels compiled per target were a quarter of this build's
# compile time. AVX-512, AVX2 and the portable baseline stay.
flags+=" $(bash "$root/scripts/sanitizer-hwy-targets.sh")"
CC=clang CXX=clang++ cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Sanitize \
    -DZRASTER_BUILD_TESTS=ON -DZRASTER_BUILD_FUZZERS=ON -DZRASTER_INSTALL=OFF -DZRASTER_BUILD_PYTHON=OFF \
    -DZRASTER_UNITY_BUILD=ON \
    -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
