#!/usr/bin/env bash
# The test suite under the sanitizers (clang):
#   asan: every test with AddressSanitizer + UndefinedBehaviorSanitizer (-fno-sanitize-recover=all,
#         LeakSanitizer on) in build-asan/, the build the fuzzers share (configure-asan.sh);
#   tsan: the multithreaded paths with ThreadSanitizer in build-tsan/: the render suite
#         (Determinism.* included) and the parallel OBJ reader (ObjParser.*).
# Any report fails the run. Zero reports is the standard (RELIABILITY.md).
#
#   bash scripts/sanitize.sh [asan|tsan|all]     (default all)
#
# Environment: ZRASTER_ASAN_BUILD_DIR, ZRASTER_TSAN_BUILD_DIR, ZRASTER_SANITIZE_JOBS (build
# parallelism, default 2), ZRASTER_TSAN_FILTER (--gtest_filter of the ThreadSanitizer run).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
which=${1:-all}
jobs=${ZRASTER_SANITIZE_JOBS:-2}
bash "$root/scripts/install-deps.sh"

# Configures and builds one sanitizer build; $1 dir, $2 sanitizer flags, rest: ninja targets.
build() {
    local dir=$1 flags=$2
    shift 2
    CC=clang CXX=clang++ cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Sanitize \
        -DZRASTER_BUILD_TESTS=ON -DZRASTER_INSTALL=OFF -DZRASTER_BUILD_PYTHON=OFF \
        -DZRASTER_UNITY_BUILD=ON \
        -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only -fno-omit-frame-pointer $flags" \
        -DCMAKE_EXE_LINKER_FLAGS="$flags" >/dev/null
    ninja -C "$dir" -j "$jobs" "$@" >"$dir/build.log" 2>&1 || {
        tail -50 "$dir/build.log"
        echo "sanitize: build failed in $dir" >&2
        exit 1
    }
}

status=0

if [ "$which" = asan ] || [ "$which" = all ]; then
    # The same build as the fuzzers' (scripts/configure-asan.sh): every library compiled once.
    dir=${ZRASTER_ASAN_BUILD_DIR:-$root/build-asan}
    bash "$root/scripts/configure-asan.sh" "$dir"
    ninja -C "$dir" -j "$jobs" >"$dir/build.log" 2>&1 || {
        tail -50 "$dir/build.log"
        echo "sanitize: build failed in $dir" >&2
        exit 1
    }
    mkdir -p "$dir/tmp"
    # Tests write their fixtures under $TMPDIR: one per build, so that concurrent suites
    # (another build's ctest) never share a directory.
    if ! (cd "$dir" &&
        TMPDIR=$dir/tmp \
            ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=1 \
            UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
            LSAN_OPTIONS=suppressions=$root/scripts/lsan.supp:print_suppressions=0 \
            ctest --output-on-failure -j "$jobs" --timeout 900 \
                -E '^(LlvmpipeCrossCheck|public_headers_|module_layering)' \
                >"$dir/ctest.log" 2>&1); then
        status=1
    fi
    # The llvmpipe cross-check loads Mesa's driver with dlopen; the driver leaks 112 bytes that
    # LeakSanitizer reports after the library is unloaded, with no module name a suppression
    # could match. It runs with everything but leak detection.
    if ! (cd "$dir" &&
        TMPDIR=$dir/tmp ASAN_OPTIONS=detect_leaks=0 \
            UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
            ctest --output-on-failure --timeout 900 -R '^LlvmpipeCrossCheck' \
                >>"$dir/ctest.log" 2>&1); then
        status=1
    fi
    grep -E "tests passed|tests failed" "$dir/ctest.log" | sed 's/^/asan+ubsan: /' || true
    if grep -qE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$dir/ctest.log"; then
        echo "asan+ubsan: sanitizer reports in $dir/ctest.log:"
        grep -E "ERROR: (Address|Leak)Sanitizer|runtime error:" "$dir/ctest.log" | sort | uniq |
            head -20 || true
        status=1
    fi
    if [ $status -ne 0 ]; then
        grep -E "^\s+[0-9]+ - |\*\*\*Failed|Exception" "$dir/ctest.log" | head -20 || true
    fi
fi

if [ "$which" = tsan ] || [ "$which" = all ]; then
    # The multithreaded paths: the render suite (TBB tiles and chunks; Determinism.* renders the
    # same frames with 1..5 threads) and the parallel OBJ reader (ObjParser.* of the io suite).
    dir=${ZRASTER_TSAN_BUILD_DIR:-$root/build-tsan}
    build "$dir" "-fsanitize=thread $(bash "$root/scripts/sanitizer-hwy-targets.sh")" \
        zraster_render_tests zraster_io_tests
    mkdir -p "$dir/tmp"
    # TBB hands tasks between threads inside libtbb.so; Debian's is not instrumented, so
    # ThreadSanitizer would see none of that synchronization and report every task's data as a
    # race. Build the same oneTBB (Debian's source of the installed libtbb12) with
    # -fsanitize=thread once, and run the tests against it (same soname, same ABI).
    tbb=$dir/tbb-tsan
    if [ ! -e "$tbb/lib/libtbb.so.12" ]; then
        bash "$root/scripts/tsan-tbb.sh" "$tbb"
    fi
    tsan_status=0
    : >"$dir/tests.log"
    for run in "zraster_render_tests:${ZRASTER_TSAN_FILTER:-*}" "zraster_io_tests:ObjParser.*"; do
        (cd "$dir" &&
            TMPDIR=$dir/tmp LD_LIBRARY_PATH=$tbb/lib \
                TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$root/scripts/tsan.supp" \
                "./${run%%:*}" --gtest_filter="${run#*:}" >>"$dir/tests.log" 2>&1) ||
            tsan_status=1
    done
    # The tests must have run against the instrumented oneTBB, not the system's.
    # (ldd's output captured first: `ldd | grep -q` under pipefail fails when grep exits before
    # ldd has written everything.)
    libraries=$(LD_LIBRARY_PATH=$tbb/lib ldd "$dir/zraster_render_tests")
    if ! grep -q "$tbb/lib/libtbb" <<<"$libraries"; then
        echo "tsan: the tests do not load $tbb/lib/libtbb.so.12"
        tsan_status=1
    fi
    grep -E "^\[  (PASSED|FAILED)  \]" "$dir/tests.log" | sed 's/^/tsan: /' || true
    if grep -q "WARNING: ThreadSanitizer" "$dir/tests.log"; then
        echo "tsan: reports in $dir/tests.log:"
        grep -A8 "WARNING: ThreadSanitizer" "$dir/tests.log" | head -40 || true
        tsan_status=1
    fi
    [ $tsan_status -eq 0 ] || status=1
fi

exit $status
