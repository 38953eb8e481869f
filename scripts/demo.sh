#!/usr/bin/env bash
# The demo of ./run.sh (after scripts/setup.sh built everything): render every demo scene in
# scenes/ through every path and variant, and write images plus the speed-against-error report
# under out/ (out/report.md is the table; out/index.html shows renders and heatmaps).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/ltrender
mkdir -p out
# Local thickness for the demo scenes that read "thickness": "vertex" (issue 3): the same bake
# anyone can rerun; it is deterministic for a seed, so the committed files come out unchanged.
scripts/bake_demo_meshes.sh "$bin"
"$bin" bench scenes/*.json -o out "$@"
echo
cat out/report.md
echo
echo "demo: images and heatmaps in out/images/, chart in out/chart.svg, contact sheet out/contact.png"
