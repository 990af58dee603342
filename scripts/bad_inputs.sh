#!/usr/bin/env bash
# Feeds the built zraster one bad input of each kind and prints a Markdown table: the input, the
# command, the exit status, the message on stderr (the actual text) and whether anything was left
# at the output path (it must be nothing). RELIABILITY.md holds its output.
#
#   bash scripts/bad_inputs.sh            (uses $ZRASTER_BIN, default build/zraster; builds it if
#                                          missing)
# Exits non-zero if a failing run exited other than 2, printed other than one line, or left a
# file behind.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
zraster=${ZRASTER_BIN:-$root/build/zraster}
[ -x "$zraster" ] || bash "$root/scripts/build.sh" >/dev/null
shared=$root/../shared/data/meshes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# Fixture files, each a few bytes.
tri='v 0 0 0\nv 1 0 0\nv 0 1 0\n'
printf "${tri}f 1 2 7\n" >index.obj
printf 'v 0 0 0\nv 1 0 0\nv nan 0 0\nf 1 2 3\n' >nan.obj
printf 'v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n' >inf.obj
printf "${tri}l 1 2\np 3\n" >lines.obj
printf "$tri" >vertices.obj
printf "mtllib nowhere.mtl\n${tri}usemtl m\nf 1 2 3\n" >nomtl.obj
: >empty.obj
mkdir folder.obj outdir.png
head -c 4096 /dev/urandom >garbage.xyzzy
ply_head='ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
printf "${ply_head}element face 1099511627776\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" >faces2e40.ply
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 300000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n0123456789ab' >vertices3e8.ply
printf "${ply_head}element face 1\nproperty list uchar int vertex_indices\n" >noend.ply
printf "${ply_head}element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n" >index.ply
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0' >truncated.ply
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2\n' >truncated-ascii.stl
{ head -c 80 /dev/zero; printf '\x02\0\0\0'; head -c 60 /dev/zero; } >truncated-binary.stl
{ head -c 80 /dev/zero; printf '\xff\xff\xff\xff'; head -c 50 /dev/zero; } >facets2e32.stl
printf 'OFF\n3 1099511627776 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >faces2e40.off
printf 'OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >short.off
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\nx\n' >zeroface.off
printf 'OFF4294967295\n3 2 0\n0 0 0\n' >glued.off
printf '{"asset":{"version":"2.0"},"meshes":[{"primitives":[' >broken.gltf
b64='data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA'
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":1099511627776,"type":"VEC3"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' "$b64" >count2e40.gltf
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"missing.bin"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' >nobuffer.gltf
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"images":[{"uri":"missing.png"}],"textures":[{"source":0}],"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' "$b64" >notexture.gltf
printf 'glTF\x02\0\0\0\xff' >truncated.glb
printf 'MM\x10\0\0\0\x02\0\x0a\0' >truncated.3ds
# External references that leave the model's folder, a FIFO as a buffer, a node graph whose
# shared children place 10^10 meshes, and a cycle of nodes.
mkdir -p model
printf '\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0' >secret.bin
buffer_gltf() {
    printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' "$1"
}
buffer_gltf ../secret.bin >model/outside.gltf
ln -s ../secret.bin model/link.bin
buffer_gltf link.bin >model/symlink.gltf
mkfifo model/fifo.bin
# 400 random triangles as big as the scene (they split without end) and one at 3e38.
awk 'BEGIN { srand(7); print "ply\nformat ascii 1.0\nelement vertex 1200\nproperty float x";
             print "property float y\nproperty float z\nelement face 400";
             print "property list uchar int vertex_indices\nend_header";
             for (i = 0; i < 1200; ++i) print 2 * rand() - 1, 2 * rand() - 1, 2 * rand() - 1;
             for (i = 0; i < 400; ++i) print 3, 3 * i, 3 * i + 1, 3 * i + 2 }' >soup.ply
printf "${ply_head}element face 1\nproperty list uchar int vertex_indices\nend_header\n3e38 0 0\n0 3e38 0\n0 0 3e38\n3 0 1 2\n" >far.ply
buffer_gltf fifo.bin >model/fifo.gltf
printf 'mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >model/outside-mtl.obj
printf 'newmtl m\nKd 1 0 0\n' >outside.mtl
shared_nodes='{"mesh":0}'
for level in 1 2 3 4 5 6 7 8 9 10; do
    shared_nodes+=",{\"children\":[$(printf "$((level - 1)),%.0s" 1 2 3 4 5 6 7 8 9)$((level - 1))]}"
done
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[%s],"scenes":[{"nodes":[10]}],"scene":0}' "$b64" "$shared_nodes" >shared-nodes.gltf
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0,"children":[1]},{"children":[0]}],"scenes":[{"nodes":[0]}],"scene":0}' "$b64" >cycle.gltf
if [ -f "$shared/gltf/BoxWithInfinites.glb" ]; then
    cp "$shared/gltf/BoxWithInfinites.glb" infinites.glb
fi
# Cells files (docs/portals.md): two rooms of one unit along x with a doorway, each variant
# breaking one rule. cells_file NAME PORTAL_CELL PORTAL_CORNERS [EXTRA_INSTANCE] [FLOOR_FILE]
mkdir -p cells
printf 'v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n' >cells/floor.obj
printf 'v 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n' >floor-outside.obj
door='[1, 0, 0.3], [1, 0, 0.7], [1, 0.8, 0.7], [1, 0.8, 0.3]'
cells_file() {
    printf '{"zraster_cells": 1, "meshes": {"floor": "%s"},
 "instances": [{"name": "floor_a", "mesh": "floor"},
               {"name": "floor_b", "mesh": "floor", "translate": [1, 0, 0]}%s],
 "cells": [{"name": "a", "box": [[0, 0, 0], [1, 1, 1]], "instances": ["floor_a", "floor_b"]},
           {"name": "b", "box": [[1, 0, 0], [2, 1, 1]], "instances": ["floor_a", "floor_b"]}],
 "portals": [{"cells": ["a", "%s"], "corners": [%s]}]}\n' "${5:-floor.obj}" "${4:-}" "$2" "$3" \
        >"cells/$1.cells.json"
}
cells_file two b "$door"
cells_file missing-cell kitchn "$door"
cells_file not-planar b '[1, 0, 0.3], [1, 0, 0.7], [1.02, 0.8, 0.7], [1, 0.8, 0.3]'
cells_file not-convex b '[1, 0, 0.3], [1, 0, 0.7], [1, 0.2, 0.5], [1, 0.8, 0.7], [1, 0.8, 0.3]'
cells_file no-cell b "$door" ', {"name": "lamp", "mesh": "floor", "translate": [5, 5, 5]}'
cells_file outside b "$door" "" ../floor-outside.obj
cells_file nested b "$door" "" two.cells.json
sed 's/"zraster_cells": 1/"zraster_cells": 2/' cells/two.cells.json >cells/version.cells.json
head -c 120 cells/two.cells.json >cells/broken.cells.json
printf '{"zraster_pvs": 1, "sets": [{"cell": "a", "visible": [0, 1]}, {"cell": "b", "visible": [0, 1]}]}\n' >two.pvs.json
printf '{"zraster_pvs": 1, "sets": [{"cell": "a", "visible": [0, 7]}, {"cell": "b", "visible": [1]}]}\n' >range.pvs.json

