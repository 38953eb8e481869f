#!/usr/bin/env bash
# The main job: set up, build, then the demo (scripts/demo.sh): every demo scene through every
# path, the images and the speed-against-error report under out/, in a few minutes.
# `./run.sh --full`: every variant timed to the CI standard, and every other demo run.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
exec scripts/demo.sh "$@"
