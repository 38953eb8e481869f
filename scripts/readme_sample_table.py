#!/usr/bin/env python3
"""The sample of the speed-against-error table in docs/measurements.md, from a bench's report.json.

Usage: scripts/readme_sample_table.py RUN_DIR
Prints the backlit sphere's rows docs/measurements.md shows (and the ortho twin's lobe=cube) as
markdown, the columns as docs/measurements.md's "A sample of the speed-against-error table" has.
Only the standard library.
"""
import json
import sys
from pathlib import Path

# (scene, path, variant, label): the rows docs/measurements.md samples, in its order.
ROWS = [
    ("backlit_sphere", "reference", "exact", "exact"),
    ("backlit_sphere", "glsl", "pow=exact", "pow=exact"),
    ("backlit_sphere", "glsl", "pow=exact:f32", "pow=exact:f32"),
    ("backlit_sphere", "arbfp", "pow=mul", "pow=mul (default)"),
    ("backlit_sphere", "arbfp", "pow=mul:vertex", "pow=mul:vertex"),
    ("backlit_sphere", "arbfp", "pow=lut:256:f16", "pow=lut:256:f16"),
    ("backlit_sphere", "arbfp", "pow=lut:256:u8", "pow=lut:256:u8"),
    ("backlit_sphere", "arbfp", "pow=sg", "pow=sg"),
    ("backlit_sphere", "arbfp", "pow=sg-simplified", "pow=sg-simplified"),
    ("backlit_sphere", "combiners", "t=vertex", "t=vertex (default)"),
    ("backlit_sphere", "combiners", "lobe=cube", "lobe=cube (perspective)"),
    ("backlit_sphere_ortho", "combiners", "lobe=cube", "lobe=cube"),
    ("backlit_sphere", "half", "pow=exact", "pow=exact"),
    ("backlit_sphere", "gx", "t=vertex", "t=vertex (default)"),
    ("backlit_sphere", "gx", "t=vertex:lut=16", "t=vertex:lut=16"),
]


def cost_cell(row):
    if row["cost"]:
        return row["cost"]
    mpix = row.get("stats", {}).get("shading_mpixels_per_s")
    if mpix:
        return f"CPU, {mpix:.1f} Mpixels/s"
    return ""


def work_cell(row):
    work = row.get("work", {})
    if "ops" in work:
        return f"{work['ops'] / 1e6:.2f}"
    return "- (" + work.get("not_counted", "").split(":")[0] + ": not counted)"


def main(argv):
    if len(argv) != 1:
        print("usage: readme_sample_table.py RUN_DIR", file=sys.stderr)
        return 2
    report = Path(argv[0]) / "report.json"
    try:
        rows = {(r["scene"], r["path"], r["variant"]): r
                for r in json.loads(report.read_text())["rows"]}
    except (OSError, ValueError, KeyError) as e:
        print(f"readme_sample_table: error: {report}: {e}", file=sys.stderr)
        return 2
    print("| scene | path | variant | ms | ratio to flat | 95% interval | max LSB | mean LSB "
          "| work (M ops) | cost |")
    print("|---" * 10 + "|")
    for scene, path, variant, label in ROWS:
        r = rows.get((scene, path, variant))
        if r is None:
            print(f"readme_sample_table: error: {report}: no row {scene} {path} {variant}",
                  file=sys.stderr)
            return 2
        iv = r["ratio_interval"]
        half = (iv["high"] - iv["low"]) / 2 / r["ratio_to_flat"] if r["ratio_to_flat"] else 0
        err = r.get("error", {})
        print(f"| {scene} | {path} | {label} | {r['ms_median_wide']:.2f} | "
              f"{r['ratio_to_flat']:.2f} | {iv['low']:.2f}-{iv['high']:.2f} "
              f"(+-{100 * half:.0f}%) | {err.get('max_lsb', 0):.2f} | "
              f"{err.get('mean_lsb', 0):.3f} | {work_cell(r)} | {cost_cell(r)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
