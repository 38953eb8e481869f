#!/usr/bin/env bash
# The one deliberate way to change goldens: re-render them (tests/golden_test.cpp with
# LT_UPDATE_GOLDENS=1), then review `git diff --stat tests/goldens` and the images before
# committing.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
LT_UPDATE_GOLDENS=1 build/ltrender_tests --gtest_filter='Renders/Golden.*'
git status --short tests/goldens
