#!/usr/bin/env bash
# Builds oneTBB's libtbb.so.12 with ThreadSanitizer into DIR/lib (for scripts/sanitize.sh tsan):
# the Debian source package of the installed libtbb12, fetched with apt-get source (a deb-src
# entry for Debian's archive is added if there is none), built with clang -fsanitize=thread.
# About 30 s of compiling on 2 cores.
#
#   bash scripts/tsan-tbb.sh DIR
set -euo pipefail
out=$1
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
if ! apt-get source --print-uris onetbb >/dev/null 2>&1; then
    $SUDO tee /etc/apt/sources.list.d/zraster-deb-src.sources >/dev/null <<'SOURCES'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb-src
URIs: http://deb.debian.org/debian-security
Suites: bookworm-security
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
    $SUDO apt-get update -qq
fi
read -r package version < <(dpkg-query -W -f='${source:Package} ${source:Version}\n' libtbb12)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get source -qq --download-only "$package=$version" >/dev/null 2>&1)
dpkg-source -x "$work/${package}_${version#*:}.dsc" "$work/src" >/dev/null 2>&1
CC=clang CXX=clang++ cmake -S "$work/src" -B "$work/build" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF \
    -DTBBMALLOC_BUILD=OFF -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only -fsanitize=thread" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" >/dev/null 2>&1
ninja -C "$work/build" -j 2 tbb >/dev/null
mkdir -p "$out/lib"
cp -P "$work"/build/*/libtbb.so* "$out/lib/"
echo "tsan-tbb: $package $version built with ThreadSanitizer in $out/lib"
