#!/usr/bin/env bash
# The demo of ./run.sh (after scripts/setup.sh built everything): render every demo scene in
# scenes/ through every path and variant, and write images plus the speed-against-error report
# under out/ (out/report.md is the table; out/index.html shows renders and heatmaps).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/ltrender
mkdir -p out out/regress
# Local thickness for the demo scenes that read "thickness": "vertex" (issue 3): the same bake
# anyone can rerun; it is deterministic for a seed, so the committed files come out unchanged.
scripts/bake_demo_meshes.sh "$bin"
# Every demo scene through every path and variant (the orthographic one is where the combiners'
# cube-map lobe is exact).
"$bin" bench scenes/*.json scenes/ortho/*.json -o out "$@"
# Per-vertex error against tessellation (issues 5 and 9): the backlit sphere at 42 to 10242
# vertices, through the GL 1.3 combiners and the Wii's GX.
# This bench and the others after the main one are about error: their timing stops at --min-time
# (--max-time 0.5) instead of going on to a +-2% interval.
"$bin" bench scenes/tessellation/*.json --paths combiners,gx --max-time 0.5 -o out/tessellation \
  --quiet "$@"
# Replacing the thickness map by vertex colours, per tessellation (issue 13): UV spheres of 4 to
# 64 rings, each baked as vertex colours and as a 512x256 map (256 rays), both rendered by the
# reference and compared (docs/maps.md "Map or vertex colours?"; ~20 s).
python3 scripts/map_vs_vertex.py --bin "$bin" --table out/tessellation/map_vs_vertex.md
# Thickness maps (issue 13, scenes/maps/): the addendum's red teapot with its baked 1024x1024
# map (its per-vertex twin, scenes/teapot_vertex.json, is in the main bench), the sphere with a
# grey map, with an rgb map and ramp, and the 0/1 checker, through every path.
"$bin" bench scenes/maps/*.json --max-time 0.5 -o out/maps --quiet "$@"
# The talk's parameter figures rebuilt on the teapot (issue 13, scenes/figures/): one labelled
# row per scene in out/figures/contact.png, each pair on adjacent rows (name order): fig14
# ambient, fig15 scale, fig16 power, fig17 distortion, fig20/21 grey and red thickness, fig21m
# the same pair with the UV map, fig22 the coloured cubes. They are pictures, not timings: the fewest frames bench allows (and no
# "$@", whose --frames would clash).
"$bin" bench scenes/figures/*.json --paths reference --frames 10 --warmup 0 --min-time 0 --max-time 0 \
  -o out/figures --quiet
# A glTF asset as the whole scene (issue 14): the baked blob with KHR_materials_volume,
# diffuse transmission and punctual lights (scripts/make_gltf_demo.py made it).
"$bin" bench scenes/gltf/blob.glb --max-time 0.5 -o out/gltf --quiet "$@"
echo
cat out/report.md
echo
echo "combiners and gx error against tessellation (out/tessellation/report.md):"
grep -E '^\| backlit_sphere_s[0-9] \| (combiners|gx) \| t=vertex \|' out/tessellation/report.md || true
# The Wii port of one demo scene, as the libogc C a porter pastes into the game (docs/
# porting-to-the-wii.md).
"$bin" export gx scenes/backlit_sphere.json -o out/backlit_sphere_gx.c
"$bin" budget out/backlit_sphere_gx.c
# The demo scenes as a studio's regression suite would run them: against ltrender's own goldens
# (320x240), with the JUnit XML a CI reads and a report page of its own.
"$bin" regress scenes --goldens tests/goldens --width 320 --height 240 --quiet \
  --junit out/regress/junit.xml -o out/regress
echo
echo "demo: images and heatmaps in out/images/, chart in out/chart.svg, contact sheet out/contact.png"
echo "demo: the talk's figures on the teapot: out/figures/contact.png; thickness maps: out/maps/report.md"
echo "demo: the report page: $PWD/out/index.html (regress against the goldens: $PWD/out/regress/index.html)"
