#!/bin/bash
# zraster's occlusion buffer and Intel's Masked Software Occlusion Culling (MSOC) side by side,
# both on their AVX2 paths, in one process (bench/msoc_compare.cpp): MSOC's fill-rate workload
# (100k triangles at 1920x1080) and rectangle tests. MSOC's public source is fetched into a
# scratch folder outside the repository and built there, with the comparison, against an
# install of the zraster build; nothing of MSOC's enters the repository.
#
#   bash scripts/msoc_compare.sh [ROUNDS]     (default 15)
#   MSOC_SOURCE=PATH_OR_URL   a clone of github.com/GameTechDev/MaskedOcclusionCulling to use
#   ZRASTER_BUILD_DIR=DIR     the zraster build (default build/, Release)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ZRASTER_BUILD_DIR:-$root/build}
source=${MSOC_SOURCE:-https://github.com/GameTechDev/MaskedOcclusionCulling}
work=$(mktemp -d "${TMPDIR:-/tmp}/msoc_compare.XXXXXX")
trap 'rm -rf "$work"' EXIT

git clone -q "$source" "$work/msoc"
echo "MSOC: $source at $(git -C "$work/msoc" rev-parse --short HEAD)"
# MSOC defines __cpuidex and _xgetbv for GCC itself, names GCC's own headers declare: renamed.
sed -i 's/\b__cpuidex\b/msoc_cpuidex/g; s/\b_xgetbv\b/msoc_xgetbv/g' \
    "$work"/msoc/*.cpp "$work"/msoc/*.h "$work"/msoc/*.inl
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log" 2>&1 ||
    { cat "$work/install.log"; exit 1; }

# MSOC's own flags (its CMakeLists.txt): SSE4.1 for the dispatcher, AVX2 + FMA for its AVX2
# path (its AVX-512 file compiled without AVX-512, as MSOC builds it by default).
cxx=${CXX:-g++}
common=(-O2 -DNDEBUG -std=c++17 -w)
"$cxx" "${common[@]}" -msse4.1 -c "$work/msoc/MaskedOcclusionCulling.cpp" -o "$work/moc.o"
"$cxx" "${common[@]}" -mavx2 -mfma -msse4.1 -c "$work/msoc/MaskedOcclusionCullingAVX2.cpp" \
    -o "$work/moc_avx2.o"
"$cxx" "${common[@]}" -mavx2 -mfma -msse4.1 -c "$work/msoc/MaskedOcclusionCullingAVX512.cpp" \
    -o "$work/moc_avx512.o"
# The comparison: zraster through pkg-config, as another project builds against it.
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig:$work/prefix/lib/x86_64-linux-gnu/pkgconfig:${PKG_CONFIG_PATH:-}"
read -r -a zraster_flags <<<"$(pkg-config --cflags --libs zraster)"
"$cxx" -O2 -DNDEBUG -std=c++20 -I"$work/msoc" -I"$root/bench" "$root/bench/msoc_compare.cpp" \
    "$work/moc.o" "$work/moc_avx2.o" "$work/moc_avx512.o" "${zraster_flags[@]}" -lhwy \
    -o "$work/msoc_compare"
"$work/msoc_compare" "${1:-15}"
