#!/usr/bin/env bash
# `zraster batch` throughput (BENCHMARKS.md, "Batch rendering"):
#   1. 300 meshes of ~5k triangles to 256x256 PNGs: `zraster batch --jobs 2` against a loop of
#      one `zraster render` process per file, in files per second;
#   2. files per second by mesh size (1k, 10k, 100k, 1M triangles) and image size;
#   3. memory over a long batch: peak RSS of 1,000 and of 10,000 files, and the RSS sampled
#      while the 10,000-file batch passes file 1,000 and file 9,000.
# The meshes are the benchmark sphere written by bench/make_obj.cpp; each set is one file and
# hard links to it under other names (every file is loaded, rendered and written on its own).
#
#   bash bench/batch_bench.sh [BUILD_DIR [WORK_DIR]]      # BUILD_DIR holds the zraster program
#   ZRASTER_BATCH_JOBS=2 ZRASTER_BATCH_RUNS=3 ZRASTER_BATCH_QUICK=1 (skip 2 and 3)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=${2:-$(mktemp -d /tmp/zraster-batch-bench.XXXXXX)}
mkdir -p "$work"
work=$(cd "$work" && pwd)
zraster=$build/zraster
jobs=${ZRASTER_BATCH_JOBS:-2}
runs=${ZRASTER_BATCH_RUNS:-3}
[ -x "$zraster" ] || { echo "no zraster program in $build (build target zraster_cli)" >&2; exit 2; }

now() { date +%s.%N; }
# rate FILES START END: files per second
rate() { python3 -c "import sys; print(f'{int(sys.argv[1]) / (float(sys.argv[3]) - float(sys.argv[2])):.1f}')" "$@"; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

g++ -std=c++20 -O2 "$root/bench/make_obj.cpp" -o "$work/make_obj"
# make_set NAME TRIANGLES COUNT: COUNT names for one mesh of about TRIANGLES triangles.
make_set() {
    local dir=$work/$1
    [ -d "$dir" ] && [ "$(ls "$dir" | wc -l)" -eq "$3" ] && return
    rm -rf "$dir" && mkdir -p "$dir"
    "$work/make_obj" "$2" "$dir/m00000.obj" >/dev/null 2>&1
    for ((i = 1; i < $3; ++i)); do ln "$dir/m00000.obj" "$dir/$(printf 'm%05d' "$i").obj"; done
}
# batch_rate SET SIZE [FLAGS...]: files per second of `zraster batch`, the median of $runs runs.
batch_rate() {
    local set=$1 size=$2 count rates=()
    shift 2
    count=$(ls "$work/$set" | wc -l)
    for ((r = 0; r < runs; ++r)); do
        rm -rf "$work/out"
        local start end
        start=$(now)
        "$zraster" batch "$work/$set" -o "$work/out" --size "$size" --jobs "$jobs" \
            --progress none "$@" 2>/dev/null
        end=$(now)
        rates+=("$(rate "$count" "$start" "$end")")
    done
    median "${rates[@]}"
}

echo "machine: $(nproc) CPUs, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "zraster: $("$zraster" --version), --jobs $jobs, median of $runs runs"
echo

make_set tri5k 5000 300
triangles=$("$zraster" info "$work/tri5k/m00000.obj" | grep -m1 -o '[0-9,]* triangles' || true)
batch=$(batch_rate tri5k 256x256)
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
[ -n "${ZRASTER_BATCH_QUICK:-}" ] && exit 0

echo "| triangles (files) | 256x256 | 1024x1024 |"
echo "|---|---|---|"
for spec in "1000 300" "10000 300" "100000 60" "1000000 10"; do
    read -r tris count <<<"$spec"
    make_set "tri$tris" "$tris" "$count"
    echo "| $tris ($count) | $(batch_rate "tri$tris" 256x256) | $(batch_rate "tri$tris" 1024x1024) |"
done
echo

# Memory: peak RSS of a 1,000-file and a 10,000-file batch, and VmRSS sampled during the latter.
make_set rss1k 1000 1000
make_set rss10k 1000 10000
peak() { /usr/bin/time -f %M "$zraster" batch "$work/$1" -o "$work/out-$1" --size 256x256 \
    --jobs "$jobs" --progress none 2>&1 >/dev/null | tail -1; }
rm -rf "$work/out-rss1k" "$work/out-rss10k"
peak1k=$(peak rss1k)
"$zraster" batch "$work/rss10k" -o "$work/out-rss10k" --size 256x256 --jobs "$jobs" \
    --progress none 2>/dev/null &
pid=$!
at1k="" at9k=""
while kill -0 "$pid" 2>/dev/null; do
    lines=$(cat "$work/out-rss10k/batch.jsonl" 2>/dev/null | wc -l)
    rss=$(awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
    [ -z "$at1k" ] && [ "$lines" -ge 1000 ] && at1k=$rss
    [ -z "$at9k" ] && [ "$lines" -ge 9000 ] && at9k=$rss
    sleep 0.02
done
wait "$pid"
rm -rf "$work/out-rss10k"
peak10k=$(peak rss10k)
echo "| 1k-triangle files, 256x256 | KiB |"
echo "|---|---|"
echo "| peak RSS, 1,000 files | $peak1k |"
echo "| peak RSS, 10,000 files | $peak10k |"
echo "| RSS at file 1,000 of 10,000 | $at1k |"
echo "| RSS at file 9,000 of 10,000 | $at9k |"
