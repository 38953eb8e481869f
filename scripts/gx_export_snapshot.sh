#!/bin/sh
# Writes what the gx path generates for every scene under scenes/ into DIR: the exported C of
# every gx variant (or the refusal line when the scene refuses it) and `info --source`. Run it
# with the binary before and after a change to the gx generator, then `diff -r BEFORE AFTER`:
# a refactor that changes no program leaves the diff empty.
# Usage: scripts/gx_export_snapshot.sh LTRENDER DIR [SCENE...]   (from the repository root;
# without scenes: every .json, .glb and .gltf under scenes/)
set -u
if [ $# -lt 2 ]; then
  echo "usage: $0 LTRENDER DIR [SCENE...]" >&2
  exit 2
fi
bin=$1
dir=$2
shift 2
scenes="$*"
[ -n "$scenes" ] || scenes=$(find scenes -name '*.json' -o -name '*.glb' -o -name '*.gltf' | sort)
mkdir -p "$dir" || exit 2
variants="t=vertex t=vertex:lut=64 t=vertex:lut=16 t=vertex:colors=round
t=vertex:lights=round-each t=vertex:map=rgb565 t=texgen t=texgen:lut=64 lobe=xf-spec"
for scene in $scenes; do
  base=$(echo "$scene" | sed 's|^scenes/||; s|/|_|g; s|\.[a-z]*$||')
  "$bin" info "$scene" --source >"$dir/$base.info" 2>&1
  for v in $variants; do
    out="$dir/${base}_$(echo "$v" | tr '=:' '-_').c"
    # A refusal is part of the snapshot: its message is what the user sees instead.
    if ! "$bin" export gx "$scene" --variant "$v" -o "$out" 2>"$out.err"; then rm -f "$out"; fi
    [ -s "$out.err" ] || rm -f "$out.err"
  done
done
