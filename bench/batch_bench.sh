#!/usr/bin/env bash
# `zraster batch` throughput (BENCHMARKS.md, "Batch rendering"):
#   1. 300 meshes of ~5k triangles to 256x256 PNGs: `zraster batch --jobs 2` against a loop of
#      one `zraster render` process per file, in files per second;
#   2. files per second by mesh size (1k, 10k, 100k, 1M triangles) and image size;
#   3. memory over a long batch: peak RSS of 1,000 and of 10,000 files, and the RSS sampled
#      while the 10,000-file batch passes file 1,000 and near its end.
# The meshes are the benchmark sphere written by bench/make_obj.cpp; each set is one file and
# hard links to it under other names (every file is loaded, rendered and written on its own).
#
#   bash bench/batch_bench.sh [BUILD_DIR [WORK_DIR]]      # BUILD_DIR holds the zraster program
#
# Environment: ZRASTER_BATCH_JOBS (2), ZRASTER_BATCH_RUNS (3: the median is shown),
# ZRASTER_BATCH_PARTS (the parts to run, default "1 2 3").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=${2:-$(mktemp -d /tmp/zraster-batch-bench.XXXXXX)}
mkdir -p "$work"
work=$(cd "$work" && pwd)
zraster=$build/zraster
jobs=${ZRASTER_BATCH_JOBS:-2}
runs=${ZRASTER_BATCH_RUNS:-3}
parts=" ${ZRASTER_BATCH_PARTS:-1 2 3} "
[ -x "$zraster" ] || { echo "no zraster program in $build (build target zraster_cli)" >&2; exit 2; }

now() { date +%s.%N; }
# rate FILES START END: files per second.
rate() {
    python3 -c "import sys; print(f'{int(sys.argv[1]) / (float(sys.argv[3]) - float(sys.argv[2])):.1f}')" "$@"
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

# make_set NAME TRIANGLES COUNT: COUNT names for one mesh of about TRIANGLES triangles.
make_set() {
    local dir=$work/$1
    if [ -d "$dir" ] && [ "$(ls "$dir" | wc -l)" -eq "$3" ]; then return; fi
    rm -rf "$dir" && mkdir -p "$dir"
    "$work/make_obj" "$2" "$dir/m00000.obj" >/dev/null 2>&1
    for ((i = 1; i < $3; ++i)); do ln "$dir/m00000.obj" "$dir/$(printf 'm%05d' "$i").obj"; done
}

# batch_rate SET SIZE: files per second of `zraster batch`, the median of $runs runs.
batch_rate() {
    local count rates=() start end
    count=$(ls "$work/$1" | wc -l)
    for ((r = 0; r < runs; ++r)); do
        rm -rf "$work/out"
        start=$(now)
        "$zraster" batch "$work/$1" -o "$work/out" --size "$2" --jobs "$jobs" --progress none \
            2>/dev/null
        end=$(now)
        rates+=("$(rate "$count" "$start" "$end")")
    done
    median "${rates[@]}"
}

batch_against_loop() {
    make_set tri5k 5000 300
    local triangles batch cpu cpu_ms loop start end
    triangles=$("$zraster" info "$work/tri5k/m00000.obj" | grep -m1 -o '[0-9,]* triangles')
    batch=$(batch_rate tri5k 256x256)
    # The CPU time of one batch (user + system): what the files cost, whatever else runs.
    rm -rf "$work/out"
    cpu=$(/usr/bin/time -f '%U %S' "$zraster" batch "$work/tri5k" -o "$work/out" \
        --size 256x256 --jobs "$jobs" --progress none 2>&1 >/dev/null | tail -1)
    cpu_ms=$(python3 -c "import sys; print(f'{(float(sys.argv[1]) + float(sys.argv[2])) / 0.3:.2f}')" $cpu)
    rm -rf "$work/loop" && mkdir -p "$work/loop"
    start=$(now)
    for f in "$work"/tri5k/*.obj; do
        "$zraster" render "$f" -o "$work/loop/$(basename "$f" .obj).png" --size 256x256
    done
    end=$(now)
    loop=$(rate 300 "$start" "$end")
    echo "| 300 files of $triangles, 256x256 | files/s |"
    echo "|---|---|"
    echo "| zraster batch --jobs $jobs | $batch |"
    echo "| a loop of zraster render | $loop |"
    echo "| ratio | $(python3 -c "print(f'{$batch / $loop:.1f}x')") |"
    echo
    echo "zraster batch: $cpu_ms ms of CPU time (user + system) per file"
    echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo
}

by_mesh_and_image_size() {
    local tris count
    echo "| triangles (files) | 256x256 | 1024x1024 |"
    echo "|---|---|---|"
    for spec in "1000 300" "10000 300" "100000 60" "1000000 10"; do
        read -r tris count <<<"$spec"
        make_set "tri$tris" "$tris" "$count"
        echo "| $tris ($count) | $(batch_rate "tri$tris" 256x256) | $(batch_rate "tri$tris" 1024x1024) |"
    done
    echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo
}

peak_rss() {
    rm -rf "$work/out-$1"
    /usr/bin/time -f %M "$zraster" batch "$work/$1" -o "$work/out-$1" --size 256x256 \
        --jobs "$jobs" --progress none 2>&1 >/dev/null | tail -1
}

memory_over_10000_files() {
    make_set rss1k 1000 1000
    make_set rss10k 1000 10000
    local peak1k peak10k pid lines rss at1k="" last="" last_lines=0
    peak1k=$(peak_rss rss1k)
    peak10k=$(peak_rss rss10k)
    # VmRSS sampled every 20 ms while the 10,000-file batch runs: at the first sample past file
    # 1,000, and the last one before it ends.
    rm -rf "$work/out-rss10k"
    "$zraster" batch "$work/rss10k" -o "$work/out-rss10k" --size 256x256 --jobs "$jobs" \
        --progress none 2>/dev/null &
    pid=$!
    while kill -0 "$pid" 2>/dev/null; do
        lines=$(wc -l 2>/dev/null <"$work/out-rss10k/batch.jsonl" || echo 0)
        rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
        if [ -n "$rss" ]; then
            if [ -z "$at1k" ] && [ "$lines" -ge 1000 ]; then at1k="$rss (file $lines)"; fi
            last=$rss last_lines=$lines
        fi
        sleep 0.02
    done
    wait "$pid"
    echo "| 1k-triangle files, 256x256 | RSS, KiB |"
    echo "|---|---|"
    echo "| peak, a batch of 1,000 files | $peak1k |"
    echo "| peak, a batch of 10,000 files | $peak10k |"
    echo "| 10,000 files: sampled past file 1,000 | $at1k |"
    echo "| 10,000 files: last sample | $last (file $last_lines) |"
}

g++ -std=c++20 -O2 "$root/bench/make_obj.cpp" -o "$work/make_obj"
echo "machine: $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "zraster: $("$zraster" --version), --jobs $jobs, median of $runs runs"
echo
if [[ "$parts" == *" 1 "* ]]; then batch_against_loop; fi
if [[ "$parts" == *" 2 "* ]]; then by_mesh_and_image_size; fi
if [[ "$parts" == *" 3 "* ]]; then memory_over_10000_files; fi
