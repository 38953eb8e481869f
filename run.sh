#!/usr/bin/env bash
# The main job: set up, build, render every demo scene through every path, and write the
# images and the speed-against-error report under out/.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
exec scripts/demo.sh "$@"
