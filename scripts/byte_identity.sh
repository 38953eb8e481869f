#!/usr/bin/env bash
# Proves a change to the gx path changed no output byte: renders every repository scene through
# every gx variant with two binaries (before and after the change) to PNG and EXR at 320x240, and
# compares the files byte for byte (an EXR's capDate header value aside: see same_file). A render
# that fails is recorded by its exit status, so a variant a scene cannot take must fail the same
# way with both binaries.
#
#   scripts/byte_identity.sh BASE_BIN NEW_BIN DIR
#
# DIR/base is rendered once and kept (delete it to render the baseline again), DIR/new every time.
# Exits 0 when every file is identical, 1 otherwise, and prints the count either way.
set -euo pipefail
if [ $# -ne 3 ]; then
  echo "usage: $0 BASE_BIN NEW_BIN DIR" >&2
  exit 2
fi
base_bin=$(realpath "$1")
new_bin=$(realpath "$2")
dir=$3
cd "$(dirname "$0")/.."

# The variants `ltrender render --help` lists for gx, plus the modifiers its grammar names but the
# list does not spell out (:base=tev, :map=rgb565), so every branch of the pixel stage is drawn.
variants=(
  t=vertex t=vertex:lut=64 t=vertex:lut=16 t=vertex:colors=round t=vertex:lights=round-each
  t=texgen t=vertex:out=xfb lobe=xf-spec t=texgen:view=object lobe=xf-spec:view=object
  t=texgen:view=object:base=tev t=vertex:map=rgb565
)
scenes=(scenes/*.json scenes/ortho/*.json scenes/maps/*.json scenes/hard/*.json scenes/gltf/*.glb)

# One line per render: "BIN OUTDIR SCENE VARIANT EXT"; xargs runs two at a time (the builds share
# the machine's cores).
jobs() {
  local bin=$1 out=$2
  for s in "${scenes[@]}"; do
    for v in "${variants[@]}"; do
      for ext in png exr; do echo "$bin $out $s $v $ext"; done
    done
  done
}
render_one() {
  local bin=$1 out=$2 scene=$3 variant=$4 ext=$5
  local name
  name=$(echo "${scene%.*}__${variant}" | sed 's|/|_|g; s|:|-|g; s|=|.|g')
  local status=0
  "$bin" render "$scene" --path gx --variant "$variant" --width 320 --height 240 \
    -o "$out/$name.$ext" >/dev/null 2>&1 || status=$?
  echo "$status" >"$out/$name.$ext.status"
}
export -f render_one

render_all() {
  local bin=$1 out=$2
  rm -rf "$out"
  mkdir -p "$out"
  jobs "$bin" "$out" | xargs -P 2 -L 1 bash -c 'render_one "$@"' _
}

if [ ! -d "$dir/base" ] || [ ! -f "$dir/base.done" ]; then
  render_all "$base_bin" "$dir/base"
  touch "$dir/base.done"
fi
render_all "$new_bin" "$dir/new"

# Two files the same byte for byte; for an EXR, except the value of its `capDate` header
# attribute, the time OpenImageIO wrote the file (the one thing two renders of the same frame
# differ in), which is compared blanked out.
same_file() {
  case "$1" in
    *.exr)
      python3 - "$1" "$2" <<'PY'
import struct, sys
def blanked(path):
    data = bytearray(open(path, 'rb').read())
    key = b'capDate\x00string\x00'
    at = data.find(key)
    if at >= 0:
        start = at + len(key) + 4
        size = struct.unpack_from('<i', data, at + len(key))[0]
        data[start:start + size] = bytes(size)
    return bytes(data)
sys.exit(0 if blanked(sys.argv[1]) == blanked(sys.argv[2]) else 1)
PY
      ;;
    *) cmp -s "$1" "$2" ;;
  esac
}

same=0
differ=0
while IFS= read -r f; do
  rel=${f#"$dir/base/"}
  if [ -f "$dir/new/$rel" ] && same_file "$f" "$dir/new/$rel"; then
    same=$((same + 1))
  else
    differ=$((differ + 1))
    echo "differs: $rel"
  fi
done < <(find "$dir/base" -type f | sort)
extra=$(comm -13 <(cd "$dir/base" && find . -type f | sort) <(cd "$dir/new" && find . -type f | sort) | wc -l)
images=$(find "$dir/base" -type f \( -name '*.png' -o -name '*.exr' \) | wc -l)
echo "byte_identity: $same identical, $differ differ, $extra only in new ($images images, the rest exit statuses)"
[ "$differ" -eq 0 ] && [ "$extra" -eq 0 ]
