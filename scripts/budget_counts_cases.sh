#!/bin/bash
# Issue 24's count check, step 1: the inputs `budget` is run on before and after the one report
# (scripts/budget_counts_diff.py, step 2). Every program file in the repository, the GX program
# `export gx` writes and the ARB programs `info --source` prints for each demo scene, and every
# demo and budget scene through each path with a budget. Usage:
#   scripts/budget_counts_cases.sh BIN OUT_DIR   (writes OUT_DIR/cases.txt, one argument list a line)
set -e
BIN=$(realpath "$1"); OUT=$(realpath -m "$2"); REPO=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$OUT"; CASES=$OUT/cases.txt; : > "$CASES"
(cd "$REPO" && find . -path ./build -prune -o \( -name '*.fp' -o -name '*.vp' -o -name '*.arb' \
  -o -name '*.comb' -o -name '*.gx' -o -name '*.c' \) -print | sort) | while read -r f; do
  echo "$REPO/${f#./}" >> "$CASES"
done
for s in "$REPO"/scenes/*.json; do
  n=$(basename "$s" .json)
  "$BIN" export gx "$s" -o "$OUT/$n.c" > /dev/null 2>&1 && echo "$OUT/$n.c" >> "$CASES"
  "$BIN" info "$s" --source > "$OUT/$n.info" 2> /dev/null || true
  python3 - "$OUT/$n.info" "$OUT/$n" >> "$CASES" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
for i, m in enumerate(re.finditer(r"!!ARB([fv])p1\.0.*?\nEND\n?", text, re.S)):
    name = "%s_%d.%s" % (sys.argv[2], i, "fp" if m.group(1) == "f" else "vp")
    open(name, "w").write(m.group(0))
    print(name)
PY
done
for s in "$REPO"/scenes/*.json "$REPO"/scenes/budget/*.json; do
  for p in arbfp combiners gx; do echo "$s --path $p" >> "$CASES"; done
done
echo "$REPO/scenes/budget/twelve_mixed.json --path arbfp --profile ps_2_x" >> "$CASES"
wc -l < "$CASES"
