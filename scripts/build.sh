#!/usr/bin/env bash
# Installs what is missing and builds zraster (Release, -O2) into build/ (or $ZRASTER_BUILD_DIR).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRASTER_BUILD_DIR:-$root/build}
bash "$root/scripts/install-deps.sh"
# Unity batches: a full build in half the time (-DZRASTER_UNITY_BUILD=OFF for file-by-file
# rebuilds while editing).
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DZRASTER_UNITY_BUILD=ON "$@" \
    >/dev/null
ninja -C "$build" -j "$(nproc)"
