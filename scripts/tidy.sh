#!/usr/bin/env bash
# clang-tidy (the committed .clang-tidy) over every translation unit of src/ and tools/, using
# the compile commands of build/ (configured here if needed, as scripts/build.sh does; nothing is
# compiled). Prints the findings; exits non-zero if there is any.
#
#   bash scripts/tidy.sh [FILE-REGEX]      (default: all of src/ and tools/)
#
# Environment: ZRASTER_TIDY_BUILD_DIR (default build), ZRASTER_TIDY_JOBS (default 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRASTER_TIDY_BUILD_DIR:-$root/build}
filter=${1:-$root/(src|tools)/}
bash "$root/scripts/install-deps.sh"
# Refreshes compile_commands.json (new files are globbed at configure time).
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
log=$(mktemp)
trap 'rm -f "$log"' EXIT
run-clang-tidy -p "$build" -j "${ZRASTER_TIDY_JOBS:-2}" -quiet "$filter" 2>&1 |
    sed 's/\x1b\[[0-9;]*m//g' >"$log" || true  # without colors
# Findings, each once (a header's finding repeats for every file that includes it).
findings=$(grep -E "^/.*: (warning|error): " "$log" | sort -u || true)
files=$(grep -cE "^clang-tidy.* -p=" "$log" || true)
if [ -n "$findings" ]; then
    echo "$findings"
    echo "tidy: $(echo "$findings" | wc -l) findings in $files files"
    exit 1
fi
if grep -qE "^(Error|error):|clang-tidy: error" "$log"; then
    cat "$log" >&2
    echo "tidy: clang-tidy failed" >&2
    exit 1
fi
echo "tidy: clean ($files files)"
