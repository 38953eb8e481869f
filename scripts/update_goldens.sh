#!/usr/bin/env bash
# The one deliberate way to change goldens: `ltrender regress --update` over the demo scenes at
# the goldens' size (the size tests/golden_test.cpp holds them at). It rewrites only the goldens
# that are missing or fail their tolerance, and lists them; review `git diff --stat tests/goldens`
# and the images (out/goldens-update/index.html flips each with the old one) before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# First the report against the goldens as they are, so the page shows what is about to change.
build/ltrender regress scenes --goldens tests/goldens --width 320 --height 240 --quiet \
  -o out/goldens-update || true
build/ltrender regress scenes --goldens tests/goldens --width 320 --height 240 --update --quiet
git status --short tests/goldens
