#!/usr/bin/env bash
# The module layering of docs/architecture.md, as CMakeLists.txt declares it (zraster_module
# DEPS), checked on the sources:
#   check_layering.sh SOURCE_DIR LAYERS_FILE
# LAYERS_FILE has one line per module, "module dep dep ...", with the modules it builds on
# directly. A file of src/M may include "X/..." only for X = M, a module M builds on (directly
# or through others), or the header-only utilities simd/ and memory/. The engine (every module
# but io) includes no file-format or command-line library; it knows no files or processes
# (no file streams, /sys, /proc or environment variables) but in platform/, which asks the
# operating system; and bench/ includes nothing of tools/. Prints each violation with its file
# and line.
set -euo pipefail
source=$1 layers=$2
declare -A direct
while read -r module deps; do
    [ -n "$module" ] && direct[$module]="$deps"
done <"$layers"

# The modules M builds on, directly or not.
reachable() {
    local -A seen=()
    local stack=(${direct[$1]}) m
    while [ ${#stack[@]} -gt 0 ]; do
        m=${stack[-1]}
        unset 'stack[-1]'
        [ -n "${seen[$m]:-}" ] && continue
        seen[$m]=1
        stack+=(${direct[$m]:-})
    done
    echo "${!seen[@]}"
}

violations=0
for module in "${!direct[@]}"; do
    allowed=" $module $(reachable "$module") simd memory "
    while IFS=: read -r file line text; do
        target=$(sed -E 's/.*#include "([a-z_]+)\/.*/\1/' <<<"$text")
        if [[ "$allowed" != *" $target "* ]]; then
            echo "layering: ${file#$source/}:$line includes $target/ (src/$module builds on:${allowed})"
            violations=$((violations + 1))
        fi
    done < <(grep -rnE '^#include "[a-z_]+/' "$source/src/$module" || true)
    if [ "$module" != io ]; then
        while IFS= read -r hit; do
            echo "layering: ${hit#$source/}: the engine includes a file-format or command-line library"
            violations=$((violations + 1))
        done < <(grep -rnE '^#include <(assimp|stb|stb_image|libdeflate|fmt|CLI|nlohmann)|^#include <zraster/(load|image_io)\.hpp>' \
            "$source/src/$module" || true)
    fi
    if [ "$module" != io ] && [ "$module" != platform ]; then
        while IFS= read -r hit; do
            echo "layering: ${hit#$source/}: the engine reads files or its process's environment (platform/ does)"
            violations=$((violations + 1))
        done < <(grep -rnE '^#include <(fstream|filesystem)>|"/(sys|proc)/|getenv\(' "$source/src/$module" || true)
    fi
done
while IFS= read -r hit; do
    echo "layering: ${hit#$source/}: bench/ includes tools/"
    violations=$((violations + 1))
done < <(grep -rnE '^#include "(\.\./)*tools/' "$source/bench" || true)

echo "module layering: ${#direct[@]} modules checked, $violations violation(s)"
[ "$violations" -eq 0 ]