# Malformed files of each format Assimp reads (what used to reach the user as Assimp's
# internals), references that are loops, FIFOs or directories, numbers out of range in files.
head -c 100 /dev/urandom >random.stl
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid x\n' >twovertex.stl
printf 'solid\n' >emptysolid.stl
head -c 84 /dev/zero >zerofacets.stl
printf '[1, 2, 3]' >array.gltf
printf '{"nodes": []}' >noasset.gltf
printf '{"asset": {"version": "3.0"}}' >version3.gltf
head -c 300 /dev/urandom | tr -d 'g' >random.glb
printf 'glTF\x02\0\0\0\x20\0\0\0\x0c\0\0\0BIN\0\0\0\0\0\0\0\0\0\0\0\0\0' >binfirst.glb
printf 'glTF\x02\0\0\0\x1f\0\0\0\x0b\0\0\0JSON{"asset":[ ' >badjson.glb
printf 'this is text, not a 3DS file at all' >text.3ds
printf 'MM\xe8\x03\0\0\x3d\x3d\x10\0\0\0\0\0\0\0\0\0\0\0\0\0' >pastend.3ds
printf 'MM\x16\0\0\0\x3d\x3d\x02\0\0\0\0\0\0\0\0\0\0\0\0\0' >tinychunk.3ds
printf "${tri}f 1 2 3\nf 1\n" >point.obj
head -c 300 /dev/urandom | tr -d 'pP' >random.ply
head -c 300 /dev/urandom | tr -d 'oO' >random.off
head -c 300 /dev/urandom | tr -d '<' >random.dae
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >tri.off
ln -s loop-b model/loop-a
ln -s loop-a model/loop-b
mkfifo model/fifo.png
printf 'newmtl m\nKd 1 1 1\nmap_Kd loop-a\n' >model/loop.mtl
printf "mtllib loop.mtl\n${tri}vt 0 0\nusemtl m\nf 1/1 2/1 3/1\n" >model/loop-texture.obj
printf 'newmtl m\nKd 1 1 1\nmap_Kd fifo.png\n' >model/fifo.mtl
printf "mtllib fifo.mtl\n${tri}vt 0 0\nusemtl m\nf 1/1 2/1 3/1\n" >model/fifo-texture.obj
printf "mtllib fifo.png\n${tri}f 1 2 3\n" >model/fifo-mtllib.obj
buffer_gltf loop-a >model/loop.gltf
printf 'newmtl m\nKd 1 1 1\nd 5\nNs 5000\n' >numbers.mtl
printf "mtllib numbers.mtl\n${tri}usemtl m\nf 1 2 3\n" >numbers.obj
printf '[{"orbit": [0, 95, 1]}]' >elevation.views.json
printf '[{"eye": [1e39, 0, 0], "target": [0, 0, 0]}]' >eye.views.json
printf '[{"eye": [3, 3, 3], "target": [0, 0, 0], "fovy": 0}]' >fovy.views.json
printf "${ply_head}element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n" >two.ply
# Indices past their values, facets of four vertices, glTF 1.0, bytes Assimp reads as nodes only,
# viewer scripts and material values out of range.
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n' >index.off
printf 'COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n3 0 1 -1\n' >negative.off
# One triangle (0,0,0) (1,0,0) (0,1,0) whose face names vertices 0, 1, 9.
printf '\x4d\x4d\x6c\0\0\0\x02\0\x0a\0\0\0\x03\0\0\0\x3d\x3d\x5c\0\0\0\x3e\x3d\x0a\0\0\0\x03\0\0\0\0\x40\x4c\0\0\0tri\0\0\x41\x42\0\0\0\x10\x41\x2c\0\0\0\x03\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\x20\x41\x10\0\0\0\x01\0\0\0\x01\0\x09\0\0\0' >index.3ds
printf 'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 5 5 5\nendloop\nendfacet\nendsolid x\n' >fourvertex.stl
printf "${tri}vt 0 0\nf 1/99/1 2/1/1 3/1/1\nvn 0 0 1\n" >uvindex.obj
printf "${tri}vn 0 0 1\nf 1//1 2//1 3//-2\n" >normalindex.obj
printf "${tri}v 0.5 -1 0\nv 1 1 0\nvt 0 0\nf 1/1 4/1 2/9 5/1 3/1\n" >pentagon.obj
printf 'glTF\x01\0\0\0\x34\0\0\0\x20\0\0\0\0\0\0\0{"asset": {"version": "1.0"}}   ' >version1.glb
printf '{"asset": {"version": "1.0"}, "meshes": {}}' >version1.gltf
head -c 4096 /dev/urandom >random.ase
printf '0 key v\n1 wheel 1e300\n' >wheel.script
printf '0 drag left 20 0\n5000000000 quit\n' >frame.script
printf 'newmtl m\nKd 2 -1 nan\nNs -5\nd nan\n' >colors.mtl
printf "mtllib colors.mtl\n${tri}usemtl m\nf 1 2 3\n" >colors.obj
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"materials":[{"name":"m","alphaMode":"MASK","alphaCutoff":7,"pbrMetallicRoughness":{"baseColorFactor":[2,0.5,-1,-0.5],"roughnessFactor":3}}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' "$b64" >factors.gltf
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty float red\nproperty float green\nproperty float blue\nproperty float alpha\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 2.5 0 0 1\n1 0 0 0 -1 0 1\n0 1 0 0 0 1 7\n3 0 1 2\n' >colors.ply
# Words that are not numbers (Assimp read their numeric prefix), faces past Assimp's corner
# limit, an index past 2^31, unusable normals, an accessor read by many primitives, glTF members
# of the wrong type, a version that is not 2.N, a field a cells file does not have.
printf 'v 1e5x 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >word.obj
printf "${tri}f 1x 2 3\n" >word-index.obj
printf "${tri}v 0.5 -1 0\nv 1 1 0\nf 1 4 2 5 3\nv 1.#INF 0 0\n" >word-pentagon.obj
printf 'newmtl m\nKd 0.5abc 0 0\n' >word.mtl
printf "mtllib word.mtl\n${tri}usemtl m\nf 1 2 3\n" >word-mtl.obj
{ printf "$tri"; printf 'f'; for k in $(seq 40000); do printf ' %d' $((k % 3 + 1)); done; echo; } >corners.obj
printf "${tri}f 1 2 2147483648\n" >index2e31.obj
printf "${tri}vn nan 0 0\nf 1//1 2//1 3//1\n" >normal-nan.obj
printf "${ply_head}element face 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n" >corners-negative.ply
{ printf "${ply_head}element face 1\nproperty list uint uint vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n40000"
  for k in $(seq 40000); do printf ' %d' $((k % 3)); done; echo; } >corners.ply
# A million vertices (all at the origin but the last two) and the indices of one triangle (the
# first vertex and the last two) after them.
mkdir -p million
{ head -c 11999976 /dev/zero; printf '\0\0\x80\x3f\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0'
  printf '\0\0\0\0\x3e\x42\x0f\0\x3f\x42\x0f\0'; } >million/v.bin
million_gltf() {  # PRIMITIVES NODES
    local primitives nodes
    primitives=$(printf '{"attributes":{"POSITION":0},"indices":1},%.0s' $(seq "$1"))
    nodes=$(printf '0,%.0s' $(seq "$2"))
    printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":12000012,"uri":"v.bin"}],"bufferViews":[{"buffer":0,"byteLength":12000000},{"buffer":0,"byteOffset":12000000,"byteLength":12}],"accessors":[{"bufferView":0,"componentType":5126,"count":1000000,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5125,"count":3,"type":"SCALAR"}],"meshes":[{"primitives":[%s]}],"nodes":[{"mesh":0},{"children":[%s]}],"scenes":[{"nodes":[1]}],"scene":0}' "${primitives%,}" "${nodes%,}"
}
million_gltf 300 1 >million/primitives300.gltf
million_gltf 1 100000 >million/placed100k.gltf
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"materials":[{"name":"m","alphaMode":7,"alphaCutoff":"x","doubleSided":1,"pbrMetallicRoughness":{"baseColorFactor":[1,0,0]}}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' "$b64" >types.gltf
printf '{"asset":{"version":"2.0abc"}}' >version2abc.gltf
sed 's/"translate": \[1, 0, 0\]/"translation": [1, 0, 0]/' cells/two.cells.json >cells/unknown-field.cells.json
# Outputs against the run's inputs, the file system's limits and special files: models named as
# their outputs would be, a FIFO at an output path, a command under a file size limit.
printf "${tri}f 1 2 3\n" >self.obj
for name in self.ply self.png self.json self.svg; do cp tri.off "$name"; done
mkfifo fifo.png fifo.svg
awk 'BEGIN { srand(7); print "ply\nformat ascii 1.0\nelement vertex 30000\nproperty float x";
             print "property float y\nproperty float z\nelement face 10000";
             print "property list uchar int vertex_indices\nend_header";
             for (i = 0; i < 30000; ++i) print 2 * rand() - 1, 2 * rand() - 1, 2 * rand() - 1;
             for (i = 0; i < 10000; ++i) print 3, 3 * i, 3 * i + 1, 3 * i + 2 }' >soup10k.ply
# A model's own texture (an output must not replace it), triangles without area, cameras that
# cannot be built.
"$zraster" render builtin:cube --size 4x4 -o self-texture.png >/dev/null 2>&1
printf 'newmtl m\nKd 1 1 1\nmap_Kd self-texture.png\n' >selftex.mtl
printf "mtllib selftex.mtl\n${tri}vt 0 0\nusemtl m\nf 1/1 2/1 3/1\n" >selftex.obj
printf "${tri}f 1 1 1\nf 2 2 2\nf 3 3 3\n" >degenerate.obj
printf '[{"eye": [1, 1, 1], "target": [1, 1, 1]}]' >same.views.json
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0,"cameras":[{"type":"perspective","perspective":{"yfov":0.5,"znear":-1,"zfar":-2}}]}' "$b64" >camera.gltf
ones="$(printf '1,%.0s' $(seq 399))1"
zeros="$(printf '0,%.0s' $(seq 399))0"
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"children":[%s]},{"mesh":0}],"scenes":[{"nodes":[%s]}],"scene":0}' "$b64" "$ones" "$zeros" >overdraw.gltf
printf '#!/usr/bin/env bash\nulimit -f 8\nexec "%s" "$@"\n' "$zraster" >file-size-limit.sh
chmod +x file-size-limit.sh

