#!/usr/bin/env bash
# The whole test suite: the same set-up as ./run.sh, then every test through ctest.
# `./test.sh --sanitize [ctest args]`: the same suite built with AddressSanitizer and
# UndefinedBehaviorSanitizer in build-sanitize/ (slower; not part of .ci/run).
set -euo pipefail
cd "$(dirname "$0")"
if [ "${1:-}" = "--sanitize" ]; then
  shift
  scripts/setup.sh --sanitize
  cd build-sanitize
  # Leaks are not checked: llvmpipe (OSMesa) and OpenImageIO keep caches that live until exit.
  # Every memory error and every UB report still fails the test that causes it.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=0:abort_on_error=0}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
  exec ctest --output-on-failure -j "$(nproc)" "$@"
fi
scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
