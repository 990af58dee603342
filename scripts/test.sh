#!/usr/bin/env bash
# Fresh Debian 12 to a test report: installs packages, builds, runs the whole suite with ctest.
#
# Unless ZRASTER_QUICK=1, three more checks run first (RELIABILITY.md), each in its own build:
#   1. the whole suite under AddressSanitizer + UndefinedBehaviorSanitizer (scripts/sanitize.sh
#      asan, build-asan/),
#   2. the multithreaded paths under ThreadSanitizer (scripts/sanitize.sh tsan, build-tsan/,
#      with an instrumented oneTBB built from Debian's source package),
#   3. a short run of every libFuzzer target, about 72 s in all (scripts/fuzz.sh, in the
#      build-asan/ build), with the loaders in the command's worker-process configuration,
#   4. zraster as a subproject of another CMake project, built as shared libraries
#      (scripts/consumer_check.sh subproject; the installed-package check is a ctest test).
# Then the main (Release) suite, whose ctest summary ends the output. Any failure makes the exit
# status non-zero; a failed extra step is reported before the main suite runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRASTER_BUILD_DIR:-$root/build}
start=$SECONDS
# The benchmarks are built too (not run): a change that breaks them fails here.
bash "$root/scripts/build.sh" -DZRASTER_BUILD_BENCH=ON
echo "test.sh: Release build ($((SECONDS - start)) s)"

failed=""
if [ "${ZRASTER_QUICK:-0}" != 1 ]; then
    step() {
        local name=$1 t0=$SECONDS
        shift
        echo "test.sh: $name ..."
        if "$@"; then
            echo "test.sh: $name passed ($((SECONDS - t0)) s)"
        else
            echo "test.sh: $name FAILED ($((SECONDS - t0)) s)"
            failed+=" $name"
        fi
    }
    step "asan+ubsan suite" bash "$root/scripts/sanitize.sh" asan
    step "tsan multithreaded tests" bash "$root/scripts/sanitize.sh" tsan
    step "short fuzz runs" env ZRASTER_FUZZ_LOAD_ISOLATION=worker \
        bash "$root/scripts/fuzz.sh" "${ZRASTER_FUZZ_SECONDS:-6}"
    step "shared-library subproject check" bash "$root/scripts/consumer_check.sh" subproject
    if [ -n "$failed" ]; then echo "test.sh: FAILED:$failed"; fi
else
    echo "test.sh: ZRASTER_QUICK=1: sanitizer builds and fuzz runs skipped"
fi

cd "$build"
status=0
ctest --output-on-failure -j "$(nproc)" --timeout 600 || status=$?
[ -z "$failed" ] || exit 1
exit $status
