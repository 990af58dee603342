#!/usr/bin/env bash
# Builds oneTBB's libtbb.so.12 with ThreadSanitizer into DIR/lib (for scripts/sanitize.sh tsan):
# the Debian source package of the installed libtbb12, fetched with apt-get source, built with
# clang -fsanitize=thread. About 30 s of compiling on 2 cores (more on a busy machine).
#
# apt-get source needs deb-src entries, which Debian's images do not enable. If there are none,
# this adds a deb-src twin of every enabled Debian deb entry (same mirrors, suites, components
# and keys: /etc/apt/sources.list.d/zraster-deb-src.{sources,list}), or deb.debian.org's if it
# finds no Debian entry, and runs apt-get update once. If the installed version has left the
# archive (a newer point release replaced it), the archive's version of the same source package
# is used: same upstream release and soname, so the same ABI.
#
#   bash scripts/tsan-tbb.sh DIR
set -euo pipefail
out=$1
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
command -v dpkg-source >/dev/null || {
    $SUDO apt-get update -qq
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq dpkg-dev >/dev/null
}
read -r package version < <(dpkg-query -W -f='${source:Package} ${source:Version}\n' libtbb12)
if ! apt-get source --print-uris "$package" >/dev/null 2>&1; then
    added=""
    # deb822 files (Debian 12's default: /etc/apt/sources.list.d/debian.sources).
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] || continue
        case $f in */zraster-deb-src.sources) continue ;; esac
        grep -q "debian" "$f" || continue
        # Each stanza once more with Types: deb-src (comments and other fields kept).
        awk 'BEGIN { RS = ""; ORS = "\n\n" } /Types:[^\n]*deb([ \n]|$)/ && !/Enabled: *no/ {
                 gsub(/Types:[^\n]*/, "Types: deb-src"); print }' "$f" |
            $SUDO tee -a /etc/apt/sources.list.d/zraster-deb-src.sources >/dev/null
        added=yes
    done
    # One-line format.
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
        [ -f "$f" ] || continue
        case $f in */zraster-deb-src.list) continue ;; esac
        if grep -qE '^deb [^#]*debian' "$f"; then
            sed -nE 's/^deb ([^#]*debian.*)/deb-src \1/p' "$f" |
                $SUDO tee -a /etc/apt/sources.list.d/zraster-deb-src.list >/dev/null
            added=yes
        fi
    done
    if [ -z "$added" ]; then
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
    fi
    $SUDO apt-get update -qq
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! (cd "$work" && apt-get source -qq --download-only "$package=$version" >/dev/null 2>&1); then
    echo "tsan-tbb: $package $version is no longer in the archive; using its current version" >&2
    (cd "$work" && apt-get source -qq --download-only "$package" >/dev/null)
fi
dsc=$(ls "$work"/*.dsc | head -1)
dpkg-source -x "$dsc" "$work/src" >/dev/null 2>&1
CC=clang CXX=clang++ cmake -S "$work/src" -B "$work/build" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBB_STRICT=OFF \
    -DTBBMALLOC_BUILD=OFF -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only -fsanitize=thread" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" >/dev/null 2>&1
ninja -C "$work/build" -j "${ZRASTER_SANITIZE_JOBS:-2}" tbb >/dev/null
mkdir -p "$out/lib"
cp -P "$work"/build/*/libtbb.so* "$out/lib/"
echo "tsan-tbb: $(basename "$dsc" .dsc) built with ThreadSanitizer in $out/lib"
