#!/usr/bin/env bash
# Shared set-up for ./run.sh and ./test.sh: install the Debian packages that are missing, then
# configure and build (Release) into build/, or with --sanitize into build-sanitize/. Idempotent
# and quiet when there is nothing to do.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake pkg-config ninja-build   # Ninja: compiles a target's files while its
                                                 # libraries still build (docs/testing.md)
  libosmesa6-dev mesa-common-dev libgl-dev   # OSMesa offscreen context + legacy GL headers
  libglm-dev                                 # vector maths
  libopenmesh-dev                            # mesh I/O and processing
  libmeshoptimizer-dev                       # vertex-cache order and triangle strips (the Wii port)
  libopenimageio-dev                         # image I/O
  libpng-dev                                 # PNG without loading OpenImageIO (image/png_file.h)
  libopenexr-dev                             # EXR without loading OpenImageIO (image/exr_file.h)
  libimath-dev                               # half (binary16) for the fp16 path
  libhwy-dev                                 # Highway: the CPU paths' vector lanes
  libembree-dev                              # ray casting for the thickness baker
  nlohmann-json3-dev libcli11-dev            # scene files, command line
  libtinygltf-dev                            # glTF 2.0 scenes (.gltf, .glb)
  libgtest-dev libbenchmark-dev              # tests, micro-benchmarks
  fonts-dejavu-core                          # the contact sheet's labels (DejaVu Sans)
  chromium                                   # the report page's test in a real browser
  python3                                    # scripts/map_vs_vertex.py (the demo and its test)
  file                                       # cpack -G DEB's dependency scan (docs/install.md)
  dolphin-emu xvfb                           # the Wii judge: Dolphin's software renderer plays
                                             # our FIFO logs under a private X server
  gcc-powerpc-linux-gnu libc6-dev-powerpc-cross  # compiling gx exports (with libogc's headers)
  assimp-testmodels                          # real glTF assets in the tests
  libsquish-dev                              # a PC DXT1 encoder the CMPR encoder is measured against
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
fi

# `--sanitize`: the ASan + UBSan build of ./test.sh --sanitize, in its own directory so that the
# Release build (timings, the demo) is never instrumented.
build=build
config=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  build=build-sanitize
  config=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DLT_SANITIZE=ON)
fi
jobs=$(nproc)
if [ ! -f "$build/CMakeCache.txt" ]; then
  # Ninja, not Make: Make builds a target only once the targets it links are whole, so the test
  # binaries waited for the core and one core idled at the end of each (docs/testing.md).
  cmake -S . -B "$build" -G Ninja "${config[@]}" >/dev/null
fi
cmake --build "$build" -j "$jobs" 2>&1 | grep -v -E '^\[ *[0-9]+(%|/[0-9]+)\]|^-- ' || true
# The grep above hides progress lines only; a failed build must still stop us.
cmake --build "$build" -j "$jobs" >/dev/null
