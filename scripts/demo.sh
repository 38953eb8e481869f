#!/usr/bin/env bash
# The demo of ./run.sh (after scripts/setup.sh built everything), written under out/
# (out/report.md is the table; out/index.html shows renders and heatmaps).
#   ./run.sh         the quick run, results in a few minutes: every demo scene through every path
#                    at its default variant and the variants the docs' story is about (bench
#                    --variants story: the LUT width, texgen, the XF lobe, ...), timed in one pass
#                    (bench --quick); the report page and contact sheet; the talk's figures; the
#                    Wii export.
#   ./run.sh --full  the complete run: the demo meshes re-baked, every variant timed to the CI
#                    standard (five rounds to a +-2% interval), then the tessellation,
#                    thickness-map, glTF and regression runs.
# Any other argument goes to every bench after the demo's own options (the last value of an
# option wins: `./run.sh --rounds 2`).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/ltrender
full=false
args=()
for a in "$@"; do
  if [ "$a" = "--full" ]; then full=true; else args+=("$a"); fi
done
steps=4
# The quick run's benches: one job a core this process may use (nproc counts those), up to 8
# (there are 8 demo scenes; a job is one scene at a time).
jobs=$(nproc)
[ "$jobs" -gt 8 ] && jobs=8
$full && steps=10
step_no=0
started=$SECONDS
# One line a step, on stderr with bench's own progress: where the run is, and since when.
step() {
  step_no=$((step_no + 1))
  echo "run.sh: step $step_no of $steps ($((SECONDS - started)) s in): $*" >&2
}
# The Wii port's vertices as a game stores them (s16 positions, s8 normals, RGB565 colours,
# s16 texture coordinates, an indexed display list: docs/porting-to-the-wii.md), a row beside
# gx's F32 immediate default in every bench of the demo scenes: report.md's "The console's bytes".
stored_list=gx:t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list
mkdir -p out out/regress
if $full; then
  # Local thickness for the demo scenes that read "thickness": "vertex" (issue 3): the same bake
  # anyone can rerun; it is deterministic for a seed, so the committed files come out unchanged
  # (the quick run uses them as committed).
  step "bake the demo meshes' thickness"
  scripts/bake_demo_meshes.sh "$bin"
  # Every demo scene through every path and variant (the orthographic one is where the combiners'
  # cube-map lobe is exact), timed to the CI standard.
  step "bench: every demo scene, path and variant, precise timing"
  "$bin" bench scenes/*.json scenes/ortho/*.json --precise --add-variant "$stored_list" -o out \
    "${args[@]}"
else
  # One job a core (bench --jobs, docs/bench.md "Jobs"): each scene's bench pinned to a core of
  # its own, the scenes shared out between them; one report.
  step "bench: every demo scene through every path, the story's variants, quick timing"
  "$bin" bench scenes/*.json scenes/ortho/*.json --variants story --quick --jobs "$jobs" \
    --add-variant "$stored_list" -o out "${args[@]}"
fi
# The talk's parameter figures rebuilt on the teapot (issue 13, scenes/figures/): one row per
# figure in out/figures/contact.png, its left and right scene side by side (fig14 ambient,
# fig15 scale, fig16 power, fig17 distortion, fig20/21 grey and red thickness, fig21m the same
# pair with the UV map, fig22 the coloured cubes alone). They are pictures, not timings: the
# fewest frames bench allows (and no run.sh arguments, whose --frames would clash).
step "the talk's figures on the teapot (reference renders)"
"$bin" bench scenes/figures/*.json --paths reference --frames 10 --warmup 0 --quick \
  --min-time 0 --max-time 0 --jobs "$jobs" -o out/figures --quiet
if $full; then
  # Per-vertex error against tessellation (issues 5 and 9): the backlit sphere at 42 to 10242
  # vertices, through the GL 1.3 combiners and the Wii's GX.
  # This bench and the others after the main one are about error: their timing stops at
  # --min-time (--max-time 0.5) instead of going on to a +-2% interval.
  step "bench: error against tessellation (combiners, gx)"
  "$bin" bench scenes/tessellation/*.json --paths combiners,gx --max-time 0.5 \
    -o out/tessellation --quiet "${args[@]}"
  # Replacing the thickness map by vertex colours, per tessellation (issue 13): UV spheres of 4 to
  # 64 rings, each baked as vertex colours and as a 512x256 map (256 rays), both rendered by the
  # reference and compared (docs/maps.md "Map or vertex colours?"; ~20 s).
  step "map or vertex colours, per tessellation"
  python3 scripts/map_vs_vertex.py --bin "$bin" --table out/tessellation/map_vs_vertex.md
  # Thickness maps (issue 13, scenes/maps/): the addendum's red teapot with its baked 1024x1024
  # map (its per-vertex twin, scenes/teapot_vertex.json, is in the main bench), the sphere with a
  # grey map, with an rgb map and ramp, and the 0/1 checker, through every path.
  step "bench: thickness maps"
  "$bin" bench scenes/maps/*.json --max-time 0.5 -o out/maps --quiet "${args[@]}"
  # A glTF asset as the whole scene (issue 14): the baked blob with KHR_materials_volume,
  # diffuse transmission and punctual lights (scripts/make_gltf_demo.py made it).
  step "bench: a glTF scene"
  "$bin" bench scenes/gltf/blob.glb --max-time 0.5 -o out/gltf --quiet "${args[@]}"
fi
# The Wii port of one demo scene, as the libogc C a porter pastes into the game (docs/
# porting-to-the-wii.md).
step "the Wii export of backlit_sphere, and its budget"
"$bin" export gx scenes/backlit_sphere.json -o out/backlit_sphere_gx.c
"$bin" budget out/backlit_sphere_gx.c
if $full; then
  # The demo scenes as a studio's regression suite would run them: against ltrender's own
  # goldens (320x240), with the JUnit XML a CI reads and a report page of its own.
  step "regress: the demo scenes against the goldens"
  "$bin" regress scenes --goldens tests/goldens --width 320 --height 240 --quiet \
    --junit out/regress/junit.xml -o out/regress
fi
step "the results"
echo
cat out/report.md
if $full; then
  echo
  echo "combiners and gx error against tessellation (out/tessellation/report.md):"
  grep -E '^\| backlit_sphere_s[0-9] \| (combiners|gx) \| t=vertex \|' \
    out/tessellation/report.md || true
fi
echo
echo "demo: images and heatmaps in out/images/, chart in out/chart.svg, contact sheet out/contact.png"
echo "demo: the talk's figures on the teapot: out/figures/contact.png"
echo "demo: the report page: $PWD/out/index.html"
if $full; then
  echo "demo: thickness maps: out/maps/report.md; regress against the goldens:" \
    "$PWD/out/regress/index.html"
else
  echo "demo: quick timing and the story's variants; ./run.sh --full times every variant to" \
    "the CI standard and adds the tessellation, thickness-map, glTF and regression runs"
fi
echo "demo: done in $((SECONDS - started)) s"