failures=0
echo "| # | Input | Command | Exit | Message (stderr) | Output left |"
echo "|---|---|---|---|---|---|"
n=0
# row DESCRIPTION ARGUMENTS...: runs `zraster ARGUMENTS` in the work directory; outputs go to
# out.png (or the path given). $expected_left: what a documented partial result leaves.
expected_left=
row() {
    local what=$1
    shift
    n=$((n + 1))
    rm -rf out.png out.jpg out.d depth.txt ./*.tmp-* 2>/dev/null || true
    local rc=0
    "${run_zraster:-$zraster}" "$@" >stdout.txt 2>stderr.txt </dev/null || rc=$?
    local left
    left=$(find . -maxdepth 2 \( -name 'out.*' -o -name '*.tmp-*' -o -name '.zraster-*' -o -name 'depth.txt' -o \
        -path './outdir.png/*' \) 2>/dev/null | sort | tr '\n' ' ')
    [ -z "$left" ] && left="none"
    [ "$rc" -eq 0 ] && left="$left(success)"
    local message
    # (| would end the cell; < would open an HTML tag in the rendered table.)
    message=$(sed -e 's/|/\\|/g' -e 's/</\&lt;/g' stderr.txt | tr '\n' ' ' | sed 's/ *$//')
    [ -z "$message" ] && message="(nothing)"
    local lines
    lines=$(wc -l <stderr.txt)
    local command="zraster $*"
    what=${what//</\&lt;}
    echo "| $n | $what | \`${command//|/\\|}\` | $rc | $message | $left |"
    if [ "$rc" -ne 0 ]; then
        if [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] ||
            { [ "$left" != "none" ] && [ "$left" != "$expected_left" ]; }; then
            failures=$((failures + 1))
        fi
    fi
}

row "missing file" render missing.obj -o out.png
row "a directory" render folder.obj -o out.png
row "not a regular file" render /dev/zero -o out.png
row "empty file" render empty.obj -o out.png
row "unknown extension, random bytes" render garbage.xyzzy -o out.png
row "OBJ face index past the vertices" render index.obj -o out.png
row "OBJ NaN coordinate" render nan.obj -o out.png
row "OBJ coordinate overflowing to infinity (1e999)" render inf.obj -o out.png
row "OBJ with only lines and points" render lines.obj -o out.png
row "OBJ with vertices only" render vertices.obj -o out.png
row "OBJ naming a missing material library (a warning)" render nomtl.obj -o out.png --size 8x8
rm -f out.png
row "PLY header claiming 2^40 faces" render faces2e40.ply -o out.png
row "binary PLY claiming 3e8 vertices in 12 bytes" render vertices3e8.ply -o out.png
row "PLY header without end_header" render noend.ply -o out.png
row "PLY face index past the vertices" render index.ply -o out.png
row "binary PLY body cut short" render truncated.ply -o out.png
row "ASCII STL cut inside a facet" render truncated-ascii.stl -o out.png
row "binary STL shorter than its facet count" render truncated-binary.stl -o out.png
row "binary STL claiming 2^32-1 facets" render facets2e32.stl -o out.png
row "OFF header claiming 2^40 faces" render faces2e40.off -o out.png
row "OFF body shorter than its header" render short.off -o out.png
row "OFF face records of 0 indices" render zeroface.off -o out.png
row "OFF count glued to the keyword (OFF4294967295)" render glued.off -o out.png
row "glTF with broken JSON" render broken.gltf -o out.png
row "glTF accessor claiming 2^40 elements" render count2e40.gltf -o out.png
row "glTF naming a missing buffer file" render nobuffer.gltf -o out.png
row "glTF naming a missing texture (a warning)" render notexture.gltf -o out.png --size 8x8
rm -f out.png
row "GLB cut after 9 bytes" render truncated.glb -o out.png
[ -f infinites.glb ] && row "glTF with infinite positions (BoxWithInfinites.glb)" render infinites.glb -o out.png
row "3DS cut inside its first chunk" render truncated.3ds -o out.png
row "image 10^6 x 10^6" render builtin:cube --size 1000000x1000000 -o out.png
row "image 16384 x 16384 (over 64 Mpx)" render builtin:cube --size 16384x16384 -o out.png
row "image over --max-pixels" render builtin:cube --size 100x100 --max-pixels 9999 -o out.png
row "image size 0x10" render builtin:cube --size 0x10 -o out.png
row "image size not WxH" render builtin:cube --size abc -o out.png
row "NaN camera position" render builtin:cube --eye nan,0,0 -o out.png
row "eye equal to target" render builtin:cube --eye 1,1,1 --target 1,1,1 -o out.png
row "up parallel to the view direction" render builtin:cube --eye 0,5,0 --target 0,0,0 --up 0,1,0 -o out.png
row "near beyond far" render builtin:cube --near 5 --far 1 -o out.png
row "field of view 180 degrees" render builtin:cube --fovy 180 -o out.png
row "negative thread count" render builtin:cube --threads -3 -o out.png
row "seven clip planes (six supported)" render builtin:cube --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 --clip-plane 1,0,0,0 -o out.png
row "background component over 255" render builtin:cube --background 300,0,0 -o out.png
row "unknown shading mode" render builtin:cube --shading toon -o out.png
row "output not .png" render builtin:cube -o out.jpg
row "output in a missing directory" render builtin:cube -o missing-dir/out.png
row "output path is a directory" render builtin:cube --size 8x8 -o outdir.png
row "output where writing fails (/proc)" render builtin:cube --size 8x8 -o /proc/out.png
row "depth output not .npy/.png" render builtin:cube --depth-out depth.txt -o out.png
row "procedural scene of 0 triangles" render sphere:0 -o out.png
row "procedural scene of 10^11 triangles" render sphere:99999999999 -o out.png
row "unknown builtin scene" render builtin:nothing -o out.png
row "unknown option" render builtin:cube --no-such-option -o out.png
row "unknown subcommand" frobnicate
row "bench with 0 frames" bench builtin:cube --frames 0
row "bench warm-up of 2^31 - 1 frames" bench builtin:cube --frames 1 --warmup 2147483647
row "glTF buffer outside the model's folder" render model/outside.gltf -o out.png
row "glTF buffer: a symbolic link out of the folder" render model/symlink.gltf -o out.png
row "glTF buffer that is a FIFO" render model/fifo.gltf -o out.png
row "glTF nodes sharing children: 10^10 placements" render shared-nodes.gltf -o out.png
row "glTF nodes in a cycle" render cycle.gltf -o out.png
row "two outputs naming one file" render builtin:cube --size 8x8 -o out.png --depth-out ./out.png
row "output name over the file system's limit" render builtin:cube --size 8x8 -o out.png --depth-out "$(printf 'n%.0s' $(seq 300)).npy"
row "clip plane with a zero normal" render builtin:cube --clip-plane 0,0,0,-1 -o out.png
row "--orbit together with --eye" render builtin:cube --orbit 30,20,3 --eye 1,2,3 -o out.png
row "BSP tree of 400 random intersecting triangles" render soup.ply --no-cull --visibility bsp -o out.png
row "painter's algorithm past --max-painter-comparisons" render soup.ply --no-cull --visibility painter --max-painter-comparisons 10000 -o out.png
row "Warnock past --max-warnock-classifications" render soup.ply --visibility warnock --max-warnock-classifications 5000 -o out.png
row "A-buffer past --max-abuffer-fragments" render soup.ply --visibility abuffer --max-abuffer-fragments 100 -o out.png
row "svg of 400 random intersecting triangles (BSP order)" svg soup.ply --no-cull -o out.svg
row "budget not a whole number" render soup.ply --visibility bsp --max-bsp-polygons 1e9 -o out.png
row "triangle at 3e38 (beyond a camera's range)" render far.ply -o out.png
row "eye at 1e39" render builtin:cube --eye 1e39,0,0 -o out.png
row "thread count 2^31 - 1 (clamped with a warning: renders)" render builtin:cube --size 8x8 --threads 2147483647 -o out.png
rm -f out.png
# cells_row DESCRIPTION FILE ELEMENT ARGUMENTS...: a row whose one-line message must also name
# the file and the JSON element.
cells_row() {
    local what=$1 file=$2 element=$3
    shift 3
    row "$what" "$@"
    if ! grep -qF "$file: $element" stderr.txt; then
        echo "(row $n: the message does not name '$file: $element')" >&2
        failures=$((failures + 1))
    fi
}
cells_row "cells file: malformed JSON" cells/broken.cells.json "malformed JSON" render cells/broken.cells.json -o out.png
cells_row "cells file: wrong version" cells/version.cells.json "zraster_cells" render cells/version.cells.json -o out.png
cells_row "cells file: a portal naming a missing cell" cells/missing-cell.cells.json "portals[0].cells[1]" render cells/missing-cell.cells.json -o out.png
cells_row "cells file: a portal not planar" cells/not-planar.cells.json "portals[0]" render cells/not-planar.cells.json -o out.png
cells_row "cells file: a portal not convex" cells/not-convex.cells.json "portals[0]" render cells/not-convex.cells.json -o out.png
cells_row "cells file: an instance in no cell" cells/no-cell.cells.json "instances[2]" render cells/no-cell.cells.json -o out.png
cells_row "cells file: a mesh file outside its folder" cells/outside.cells.json "meshes.floor" render cells/outside.cells.json -o out.png
cells_row "cells file naming another cells file" cells/nested.cells.json "meshes.floor" render cells/nested.cells.json -o out.png
cells_row "--pvs file for another scene" two.pvs.json "sets" render building:2x2 --pvs two.pvs.json -o out.png
cells_row "--pvs file with a cell index out of range" range.pvs.json "sets[0].visible" render cells/two.cells.json --pvs range.pvs.json -o out.png
# Malformed files: causes in the user's terms, Assimp's text at most as a trailing detail.
row "STL of 100 random bytes" render random.stl -o out.png
row "ASCII STL facet of two vertices" render twovertex.stl -o out.png
row "ASCII STL: 'solid' and nothing else" render emptysolid.stl -o out.png
row "binary STL of 0 facets" render zerofacets.stl -o out.png
row "glTF that is a JSON array" render array.gltf -o out.png
row "glTF without an asset" render noasset.gltf -o out.png
row "glTF of version 3.0" render version3.gltf -o out.png
row "GLB of random bytes" render random.glb -o out.png
row "GLB whose first chunk is not JSON" render binfirst.glb -o out.png
row "GLB whose JSON chunk is not valid JSON" render badjson.glb -o out.png
row "3DS of text" render text.3ds -o out.png
row "3DS chunk declaring bytes past the end" render pastend.3ds -o out.png
row "3DS chunk smaller than its header" render tinychunk.3ds -o out.png
row "OBJ face of one corner" render point.obj -o out.png
row "PLY of random bytes" render random.ply -o out.png
row "OFF of random bytes" render random.off -o out.png
row "COLLADA of random bytes" render random.dae -o out.png
# References that are not regular files: the cause, and the --allow-outside-references hint only
# for files outside the model's folder.
row "OBJ texture: a loop of symbolic links (a warning)" render model/loop-texture.obj --size 8x8 -o out.png
rm -f out.png
row "OBJ texture: a FIFO (a warning)" render model/fifo-texture.obj --size 8x8 -o out.png
rm -f out.png
row "OBJ material library: a FIFO (a warning)" render model/fifo-mtllib.obj --size 8x8 -o out.png
rm -f out.png
row "glTF buffer: a loop of symbolic links" render model/loop.gltf -o out.png
row "glTF buffer: a FIFO, outside references allowed" --allow-outside-references render model/fifo.gltf -o out.png
# Numbers out of range, in files and options.
row "MTL opacity 5 and shininess 5000 (warnings)" render numbers.obj --size 8x8 -o out.png
rm -f out.png
row "views file: orbit elevation 95 degrees" batch tri.off --views-json elevation.views.json --size 8x8 -o out.d
row "views file: eye at 1e39" batch tri.off --views-json eye.views.json --size 8x8 -o out.d
row "views file: field of view 0" batch tri.off --views-json fovy.views.json --size 8x8 -o out.d
row "orbit distance 10^30 scene radii" render builtin:cube --orbit 0,0,1e30 -o out.png
row "field of view 10^-9 degrees" render builtin:cube --fovy 1e-9 -o out.png
row "near plane 10^-30" render builtin:cube --near 1e-30 -o out.png
row "up vector of 10^-40" render builtin:cube --up 1e-40,0,0 -o out.png
row "clip plane of 10^31" render builtin:cube --clip-plane 1e31,0,0,0 -o out.png
row "point light at 10^39" render builtin:cube --point-light 1e39,0,0 -o out.png
row "focal length 10^12 pixels" render builtin:cube --intrinsics 1e12,1e12,4,4 --size 8x8 -o out.png
row "PLY past --max-triangles (refused in the worker)" render two.ply --max-triangles 1 -o out.png
row "glTF past --max-instances" render shared-nodes.gltf --max-instances 1000 -o out.png
# Indices, facets and versions Assimp would bend silently; nodes without meshes; viewer scripts;
# material values (warnings naming the value and what is used).
row "OFF face index past the vertices" render index.off -o out.png
row "COFF face index -1 (Assimp: vertex 0)" render negative.off -o out.png
row "3DS face index past the vertices (a warning)" render index.3ds --size 8x8 -o out.png
rm -f out.png
row "ASCII STL facet of four vertices" render fourvertex.stl -o out.png
row "OBJ texture coordinate index past the vt lines" render uvindex.obj -o out.png
row "OBJ negative normal index before the first vn" render normalindex.obj -o out.png
row "OBJ pentagon (read by Assimp) with a texture index past the vt lines" render pentagon.obj -o out.png
row "GLB version 1 (glTF 1.0)" render version1.glb -o out.png
row "glTF 1.0" render version1.gltf -o out.png
cp shared-nodes.gltf shared-nodes.json
row "glTF named .json, nodes sharing children: 10^10 placements" render shared-nodes.json -o out.png
row "4 KiB of random bytes named .ase (Assimp: nodes, no mesh)" render random.ase -o out.png
row "view script: wheel of 1e300 notches" view sphere:20 --script wheel.script
row "view script: frame 5 x 10^9" view sphere:20 --script frame.script
row "MTL base color 2,-1,NaN, shininess -5, opacity NaN (warnings)" render colors.obj --size 8x8 -o out.png
rm -f out.png
row "glTF baseColorFactor, alpha, roughness and alphaCutoff out of range (warnings)" render factors.gltf --size 8x8 -o out.png
rm -f out.png
row "PLY vertex colors 2.5, -1 and alpha 7 (a warning)" render colors.ply --size 8x8 -o out.png
rm -f out.png
row "OBJ coordinate 1e5x (not a number)" render word.obj -o out.png
row "OBJ face index 1x (not a number)" render word-index.obj -o out.png
row "OBJ read by Assimp (a pentagon) with a coordinate 1.#INF" render word-pentagon.obj -o out.png
row "MTL color 0.5abc (not a number)" render word-mtl.obj -o out.png
row "OBJ face of 40000 corners" render corners.obj -o out.png
row "OBJ face index 2^31" render index2e31.obj -o out.png
row "OBJ normal NaN (a warning: recomputed)" render normal-nan.obj --size 8x8 -o out.png
rm -f out.png
row "PLY face with a negative corner count" render corners-negative.ply -o out.png
row "PLY face of 40000 corners" render corners.ply -o out.png
row "glTF: a million-vertex accessor read by 300 primitives" render million/primitives300.gltf -o out.png
row "glTF: a million-vertex mesh of one triangle placed 10^5 times" render million/placed100k.gltf -o out.png
row "glTF material members of the wrong types (warnings)" render types.gltf --size 8x8 -o out.png
rm -f out.png
row "glTF version 2.0abc" render version2abc.gltf -o out.png
cells_row "cells file: a field it does not have (\"translation\")" cells/unknown-field.cells.json "instances[1]" render cells/unknown-field.cells.json -o out.png
long_name=$(printf 'n%.0s' $(seq 251))
row "svg output name over the file system's limit" svg builtin:cube --size 16x16 -o "${long_name}n.svg"
row "svg output name of 255 bytes (renders)" svg builtin:cube --size 16x16 -o "$long_name.svg"
row "bench --out name of 255 bytes (renders)" bench builtin:cube --size 16x16 --frames 1 --warmup 0 --out "$long_name.png"
rm -f "$long_name.svg" "$long_name.png"
# The type, size, time and (for a regular file) the checksum of FILE; reading a FIFO would block.
file_state() {
    ls -l --time-style=full-iso "$1"
    if [ -f "$1" ]; then cksum <"$1"; fi
}
# unchanged_row DESCRIPTION FILE ARGUMENTS...: a row that must leave FILE as it was.
unchanged_row() {
    local what=$1 file=$2
    shift 2
    local before
    before=$(file_state "$file")
    row "$what" "$@"
    if [ "$before" != "$(file_state "$file")" ]; then
        echo "(row $n: $file changed)" >&2
        failures=$((failures + 1))
    fi
}
unchanged_row "--points-out naming the model" self.ply render self.ply --size 8x8 -o out.png --points-out self.ply
unchanged_row "--camera-json naming the model" self.json render self.json --size 8x8 -o out.png --camera-json self.json
unchanged_row "-o naming the model (a model named .png)" self.png render self.png --size 8x8 -o self.png
unchanged_row "svg -o naming the model" self.svg svg self.svg --size 8x8 -o self.svg
unchanged_row "batch --log naming an input" self.obj batch self.obj -o out.d --size 8x8 --log self.obj
unchanged_row "-o naming the model's own texture" self-texture.png render selftex.obj --size 8x8 -o self-texture.png
row "OBJ whose every triangle has zero area" render degenerate.obj -o out.png
row "6 KB glTF drawing one screen-sized triangle 160,000 times" render overdraw.gltf -o out.png
row "--views-json camera whose eye is its target" batch tri.off -o out.d --size 8x8 --views-json same.views.json
unchanged_row "batch --log naming the model's own texture" self-texture.png batch selftex.obj -o out.d --size 8x8 --log self-texture.png
row "--threads 0x10 (whole numbers are decimal)" render builtin:cube --size 8x8 --threads 0x10 -o out.png
row "glTF camera (ignored by zraster) with znear -1" render camera.gltf -o out.png
row "--sensor-max-range below the default minimum" render builtin:cube -o out.png --z-out out.npy --sensor kinect --sensor-max-range 0.2
row "batch --log in a missing folder" batch tri.off -o out.d --size 8x8 --log nodir/l.jsonl
row "batch --log naming a folder" batch tri.off -o out.d --size 8x8 --log folder.obj
expected_left="./out.d "
row "batch --log that cannot be written (/dev/full: the inputs finished before stay)" batch tri.off -o out.d --size 8x8 --progress none --log /dev/full
expected_left=
row "explain past the BSP budget (10^4 random triangles)" explain bsp soup10k.ply -o out.ex/deeper
unchanged_row "bench --out naming a FIFO" fifo.png bench builtin:cube --size 16x16 --frames 1 --warmup 0 --out fifo.png
unchanged_row "svg -o naming a FIFO" fifo.svg svg builtin:cube --size 16x16 -o fifo.svg
run_zraster=./file-size-limit.sh
row "render under ulimit -f 8 (8 KiB)" render sphere:2000 --size 512x512 -o out.png
row "svg under ulimit -f 8 (8 KiB)" svg sphere:2000 --size 256x256 -o out.svg
run_zraster=
# The object-space algorithms' budgets: 1,600 coincident triangles (a glTF whose node places one
# triangle 40 times, placed 40 times), a frame past the A-buffer's default, a raised A-buffer
# budget under a 2 GiB address space, explain's folder after a refusal, and a convex mesh, whose
# BSP tree is a chain.
children=$(printf '1,%.0s' $(seq 39))1
roots=$(printf '0,%.0s' $(seq 39))0
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"children":[%s]},{"mesh":0}],"scenes":[{"nodes":[%s]}],"scene":0}' "$b64" "$children" "$roots" >coincident.gltf
printf '#!/usr/bin/env bash\nulimit -v 2097152\nexec "%s" "$@"\n' "$zraster" >address-space-limit.sh
chmod +x address-space-limit.sh
row "painter's algorithm: 1,600 coincident triangles past --max-projected-polygons" render coincident.gltf --size 64x64 --visibility painter --max-projected-polygons 1000 -o out.png
row "painter's algorithm: 1,600 coincident triangles past --max-painter-comparisons" render coincident.gltf --size 64x64 --visibility painter --max-painter-comparisons 100000 -o out.png
row "BSP drawing: 1,600 coincident triangles past --max-painted-fragments" render coincident.gltf --size 64x64 --visibility bsp --max-painted-fragments 100000 -o out.png
row "BSP input past --max-bsp-polygons (refused before the tree is made)" render soup.ply --no-cull --visibility bsp --max-bsp-polygons 100 -o out.png
row "A-buffer at 8192x8192 with 8x8 samples (past the default of 2^24 fragments)" render builtin:cube --size 8192x8192 --aa 8 --visibility abuffer -o out.png
run_zraster=./address-space-limit.sh
row "A-buffer budget raised past a 2 GiB address space (ulimit -v)" render soup.ply --size 4096x4096 --no-cull --aa 2 --visibility abuffer --max-abuffer-fragments 4000000000 -o out.png
run_zraster=
row "explain past the BSP budget into a new folder" explain bsp soup10k.ply -o out.ex
row "BSP tree of a convex 20,000-triangle sphere (a chain) past --max-bsp-classifications" render sphere:20000 --size 64x64 --visibility bsp --max-bsp-classifications 10000000 -o out.png
# The paths that rasterize every triangle whole, budgeted by the samples the triangles' bounding
# boxes cover (--max-covered-samples), on a 3 KB glTF placing one large triangle 50,000 times
# (within the bin budget: the z-buffer draws it), and transparent; explain's A-buffer on it; a BSP
# budget raised past a 2 GiB address space.
stack_children=$(printf '1,%.0s' $(seq 249))1
stack_roots=$(printf '0,%.0s' $(seq 199))0
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"%s"}],"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"children":[%s]},{"mesh":0}],"scenes":[{"nodes":[%s]}],"scene":0}' "$b64" "$stack_children" "$stack_roots" >stacked.gltf
row "--view overdraw of one large triangle placed 50,000 times" render stacked.gltf -o out.png --view overdraw
row "--no-depth-test, one large triangle placed 50,000 times" render stacked.gltf -o out.png --no-depth-test
row "--msaa --aa 8 at 256x256, one large triangle placed 50,000 times" render stacked.gltf --size 256x256 --aa 8 --msaa -o out.png
row "explain abuffer, one large triangle placed 50,000 times (past 2^24 fragments)" explain abuffer stacked.gltf --size 256x256 -o out.ex
sed 's/"meshes":\[{"primitives":\[{"attributes":{"POSITION":0}}\]}\]/"materials":[{"alphaMode":"BLEND","pbrMetallicRoughness":{"baseColorFactor":[1,0,0,0.5]}}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}]/' stacked.gltf >stacked-glass.gltf
row "one large transparent (BLEND) triangle placed 50,000 times" render stacked-glass.gltf --size 640x360 -o out.png
run_zraster=./address-space-limit.sh
row "BSP budget raised past a 2 GiB address space (ulimit -v)" render soup.ply --visibility bsp --max-bsp-polygons 9999999999999999999 -o out.png
run_zraster=
# What the loaders' last budgets and format checks refuse: the bytes a glTF's accessors decode to
# (a sparse accessor of 150 million vertices; one of a million read by 140 primitives, within the
# triangle budget's counts), polygons whose triangulation takes quadratic time, a glTF asking for
# a newer reader, a PLY whose magic only Assimp took for one (its header was not checked), a cells
# instance with a matrix and its parts, an MTL decal.
printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":16,"uri":"data:application/octet-stream;base64,AAAAAAAAgD8AAIA/AACAPw=="}],"bufferViews":[{"buffer":0,"byteLength":4},{"buffer":0,"byteOffset":4,"byteLength":12}],"accessors":[{"componentType":5126,"count":150000000,"type":"VEC3","min":[0,0,0],"max":[1,1,1],"sparse":{"count":1,"indices":{"bufferView":0,"componentType":5125},"values":{"bufferView":1}}}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' >sparse150m.gltf
million_gltf 140 1 >million/primitives140.gltf
awk 'BEGIN { for (k = 0; k < 32767; ++k) print "v", cos(k * 0.00019), sin(k * 0.00019), 0;
             printf "f"; for (k = 1; k <= 32767; ++k) printf " %d", k; print "" }' >fan32767.obj
awk 'BEGIN { print "ply\nformat ascii 1.0\nelement vertex 20000\nproperty float x\nproperty float y";
             print "property float z\nelement face 1\nproperty list ushort int vertex_indices\nend_header";
             for (k = 0; k < 20000; ++k) print cos(k * 0.0003), sin(k * 0.0003), 0;
             printf "20000"; for (k = 0; k < 20000; ++k) printf " %d", k; print "" }' >fan20000.ply
printf '{"asset":{"version":"2.0","minVersion":"3.0"}}' >minversion3.gltf
sed 's/"translate": \[1, 0, 0\]/"matrix": [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], "translate": [1, 0, 0]/' \
    cells/two.cells.json >cells/matrix-and-translate.cells.json
printf 'plyply\nformat ascii 1.0\nelement vertex 400000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n' >plyply.ply
printf 'newmtl m\nKd 0.5\ndecal m.png\n' >decal.mtl
printf "mtllib decal.mtl\n${tri}usemtl m\nf 1 2 3\n" >decal.obj
row "glTF: a 578-byte sparse accessor of 150 million vertices (past --max-geometry-memory)" render sparse150m.gltf -o out.png
row "glTF: a million-vertex accessor read by 140 primitives (within the triangle counts)" render million/primitives140.gltf -o out.png
row "OBJ face of 32767 corners (quadratic triangulation)" render fan32767.obj --max-triangles 100 -o out.png
row "PLY face of 20000 corners (quadratic triangulation)" render fan20000.ply -o out.png
row "PLY of two headers run together (\"plyply\": Assimp's magic) declaring 4e8 vertices" render plyply.ply -o out.png
row "glTF asset minVersion 3.0" render minversion3.gltf -o out.png
cells_row "cells file: an instance with both \"matrix\" and \"translate\"" cells/matrix-and-translate.cells.json "instances[1]" render cells/matrix-and-translate.cells.json -o out.png
row "MTL decal statement and a one-number Kd (warning; gray)" render decal.obj --size 8x8 -o out.png
rm -f out.png
# Settings that would change nothing in the frame the others ask for.
row "--no-depth-test with the A-buffer (changes nothing)" render builtin:cube --size 8x8 --visibility abuffer --no-depth-test -o out.png
row "--depth-format with painter's (changes nothing)" render builtin:cube --size 8x8 --visibility painter --depth-format d16 -o out.png
row "--edge-color without --wireframe or --hidden-line" render builtin:cube --size 8x8 --edge-color 255,0,0 -o out.png
row "--light-dir with --shading unlit" render builtin:cube --size 8x8 --shading unlit --light-dir 0,0,1 -o out.png
row "svg --edge-width without --edges" svg builtin:cube --size 8x8 --edge-width 2 -o out.svg
row "--reversed-z --depth-compare less (a warning: nothing passes)" render builtin:cube --size 8x8 --reversed-z --depth-compare less -o out.png
rm -f out.png
# explain's pictures past their budget (each frame is held until the folder is written): refused
# before the first frame, and no folder made.
row "explain zbuffer: eight frames of 8192x8192 (past --max-explain-pixels)" explain zbuffer sphere:2000 --size 8192x8192 -o out.d
row "explain hiz: its views at 8192x8192 (past --max-explain-pixels)" explain hiz city:2000 --size 8192x8192 -o out.d
rm -rf out.d
# A cells file as pvs's output, FIFOs nothing writes as --views-json and --list (opening them
# waited for ever), OBJ vertices of 5 numbers, glTF placements and accessors glTF 2.0 forbids.
unchanged_row "pvs -o naming its own cells file" cells/two.cells.json pvs cells/two.cells.json -o ./cells/two.cells.json
mkfifo views.fifo list.fifo
row "batch --views-json naming a FIFO nothing writes" batch tri.off -o out.d --size 8x8 --views-json views.fifo
row "batch --list naming a FIFO nothing writes" batch --list list.fifo -o out.d --size 8x8
printf "v 0 0 0 1 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" >fivenumbers.obj
row "OBJ vertex of 5 numbers" render fivenumbers.obj -o out.png
printf '{"asset":{"version":"2.0"},"nodes":[{"rotation":[0,0,10,0]}],"scenes":[{"nodes":[0]}]}' >rotation.gltf
row "glTF node rotation that is not a unit quaternion" render rotation.gltf -o out.png
printf '{"asset":{"version":"2.0"},"accessors":[{"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}' >zeros.gltf
row "glTF accessor of zeros (no bufferView)" render zeros.gltf -o out.png
printf "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 junk\n" >junk.off
row "OFF face with a word after its indices" render junk.off -o out.png
rm -rf out.d
# Frames past their memory: a mesh placed many times (the frame estimated before the camera fit
# copies it), and 30 levels of empty glTF nodes each holding the next twice (2^31 nodes the
# importer copies per path: 7.8 GB before it failed).
row "a frame past --max-frame-bytes (the estimate of its vertices, triangles and targets)" render sphere:2000 --size 64x64 --max-frame-bytes 100K -o out.png
python3 - <<'PY'
import json
nodes = [{"mesh": 0}] + [{"children": [level + 1, level + 1]} for level in range(1, 31)] + [{}]
document = json.load(open("zeros.gltf"))
document["nodes"], document["scenes"] = nodes, [{"nodes": [0, 1]}]
document["buffers"] = [{"byteLength": 36, "uri": "data:application/octet-stream;base64,"
                        "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]
document["bufferViews"] = [{"buffer": 0, "byteLength": 36}]
document["accessors"][0]["bufferView"] = 0
json.dump(document, open("nodes2e31.gltf", "w"))
PY
row "glTF of 30 levels of empty nodes sharing children (2^31 nodes in the importer)" render nodes2e31.gltf -o out.png
# What a small glTF expands into in the importer (issue 27), each refused by its estimate before
# the importer reads the file: JSON nested 200,000 deep (the importer's parser crashed), a
# buffer declaring 6 GiB of a sparse file (read whole: 6.3 GB), an animation of 10^8 sparse keys
# (7.5 GB), 2,000 joints placed 4,096 times (a bone per joint per placement: 7.8 GB), 200,000
# primitives each with its own material (3.09 GB); and a material number outside its glTF range
# (a warning).
python3 - <<'PY'
import json, struct
tri = struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0)
def base(uri="h27.bin", length=36):
    return {"asset": {"version": "2.0"}, "buffers": [{"uri": uri, "byteLength": length}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 0]}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0}
open("h27.bin", "wb").write(tri + struct.pack('<I', 0) + struct.pack('<16f', *([1.0] * 16))
                            + struct.pack('<12H', *([0, 1, 2, 3] * 3)) + struct.pack('<12f', *([0.25] * 12)))
open("deep.gltf", "w").write('{"asset":{"version":"2.0"},"extras":' + '[' * 200000 + ']' * 200000 + '}')
with open("sparse6g.bin", "wb") as f: f.write(tri); f.truncate(6 * 2**30)
json.dump(base("sparse6g.bin", 6 * 2**30), open("buffer6g.gltf", "w"))
d = base(length=104)
d["bufferViews"] += [{"buffer": 0, "byteOffset": 36, "byteLength": 4}, {"buffer": 0, "byteOffset": 40, "byteLength": 64}]
sparse = {"count": 1, "indices": {"bufferView": 1, "componentType": 5125}, "values": {"bufferView": 2}}
d["accessors"] += [{"componentType": 5126, "count": 10**8, "type": "SCALAR", "min": [0], "max": [1], "sparse": sparse},
                   {"componentType": 5126, "count": 10**8, "type": "VEC3", "sparse": sparse}]
d["animations"] = [{"samplers": [{"input": 1, "output": 2}], "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}]
json.dump(d, open("keys1e8.gltf", "w"))
d = base(length=104)
d["bufferViews"] += [{"buffer": 0, "byteOffset": 36, "byteLength": 4}, {"buffer": 0, "byteOffset": 40, "byteLength": 64}]
d["buffers"][0]["byteLength"] = 176
d["bufferViews"] += [{"buffer": 0, "byteOffset": 104, "byteLength": 24}, {"buffer": 0, "byteOffset": 128, "byteLength": 48}]
d["accessors"] += [{"bufferView": 3, "componentType": 5123, "count": 3, "type": "VEC4"},
                   {"bufferView": 4, "componentType": 5126, "count": 3, "type": "VEC4"},
                   {"componentType": 5126, "count": 2000, "type": "MAT4", "sparse": sparse}]
d["meshes"][0]["primitives"][0]["attributes"].update({"JOINTS_0": 1, "WEIGHTS_0": 2})
nodes = [{"children": [k + 1, k + 1]} for k in range(12)] + [{"mesh": 0, "skin": 0}]
joints = list(range(len(nodes), len(nodes) + 2000))
nodes += [{"name": "j%d" % j} for j in range(2000)]
d["nodes"], d["scenes"], d["skins"] = nodes, [{"nodes": [0] + joints}], [{"joints": joints, "inverseBindMatrices": 3}]
json.dump(d, open("bones8m.gltf", "w"))
d = base()
d["materials"] = [{} for _ in range(200000)]
d["meshes"][0]["primitives"] = [{"attributes": {"POSITION": 0}, "material": i} for i in range(200000)]
json.dump(d, open("materials200k.gltf", "w"))
d = base()
d["materials"] = [{"pbrMetallicRoughness": {"metallicFactor": -5}, "emissiveFactor": [-5, 0, 0]}]
d["meshes"][0]["primitives"][0]["material"] = 0
json.dump(d, open("metallic.gltf", "w"))
PY
row "glTF JSON nested 200,000 deep (the importer's parser crashed)" render deep.gltf -o out.png
row "glTF buffer declaring 6 GiB of a sparse file (read whole: 6.3 GB)" render buffer6g.gltf -o out.png
row "glTF animation of 10^8 sparse keys in 1 KB (7.5 GB)" render keys1e8.gltf -o out.png
row "glTF skin of 2,000 joints placed 4,096 times (a bone per joint per placement: 7.8 GB)" render bones8m.gltf -o out.png
row "glTF of 200,000 primitives each with its own material (3.09 GB)" render materials200k.gltf -o out.png
row "glTF metallicFactor -5 and emissiveFactor -5 (a warning)" render metallic.gltf -o out.png --size 8x8
rm -f sparse6g.bin
# Non-glTF expansion (issue 27, H18-H20, H3, H9, H15): counted before the importer reads them.
python3 - <<'PY'
depth = 30
node = lambda k: ('<node id="n%d"><instance_geometry url="#g"/></node>' % k if k == depth else
                  '<node id="n%d"><instance_node url="#n%d"/><node id="m%d"><translate>0.1 0 0</translate>'
                  '<instance_node url="#n%d"/></node></node>' % (k, k + 1, k, k + 1))
open("graph2e30.dae", "w").write(
    '<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">'
    '<library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" count="9">0 0 0 1 0 0 0 1 0'
    '</float_array><technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/>'
    '<param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>'
    '<vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="1">'
    '<input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry></library_geometries>'
    '<library_nodes>' + ''.join(node(k) for k in range(1, depth + 1)) + '</library_nodes><library_visual_scenes>'
    '<visual_scene id="s">' + node(0) + '</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/>'
    '</scene></COLLADA>')
open("m200k.mtl", "w").write("".join("newmtl m%d\nKd 1 0 0\n" % i for i in range(200000)))
open("mdef200k.obj", "w").write("mtllib m200k.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m0\nf 1 2 3\n")
open("loads100k.lws", "w").write("LWSC\n3\n\nFirstFrame 1\nLastFrame 1\n\n" +
                                 "".join("LoadObjectLayer 1 tri.obj\nPosition %d 0 0\n" % i for i in range(100000)))
PY
row "COLLADA of 30 levels of nodes placing the next twice (<instance_node>: 2^30 placements)" render graph2e30.dae -o out.png
row "OBJ whose material library defines 200,000 materials" render mdef200k.obj -o out.png
printf 'mtllib sparse.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >sparsemtl.obj
printf 'newmtl m\nKd 1 0 0\n' >sparse.mtl
truncate -s 20G sparse.mtl
row "OBJ whose material library is a 20 GiB (sparse) file" render sparsemtl.obj -o out.png
rm -f sparse.mtl
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >tri.obj
row "LightWave scene loading one object 100,000 times" render loads100k.lws -o out.png
mkdir -p lws.d
printf 'LWSC\n3\n\nFirstFrame 1\nLastFrame 1\n\nLoadObjectLayer 1 ../tri.obj\n' >lws.d/outside.lws
row "LightWave scene loading an object outside its folder" render lws.d/outside.lws -o out.png
printf 'newmtl m\nKd 1 1 1\nmap_Ka amb.png\n' >amb.mtl
printf 'mtllib amb.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >amb.obj
printf 'not an image zraster reads' >amb.png
row "-o over a texture the model's MTL names (map_Ka) that zraster does not read" render amb.obj -o amb.png
printf "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 300 0 0\n" >color300.off
row "OFF face color of 300 (colors are 0..255)" render color300.off -o out.png
rm -f out.png
# Settings that change nothing, found by the fourth hostile run: the depth test's flags with
# --no-depth-test or --wireframe, shading with --wireframe or a view without shading, an infinite
# far plane with --ortho, a sensor seed without noise; a 2D explain given a scene; a seed out of
# range; batch given a procedural scene; a model's numbers a reader took a prefix of.
row "--depth-format with --no-depth-test (changes nothing)" render builtin:cube --size 8x8 --no-depth-test --depth-format d16 -o out.png
row "--light-dir with --wireframe (changes nothing)" render builtin:cube --size 8x8 --wireframe --light-dir 0,0,1 -o out.png
row "--shading with --view depth (changes nothing)" render builtin:cube --size 8x8 --view depth --shading flat -o out.png
row "--ortho --infinite-far (changes nothing)" render builtin:cube --size 8x8 --ortho --infinite-far -o out.png
row "--sensor-seed without --sensor-noise" render builtin:cube --size 8x8 --z-out z.npy --sensor kinect --sensor-seed 3 -o out.png
row "explain of a 2D algorithm given a scene" explain cohen-sutherland builtin:cube -o out.d
row "building seed past 2^64 - 1" render building:2x2:18446744073709551616 -o out.png
row "batch given a procedural scene" batch builtin:cube -o out.d
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0x\n1 0 0\n0 1 0\n3 0 1 2\n' >hexword.ply
row "ASCII PLY coordinate '0x' (Assimp read 0)" render hexword.ply -o out.png
printf 'newmtl m\nKd 1 0 0\nillum 4294967296\n' >illum.mtl
printf "mtllib illum.mtl\n${tri}usemtl m\nf 1 2 3\n" >illum.obj
row "MTL illum 4294967296 (Assimp wrapped it)" render illum.obj -o out.png
# Formats no check of ours counts before reading, found by the fifth hostile run: the importer's
# memory and time follow the file and the budgets.
printf 'tess 10\nf 1 0 0 0 0 0 0 0 0\ns 0 0 0 1\n' >tess10.nff
row "38-byte NFF whose sphere Assimp tessellates 10 times (6.4 GB in the importer)" render tess10.nff -o out.png
printf 'AC3Db\nMATERIAL "m" rgb 1 1 1  amb 0.2 0.2 0.2  emis 0 0 0  spec 0 0 0  shi 10  trans 0\nOBJECT world\nkids 1\nOBJECT poly\nsubdiv 14\nnumvert 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nnumsurf 1\nSURF 0x10\nmat 0\nrefs 4\n0 0 0\n1 0 0\n2 0 0\n3 0 0\nkids 0\n' >subdiv14.ac
row "AC3D quad subdivided 14 times (7.7 GB, past 60 s)" render subdiv14.ac -o out.png
printf 'LWSC\n3\n\nFirstFrame 1\nLastFrame 1\n\nLoadObjectLayer 1 loop.lws\n' >loop.lws
row "LightWave scene loading itself" render loop.lws -o out.png
buffer_gltf %2e%2e/secret.bin >model/escaped.gltf
row "glTF buffer URI %2e%2e/secret.bin (an escaped ../)" render model/escaped.gltf -o out.png
printf 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1,5 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n' >comma.stl
row "ASCII STL coordinate '1,5' (Assimp read 1.5)" render comma.stl -o out.png
printf 'ply\nformat binary_middle_endian 1.0\nelement vertex 3\nproperty float x\nend_header\n' >middle.ply
row "PLY format binary_middle_endian" render middle.ply -o out.png
# Numbers and nesting the importers used unchecked (crashes in process, values read wrongly).
dae_tri() { # $1: float array attributes, $2: asset elements
    printf '<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1"><asset>%s</asset><library_geometries><geometry id="g"><mesh><source id="p"><float_array id="pa" %s>0 0 0 1 0 0 0 1 0</float_array><technique_common><accessor source="#pa" count="3" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/></vertices><triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/><p>0 1 2</p></triangles></mesh></geometry></library_geometries><library_visual_scenes><visual_scene id="s"><node id="a"><instance_geometry url="#g"/></node></visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene></COLLADA>' "$2" "$1"
}
dae_tri 'count="-1"' '' >count.dae
row "COLLADA float_array count=\"-1\" (crashed the importer in process)" --load-in-process render count.dae -o out.png
dae_tri 'count="9"' '<unit meter="-1"/>' >unit.dae
row "COLLADA <unit meter=\"-1\"> (mirrored the model)" render unit.dae -o out.png
{ printf 'xof 0303txt 0032\nMesh m {\n3;\n0;0;0;,\n1;0;0;,\n0;1;0;;\n1;\n3;0,1,2;;\n}\n'; for i in $(seq 2002); do printf 'Frame f {\n{ m }\n}\n'; done; } >frames.x
row "X Frames holding data references, read as 1,001 levels of nesting (crashed in process)" --load-in-process render frames.x -o out.png
ln -sf loop-b.obj loop-a.obj; ln -sf loop-a.obj loop-b.obj
row "model that is a loop of symbolic links" render loop-a.obj -o out.png
# Formats the sixth hostile run reached: importers that crashed or read past their arrays, and
# budgets a small input got round.
python3 - <<'PY'
import zipfile
ct = ('<?xml version="1.0" encoding="UTF-8"?><Types xmlns="http://schemas.openxmlformats.org/'
      'package/2006/content-types"><Default Extension="rels" ContentType="application/'
      'vnd.openxmlformats-package.relationships+xml"/><Default Extension="model" ContentType='
      '"application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>')
rels = ('<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats'
        '.org/package/2006/relationships"><Relationship Target="/3D/3dmodel.model" Id="rel0" '
        'Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/></Relationships>')
mesh = ('<mesh><vertices><vertex x="0" y="0" z="0"/><vertex x="1" y="0" z="0"/><vertex x="0" '
        'y="1" z="0"/></vertices><triangles><triangle v1="0" v2="1" v3="2"/></triangles></mesh>')
model = ('<?xml version="1.0" encoding="UTF-8"?><model unit="millimeter" xmlns="http://schemas.'
         'microsoft.com/3dmanufacturing/core/2015/02"><resources><object id="1" type="model">' +
         mesh + '</object><object id="2" type="model"><components><component objectid="1"/>'
         '<component objectid="2"/></components></object></resources><build><item objectid="2"/>'
         '</build></model>')
with zipfile.ZipFile('self.3mf', 'w', zipfile.ZIP_DEFLATED) as z:
    z.writestr('[Content_Types].xml', ct)
    z.writestr('_rels/.rels', rels)
    z.writestr('3D/3dmodel.model', model)
PY
row "3MF component naming its own object (crashed the importer in process)" --load-in-process render self.3mf -o out.png
printf 'GeometryNode { ObjectRef {ref {$g}} }\nGeometryObject $g { Mesh { VertexArray (attrib = "position") { float[3] { {0, 0, 0}, {1, 0, 0}, {0, 1, 0} } } IndexArray { unsigned_int32[3] { {0, 1, 3} } } } }\n' >past.ogex
row "OpenGEX index equal to the vertex count (read from past the array)" render past.ogex -o out.png
printf 'MD5Version 10\ncommandline ""\nnumJoints 1\nnumMeshes 1\njoints {\n"root" -1 ( 0 0 0 ) ( 0 0 0 )\n}\nmesh {\nshader "x"\nnumverts 3\nvert 0 ( 0 0 ) 0 1\nvert 1 ( 0 0 ) 1 1\nvert 2 ( 0 0 ) 2 1\nnumtris 1\ntri 0 0 1 -1\nnumweights 3\nweight 0 0 1 ( 0 0 0 )\nweight 1 0 1 ( 1 0 0 )\nweight 2 0 1 ( 0 1 0 )\n}\n' >neg.md5mesh
row "MD5 triangle index -1 (an assertion in the importer)" render neg.md5mesh -o out.png
python3 -c "
n = 1001
open('chain.smd', 'w').write('version 1\nnodes\n' + ''.join('%d \"b%d\" %d\n' % (i, i, i - 1) for i in range(n)) + 'end\nskeleton\ntime 0\n0 0 0 0 0 0 0\nend\ntriangles\nmat\n0 0 0 0 0 0 1 0 0\n0 1 0 0 0 0 1 1 0\n0 0 1 0 0 0 1 0 1\nend\n')"
row "SMD of 1,001 bones in a chain (100,000 crashed the importer)" render chain.smd -o out.png
printf '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0,"extensions":{"KHR_texture_transform":{"scale":[1]}}}}}],"textures":[{"source":0}],"images":[{"uri":"t.png"}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA","byteLength":36}]}' >transform.gltf
row "glTF KHR_texture_transform scale of one number (the importer aborted)" render transform.gltf -o out.png
row "--max-load-seconds nan (accepted as the default)" render builtin:cube --max-load-seconds nan -o out.png
row "bench of 10^6 frames of 4096x4096 (ran for hours, printing nothing)" bench builtin:cube --size 4096x4096 --frames 1000000
rm -rf out.d out.png z.npy
echo
echo "$n inputs; $failures broke the contract (exit 2, one line, nothing left)."
[ "$failures" -eq 0 ]
