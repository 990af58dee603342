#!/usr/bin/env bash
# The install/consumer check (docs/api.md): zraster as another project sees it.
#
#   bash scripts/consumer_check.sh installed   (default)
#     Installs the build in $ZRASTER_BUILD_DIR (default build/) into a temporary prefix, then
#     builds the examples/ out of tree against it with find_package(zraster) and with pkg-config,
#     with GCC and with Clang, and runs them. Checks the installed layout too.
#   bash scripts/consumer_check.sh subproject
#     A consumer project that add_subdirectory()s this source tree with BUILD_SHARED_LIBS=ON:
#     zraster's tests, benchmarks and command stay out of it, the shared libraries link with no
#     undefined symbols and export the public API only (nothing of zraster::detail), and the
#     examples run against them.
# Exit status 0 when every check passed; each failure is printed with its cause.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRASTER_BUILD_DIR:-$root/build}
mode=${1:-installed}
work=$(mktemp -d "${TMPDIR:-/tmp}/zraster-consumer.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
    echo "consumer check: FAILED: $*"
    failures=$((failures + 1))
}

# Runs the three examples built in $1, checking their outputs.
run_examples() {
    local dir=$1 label=$2
    if "$dir/render_from_memory" "$work/out.ppm" >"$work/log" 2>&1 && [ -s "$work/out.ppm" ]; then
        echo "consumer check: $label: render_from_memory: $(head -1 "$work/log")"
    else
        fail "$label: render_from_memory: $(cat "$work/log")"
    fi
    if "$dir/occlusion_culling" >"$work/log" 2>&1; then
        echo "consumer check: $label: occlusion_culling: $(head -1 "$work/log")"
    else
        fail "$label: occlusion_culling: $(cat "$work/log")"
    fi
    if [ -x "$dir/load_and_render" ]; then
        if "$dir/load_and_render" sphere:2000 "$work/out.png" >"$work/log" 2>&1 &&
            [ "$(head -c 4 "$work/out.png" | od -An -c | tr -d ' ')" = '211PNG' ]; then
            echo "consumer check: $label: load_and_render: $(head -1 "$work/log")"
        else
            fail "$label: load_and_render: $(cat "$work/log")"
        fi
        rm -f "$work/out.png"
    fi
    rm -f "$work/out.ppm"
}

compilers=(g++)
command -v clang++ >/dev/null && compilers+=(clang++)

if [ "$mode" = installed ]; then
    prefix=$work/prefix
    cmake --install "$build" --prefix "$prefix" >"$work/install.log" 2>&1 ||
        { cat "$work/install.log"; exit 1; }
    libdir=$(dirname "$(find "$prefix" -name zraster-core.pc | head -1)")
    libdir=${libdir%/pkgconfig}
    for f in include/zraster/render.hpp include/zraster/version.hpp include/zraster/export.hpp \
        bin/zraster; do
        [ -e "$prefix/$f" ] || fail "installed prefix lacks $f"
    done
    for f in libzraster_core.a libzraster_io.a cmake/zraster/zrasterConfig.cmake \
        cmake/zraster/zrasterConfigVersion.cmake cmake/zraster/zrasterTargets.cmake \
        pkgconfig/zraster-core.pc pkgconfig/zraster.pc; do
        [ -e "$libdir/$f" ] || fail "installed prefix lacks ${libdir#$prefix/}/$f"
    done
    # No file-format library in zraster::core's headers or on its link line.
    if grep -rlE '#include <(assimp|stb|libdeflate|fmt|CLI|nlohmann)' "$prefix/include/zraster" \
        | grep -vE '/(load|image_io)\.hpp$'; then
        fail "a zraster::core header includes a file-format or command-line library"
    fi
    if grep -E 'assimp|stb|deflate|fmt|CLI11|nlohmann' "$libdir/pkgconfig/zraster-core.pc"; then
        fail "zraster-core.pc names a file-format library"
    fi
    version=$("$prefix/bin/zraster" --version 2>/dev/null || true)
    echo "consumer check: installed into a temporary prefix (${libdir#$prefix/}), zraster --version: ${version:-?}"

    for cxx in "${compilers[@]}"; do
        # CMake: find_package(zraster) from the prefix.
        out=$work/cmake-$cxx
        if cmake -S "$root/examples" -B "$out" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" \
            -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release >"$work/log" 2>&1 &&
            cmake --build "$out" >>"$work/log" 2>&1; then
            run_examples "$out" "find_package, $cxx"
        else
            fail "find_package, $cxx: the examples do not build: $(tail -30 "$work/log")"
        fi
        # pkg-config: static libraries need --static for their private dependencies.
        out=$work/pkg-$cxx
        mkdir -p "$out"
        export PKG_CONFIG_PATH=$libdir/pkgconfig
        ok=1
        for example in render_from_memory occlusion_culling; do
            # shellcheck disable=SC2046
            "$cxx" -std=c++20 -O2 "$root/examples/$example/main.cpp" -o "$out/$example" \
                $(pkg-config --cflags --libs --static zraster-core) >"$work/log" 2>&1 ||
                { ok=0; fail "pkg-config zraster-core, $cxx: $example: $(tail -20 "$work/log")"; }
        done
        # shellcheck disable=SC2046
        "$cxx" -std=c++20 -O2 "$root/examples/load_and_render/main.cpp" -o "$out/load_and_render" \
            $(pkg-config --cflags --libs --static zraster) >"$work/log" 2>&1 ||
            { ok=0; fail "pkg-config zraster, $cxx: load_and_render: $(tail -20 "$work/log")"; }
        [ $ok = 1 ] && run_examples "$out" "pkg-config, $cxx"
    done
