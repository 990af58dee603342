#!/usr/bin/env bash
# Compiles every public header on its own, as a consumer would include it, with the strictest
# warnings as errors and only the definitions zraster::core exports:
#   check_headers.sh COMPILER SOURCE_DIR BINARY_DIR
# Fails naming each header that does not compile alone or warns.
set -euo pipefail
shopt -s nullglob
compiler=$1 source=$2 binary=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# One header: included twice (include guards) into an otherwise empty program.
check() {
    local name=zraster/$(basename "$1") tag
    tag=$(basename "$1" .hpp)
    printf '#include <%s>\n#include <%s>\nint main() {}\n' "$name" "$name" >"$work/$tag.cpp"
    if ! "$compiler" -std=c++20 -Wall -Wextra -Wpedantic -Werror -Wshadow -fsyntax-only \
        -DGLM_FORCE_XYZW_ONLY -DGLM_ENABLE_EXPERIMENTAL \
        -I"$source/include" -I"$binary/include" "$work/$tag.cpp" 2>"$work/$tag.log"; then
        echo "FAILED: $name does not compile alone with $compiler:"
        head -20 "$work/$tag.log"
        return 1
    fi
}
export -f check
export compiler source binary work
headers=("$source"/include/zraster/*.hpp "$binary"/include/zraster/*.hpp)
failed=$(printf '%s\n' "${headers[@]}" |
    xargs -P "$(nproc)" -I{} bash -c 'check "$1" || echo "FAILED-HEADER"' _ {} |
    tee "$work/report" | grep -c '^FAILED-HEADER' || true)
grep -v '^FAILED-HEADER' "$work/report" || true
echo "${#headers[@]} public headers compiled alone with $(basename "$compiler"), $failed failed"
[ "$failed" -eq 0 ]
