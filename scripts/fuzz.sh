#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) in
# build-fuzz/ and runs each for SECONDS_PER_TARGET seconds (default 10), one after the other.
# Prints per target the executions and any finding; exits non-zero if a target found a crash,
# a leak, a timeout or an out-of-memory.
#
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET]
#
# Environment: ZRASTER_FUZZ_BUILD_DIR (default build-asan, shared with scripts/sanitize.sh asan),
# ZRASTER_FUZZ_TARGETS (space-separated subset), ZRASTER_FUZZ_JOBS (build parallelism, default 2),
# ZRASTER_FUZZ_TIMEOUT (seconds an input may take before it is a hang finding, default 20),
# ZRASTER_FUZZ_LOAD_ISOLATION=worker (the loader targets run Assimp in the worker process the
# command uses, so that Assimp's own crashes, open findings 16 and 17, are refused files: what CI
# runs; default: in process, where the sanitizers see them).
# Corpora grow in $build/corpus/<target> across runs; findings land in $build/findings/<target>.
# Seeds: fuzz/seeds/<target> (committed) plus the shared meshes of ../shared/data/meshes of the
# target's formats (copied at run time, not committed).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRASTER_FUZZ_BUILD_DIR:-$root/build-asan}
seconds=${1:-10}
all_targets="fuzz_load_obj fuzz_load_ply fuzz_load_stl fuzz_load_gltf fuzz_load_off fuzz_load_3ds
             fuzz_load_dae fuzz_load_lws
             fuzz_cells fuzz_pipeline fuzz_cluster_cull fuzz_cli fuzz_worker_message fuzz_mesh_view
             fuzz_gltf_graph fuzz_obj_mtl"
targets=${ZRASTER_FUZZ_TARGETS:-$all_targets}
shared=$root/../shared/data/meshes

bash "$root/scripts/install-deps.sh"
# The build the sanitized test suite uses too (scripts/configure-asan.sh).
bash "$root/scripts/configure-asan.sh" "$build"
# shellcheck disable=SC2086
ninja -C "$build" -j "${ZRASTER_FUZZ_JOBS:-2}" $targets >"$build/fuzz-build.log" 2>&1 || {
    tail -50 "$build/fuzz-build.log"
    echo "fuzz: build failed in $build" >&2
    exit 1
}

# Seeds for a target: its committed seeds and the shared meshes of its formats (<= 128 KiB).
shared_patterns() {
    case $1 in
        fuzz_load_obj) echo "*.obj" ;;
        fuzz_load_ply) echo "*.ply" ;;
        fuzz_load_stl) echo "*.stl" ;;
        fuzz_load_gltf) echo "*.gltf *.glb" ;;
        fuzz_load_off) echo "*.off" ;;
        fuzz_load_3ds) echo "*.3ds" ;;
        fuzz_load_dae) echo "*.dae" ;;
    esac
}
# Seconds for a target: SECONDS_PER_TARGET, but half of it (at least 1) for the two targets that
# saturate in seconds (hundreds of thousands of executions a second: fuzz_cluster_cull,
# fuzz_worker_message) and for the two generator targets (fuzz_gltf_graph, fuzz_obj_mtl, whose
# inputs all build valid files), which keeps the short CI run (6 s) short. Longer runs (ZRASTER_FUZZ_EVEN=1, or SECONDS_PER_TARGET over 60)
# give every target the full time.
target_seconds() {
    if [ "${ZRASTER_FUZZ_EVEN:-0}" = 1 ] || [ "$seconds" -gt 60 ]; then
        echo "$seconds"
        return
    fi
    case $1 in
        fuzz_cluster_cull | fuzz_worker_message | fuzz_gltf_graph | fuzz_obj_mtl)
            echo $(((seconds + 1) / 2)) ;;
        *) echo "$seconds" ;;
    esac
}
dictionary() {
    case $1 in
        fuzz_load_obj) echo obj ;;
        fuzz_load_ply) echo ply ;;
        fuzz_load_stl) echo stl ;;
        fuzz_load_gltf) echo gltf ;;
        fuzz_load_off) echo off ;;
        fuzz_load_dae) echo dae ;;
        fuzz_load_lws) echo lws ;;
        fuzz_cells) echo cells ;;
        fuzz_cli) echo cli ;;
    esac
}

# Companion files (glTF buffers and textures) the shared glTF seeds refer to by name.
fixtures=""
for d in "$shared"/gltf/*/; do
    [ -d "$d" ] && fixtures+="${fixtures:+:}$d"
done
export ZRASTER_FUZZ_FIXTURES=$fixtures
# Sanitizer reports must fail the run; leaks are findings too.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/scripts/lsan.supp:print_suppressions=0}
mkdir -p "$build/tmp"
export TMPDIR=$build/tmp

status=0
total_runs=0
total_seconds=0
for t in $targets; do
    corpus=$build/corpus/$t
    seeds=$build/seeds/$t
    findings=$build/findings/$t
    mkdir -p "$corpus" "$findings"
    rm -rf "$seeds"
    mkdir -p "$seeds"
    cp "$root/fuzz/seeds/$t/"* "$seeds/" 2>/dev/null || true
    for p in $(shared_patterns "$t"); do
        if [ -d "$shared" ]; then
            find "$shared" -name "$p" -size -129k -exec cp {} "$seeds/" \;
        fi
    done
    # Slow units (libFuzzer saves any input over 10 s by default) are not findings: on a loaded
    # machine a 0.5 s input can take that long. Hangs are: -timeout (ZRASTER_FUZZ_TIMEOUT
    # seconds, default 20; long runs at low priority beside other work want more, or CPU
    # starvation ends them as a "timeout").
    t_seconds=$(target_seconds "$t")
    total_seconds=$((total_seconds + t_seconds))
    args=(-max_total_time="$t_seconds" -timeout="${ZRASTER_FUZZ_TIMEOUT:-20}" -report_slow_units=20
          -rss_limit_mb=2048
          -malloc_limit_mb=512
          -max_len=65536 -close_fd_mask=1 -print_final_stats=1 -artifact_prefix="$findings/")
    dict=$(dictionary "$t")
    [ -n "$dict" ] && args+=(-dict="$root/fuzz/dict/$dict.dict")
    log=$build/$t.log
    before=$(find "$findings" -type f ! -name 'slow-unit-*' | wc -l)
    rc=0
    "$build/fuzz/$t" "${args[@]}" "$corpus" "$seeds" >"$log" 2>&1 || rc=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    runs=${runs:-0}
    total_runs=$((total_runs + runs))
    files=$(find "$corpus" -type f | wc -l)
    new=$(find "$findings" -type f ! -name 'slow-unit-*' | wc -l)
    if [ "$rc" -ne 0 ] || [ "$new" -gt "$before" ]; then
        status=1
        line=$(printf '%-16s %9s runs in %ss, corpus %5s: FINDING (exit %s), see %s' \
            "$t" "$runs" "$t_seconds" "$files" "$rc" "$log")
        echo "$line"
        grep -E "ERROR: |runtime error: |invariant broken|Test unit written" "$log" | head -5 |
            sed 's/^/    /'
    else
        line=$(printf '%-16s %9s runs in %ss, corpus %5s: no finding' "$t" "$runs" "$t_seconds" \
            "$files")
        echo "$line"
    fi
done
echo "fuzz: $total_runs executions in total, $(echo "$targets" | wc -w) targets, ${total_seconds}s:" \
    "$([ $status -eq 0 ] && echo "no finding" || echo "FINDINGS (see above)")"
exit $status
