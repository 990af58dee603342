#!/usr/bin/env bash
# Compiles every public header on its own, as a consumer would include it, with the strictest
# warnings as errors and only the definitions zraster::core exports:
#   check_headers.sh COMPILER SOURCE_DIR BINARY_DIR
# Fails naming each header that does not compile alone or warns.
set -euo pipefail
compiler=$1 source=$2 binary=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0 count=0
for header in "$source"/include/zraster/*.hpp "$binary"/include/zraster/*.hpp; do
    name=zraster/$(basename "$header")
    printf '#include <%s>\n#include <%s>\nint main() {}\n' "$name" "$name" >"$work/main.cpp"
    if ! "$compiler" -std=c++20 -Wall -Wextra -Wpedantic -Werror -Wshadow -fsyntax-only \
        -DGLM_FORCE_XYZW_ONLY -DGLM_ENABLE_EXPERIMENTAL \
        -I"$source/include" -I"$binary/include" "$work/main.cpp" 2>"$work/log"; then
        echo "FAILED: $name does not compile alone with $compiler:"
        head -20 "$work/log"
        failed=$((failed + 1))
    fi
    count=$((count + 1))
done
echo "$count public headers compiled alone with $(basename "$compiler"), $failed failed"
[ "$failed" -eq 0 ]
