#!/usr/bin/env bash
# Makes the README's gallery of `zraster explain` pictures: docs/images/explain/*.png, small.
# Usage: bash docs/images/make_explain_gallery.sh [path/to/zraster]   (default: build/zraster)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
zraster=${1:-$root/build/zraster}
out=$root/docs/images/explain
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"

# ALGORITHM, SCENE (empty for the 2D ones), the picture kept, its name in the gallery.
while read -r algorithm scene picture name; do
    [ "$scene" = "-" ] && scene=""
    # shellcheck disable=SC2086
    "$zraster" explain "$algorithm" $scene --size 320x240 -o "$work/$algorithm" >/dev/null
    cp "$work/$algorithm/$picture" "$out/$name"
done <<'LIST'
zbuffer builtin:default zbuffer-04.png zbuffer.png
painter builtin:default painter-05.png painter.png
bsp builtin:cube bsp-level-02.png bsp.png
warnock builtin:default warnock-level-04.png warnock.png
abuffer builtin:default abuffer-fragments.png abuffer.png
sutherland-hodgman - sutherland-hodgman-2d-2.png sutherland-hodgman.png
sutherland-hodgman - sutherland-hodgman-homogeneous.png sutherland-hodgman-homogeneous.png
cohen-sutherland - cohen-sutherland.png cohen-sutherland.png
liang-barsky - liang-barsky.png liang-barsky.png
bresenham - bresenham.png bresenham.png
frustum-culling builtin:default frustum-culling.png frustum-culling.png
backface-culling sphere:200 backface-culling.png backface-culling.png
occlusion-culling building:6x6 occlusion-culling.png occlusion-culling.png
LIST
ls "$out"
