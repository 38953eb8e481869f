#!/usr/bin/env bash
# The one deliberate way to change goldens: `ltrender regress --update` over the demo scenes at
# the goldens' size (the size tests/golden_test.cpp holds them at). It rewrites only the goldens
# that are missing or fail their tolerance, and lists them; review `git diff --stat tests/goldens`
# and the images (out/goldens-update/index.html flips each with the old one) before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# First the report against the goldens as they are, so the page shows what is about to change.
# `--golden-key none`: ltrender's own goldens are one image a case (tests/golden_test.cpp holds
# them), so an intended change rewrites it rather than adding a renderer's override.
build/ltrender regress scenes --goldens tests/goldens --width 320 --height 240 --quiet \
  --golden-key none -o out/goldens-update || true
build/ltrender regress scenes --goldens tests/goldens --width 320 --height 240 --update --quiet \
  --golden-key none
git status --short tests/goldens
