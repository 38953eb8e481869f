#!/usr/bin/env bash
# The whole test suite: the same set-up as ./run.sh, then every test through ctest.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
