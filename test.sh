#!/usr/bin/env bash
# The whole test suite: the same set-up as ./run.sh, then every test through ctest.
# `./test.sh --sanitize [ctest args]`: the same suite built with AddressSanitizer and
# UndefinedBehaviorSanitizer in build-sanitize/ (slower; not part of .ci/run).
set -euo pipefail
cd "$(dirname "$0")"
if [ "${1:-}" = "--sanitize" ]; then
  shift
  # Every memory error, leak and UB report fails the test that causes it; leaks inside the
  # libraries (OpenMesh's log streams, OSMesa/LLVM) are suppressed by name in scripts/lsan.supp.
  # Set before the build: gtest_discover_tests runs the instrumented binary at build time, and
  # the cases that load scenes (bounds_test) meet OpenMesh's leak there too.
  export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
  export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp:print_suppressions=0}"
  export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
  scripts/setup.sh --sanitize
  cd build-sanitize
  exec ctest --output-on-failure -j "$(nproc)" "$@"
fi
scripts/setup.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
