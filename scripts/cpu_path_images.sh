#!/usr/bin/env bash
# Every repository scene through every variant of the paths that shade on the CPU (half,
# reference, gx), written as float EXR into one folder: run it before and after a change meant to
# make them faster, and `--compare` says whether any byte moved (issue 39: none may). An 8-bit
# path's EXR holds its bytes exactly (k/255 in half floats), so its PNG is covered too.
#
#   scripts/cpu_path_images.sh DIR [PATH...]     # default paths: half reference gx
#   scripts/cpu_path_images.sh before/ && <change, rebuild> && scripts/cpu_path_images.sh after/
#   scripts/cpu_path_images.sh --compare before/ after/
#
# Scenes: every scenes/**/*.json and .glb, at each scene's own size, plus the demo scenes
# (scenes/*.json) at the bench's 1280x720. A scene a variant refuses is listed as refused.
# Uses build/ltrender (LTRENDER=... for another binary).
set -euo pipefail

if [ "${1:-}" = --compare ]; then
  exec python3 - "${2:?usage: --compare BEFORE AFTER}" "${3:?usage: --compare BEFORE AFTER}" <<'PY'
import pathlib, re, sys
before, after = (pathlib.Path(p) for p in sys.argv[1:3])
def content(path):
    data = path.read_bytes()
    # capDate, type string, size 19, "YYYY:MM:DD HH:MM:SS" (OpenEXR's standard attribute).
    return re.sub(rb"(capDate\0string\0\x13\0\0\0).{19}", rb"\1", data, flags=re.S)
names = sorted({p.name for p in before.iterdir()} | {p.name for p in after.iterdir()})
differ = [n for n in names
          if not (before / n).exists() or not (after / n).exists()
          or content(before / n) != content(after / n)]
for n in differ:
    print("differs:", n)
print(f"{len(names) - len(differ)} of {len(names)} files identical")
sys.exit(1 if differ else 0)
PY
fi
cd "$(dirname "$0")/.."
out=${1:?usage: scripts/cpu_path_images.sh DIR [PATH...]}
shift
paths=("$@")
[ ${#paths[@]} -gt 0 ] || paths=(half reference gx)
bin=${LTRENDER:-build/ltrender}
mkdir -p "$out"

# The variants of one path, as `render --help` lists them under the path's line.
variants_of() {
  "$bin" render --help | awk -v p="  $1:" '
    index($0, p) == 1 { on = 1; next }
    on && /^      --variant / { print $2; next }
    on { exit }'
}

# The modifiers a path's grammar takes that its list does not spell out, so every branch of its
# pixel stage is drawn (gx: the TEV konst base of advise's search, the RGB565 thickness map).
extra_variants_of() {
  [ "$1" = gx ] && printf '%s\n' t=vertex:base=tev t=texgen:view=object:base=tev t=vertex:map=rgb565
  return 0
}

render_one() {  # scene path variant [width height]
  local scene=$1 path=$2 variant=$3 size=()
  local name
  name=$(echo "${scene#scenes/}" | tr '/' '_')
  name="${name%.*}__${path}__${variant//[:=]/_}"
  if [ $# -eq 5 ]; then
    size=(--width "$4" --height "$5")
    name="${name}__${4}x${5}"
  fi
  if ! "$bin" render "$scene" --path "$path" --variant "$variant" "${size[@]}" \
      -o "$out/$name.exr" 2> "$out/$name.err"; then
    echo "refused: $(tail -1 "$out/$name.err")" > "$out/$name.refused"
  fi
  rm -f "$out/$name.err"
}

mapfile -t scenes < <(find scenes -name '*.json' -o -name '*.glb' | sort)
for path in "${paths[@]}"; do
  mapfile -t variants < <(variants_of "$path"; extra_variants_of "$path")
  [ ${#variants[@]} -gt 0 ] || { echo "no variants listed for $path" >&2; exit 1; }
  for variant in "${variants[@]}"; do
    for scene in "${scenes[@]}"; do render_one "$scene" "$path" "$variant"; done
    for scene in scenes/*.json; do render_one "$scene" "$path" "$variant" 1280 720; done
  done
done
echo "$(find "$out" -name '*.exr' | wc -l) images, $(find "$out" -name '*.refused' | wc -l) refused, in $out"
