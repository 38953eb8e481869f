#!/usr/bin/env bash
# Bakes the vertex-colour thickness of the demo meshes (inverted-normal AO, `ltrender bake`).
# The outputs are committed so the tests have them; rerunning rewrites them byte for byte.
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/ltrender}
# The blob: default max distance (a quarter of its bounding-box diagonal); thick parts keep 0.1.
"$bin" bake meshes/blob.ply -o meshes/blob_baked.ply --min 0.1 --max 1 --seed 1
# Slab and block with one absolute distance so their thickness is comparable (thin_vs_thick).
"$bin" bake meshes/slab.ply -o meshes/slab_baked.ply --max-distance 1 --min 0.1 --max 1 --seed 1
"$bin" bake meshes/block.ply -o meshes/block_baked.ply --max-distance 1 --min 0.1 --max 1 --seed 1
# The teapot (issue 13): the addendum's 50% grey floor (--min 0.5, "minimal translucency
# everywhere"), default max distance; the same bake as vertex colours and as a 1024x1024 UV map,
# so scenes/teapot_vertex.json against scenes/teapot.json is the error of replacing the map.
"$bin" bake meshes/teapot.ply -o meshes/teapot_baked.ply --rays 256 --min 0.5 --seed 1
"$bin" bake meshes/teapot.ply --texture 1024x1024 -o meshes/teapot_thickness.png --rays 256 \
  --min 0.5 --seed 1
