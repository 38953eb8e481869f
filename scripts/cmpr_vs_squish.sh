#!/usr/bin/env bash
# The CMPR encoder against libsquish's DXT1, both decoded the console's way, on real textures:
# the glTF sample textures of the Debian package assimp-testmodels (each distinct file once) and
# the repository's demo maps. Prints the Markdown table docs/textures.md holds; exits 1 if our
# encoder's mean error is above squish's on any image.
#   scripts/cmpr_vs_squish.sh [BUILD_DIR]     (default build/; builds the cmpr_vs_squish target)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" -j2 --target cmpr_vs_squish >/dev/null
mapfile -t gltf < <(dpkg -L assimp-testmodels | grep -i -E '/glTF2?/.*\.(png|jpg)$' | sort |
  while read -r f; do echo "$(md5sum < "$f" | cut -c1-32) $f"; done | sort -u -k1,1 | cut -d' ' -f2- | sort)
"$build/cmpr_vs_squish" "${gltf[@]}" scenes/maps/*.png meshes/teapot_thickness.png