elif [ "$mode" = subproject ]; then
    consumer=$work/consumer
    mkdir -p "$consumer"
    cat >"$consumer/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(consumer LANGUAGES CXX)
set(BUILD_SHARED_LIBS ON)
add_subdirectory("$root" zraster)
foreach(example render_from_memory occlusion_culling)
  add_executable(\${example} "$root/examples/\${example}/main.cpp")
  target_link_libraries(\${example} PRIVATE zraster::core)
endforeach()
add_executable(load_and_render "$root/examples/load_and_render/main.cpp")
target_link_libraries(load_and_render PRIVATE zraster::zraster)
CMAKE
    # GoogleTest, Google Benchmark, CLI11 and fmt are not asked for: a consumer needs none of them.
    # Unoptimized: the check is about the build, the exports and the link, and -O0 compiles the
    # SIMD kernels in a fraction of the time. File by file (the other builds are unity builds):
    # every source of the libraries compiles on its own, with the includes it names.
    if ! cmake -S "$consumer" -B "$consumer/build" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
        -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DZRASTER_UNITY_BUILD=OFF \
        -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON -DCMAKE_DISABLE_FIND_PACKAGE_fmt=ON \
        >"$work/log" 2>&1; then
        fail "add_subdirectory: configuration failed: $(tail -30 "$work/log")"
    elif ! ninja -C "$consumer/build" -j "$(nproc)" >"$work/log" 2>&1; then
        fail "add_subdirectory: the build failed: $(grep -A5 -m3 'FAILED\|error' "$work/log" | head -40)"
    else
        targets=$(ninja -C "$consumer/build" -t targets all)
        if grep -qE '^(zraster_[a-z]+_tests|pipeline_bench|zraster_cli|fuzz_)' <<<"$targets"; then
            fail "add_subdirectory builds zraster's tests, benchmarks or command"
        fi
        core=$(find "$consumer/build" -name 'libzraster_core.so.*' -type f | head -1)
        if [ -z "$core" ]; then
            fail "BUILD_SHARED_LIBS=ON made no libzraster_core.so"
        else
            exported=$(nm -DC --defined-only "$core")
            leaked=$(grep -cE 'zraster::detail|hwy::|zraster::N_' <<<"$exported" || true)
            api=$(grep -cE ' T zraster::' <<<"$exported" || true)
            [ "$leaked" -eq 0 ] || fail "libzraster_core.so exports $leaked internal symbols: $(grep -E 'zraster::detail|hwy::' <<<"$exported" | head -5)"
            [ "$api" -gt 50 ] || fail "libzraster_core.so exports only $api functions"
            soname=$(objdump -p "$core" | awk '/SONAME/ {print $2}')
            echo "consumer check: shared: $(basename "$core") (SONAME $soname), $api API functions exported, $leaked internal"
        fi
        libraries=$(ldd "$consumer/build/render_from_memory")
        grep -q 'libzraster_core.so' <<<"$libraries" ||
            fail "render_from_memory is not linked to the shared libzraster_core"
        run_examples "$consumer/build" "add_subdirectory, shared"
    fi
else
    echo "usage: consumer_check.sh [installed|subproject]" >&2
    exit 2
fi

if [ "$failures" -gt 0 ]; then
    echo "consumer check ($mode): $failures failure(s)"
    exit 1
fi
echo "consumer check ($mode): passed"
