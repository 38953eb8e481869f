#!/usr/bin/env python3
"""How far each default variant's ratio to flat repeats over several bench runs (issue 11).

Usage: scripts/ratio_repeatability.py RUN_DIR RUN_DIR [RUN_DIR ...]
where each RUN_DIR holds the report.json of one `ltrender bench ... -o RUN_DIR` of the same
scenes. Prints, as markdown, every scene's default variant (each path's first variant) with its
ratio in every run, the median of the runs, the worst deviation from that median and the first
run's 95% interval; then each path's worst deviation over the scenes, and how often the first
run's intervals hold the other runs' ratios and how many rows lie within 5% of their median
(every variant). Only the standard library.
"""
import json
import statistics
import sys
from pathlib import Path


def main(run_dirs):
    if len(run_dirs) < 2:
        print("usage: ratio_repeatability.py RUN_DIR RUN_DIR [RUN_DIR ...]", file=sys.stderr)
        return 2
    runs = []
    for d in run_dirs:
        report = Path(d) / "report.json"
        try:
            runs.append({(r["scene"], r["path"], r["variant"]): r
                         for r in json.loads(report.read_text())["rows"]})
        except (OSError, ValueError, KeyError) as e:
            print(f"ratio_repeatability: error: {report}: {e}", file=sys.stderr)
            return 2
    defaults = {}  # (scene, path) -> its first variant, as the first run lists them
    for scene, path, variant in runs[0]:
        defaults.setdefault((scene, path), variant)
    header = "| scene | path | variant | " + " | ".join(f"run {i + 1}" for i in range(len(runs)))
    print(header + " | median | worst dev | interval (run 1) |")
    print("|---" * (6 + len(runs)) + "|")
    worst_by_path = {}
    for (scene, path), variant in defaults.items():
        if path == "flat":
            continue
        key = (scene, path, variant)
        if any(key not in run for run in runs):
            print(f"ratio_repeatability: error: {scene} {path} {variant} is not in every run",
                  file=sys.stderr)
            return 2
        ratios = [run[key]["ratio_to_flat"] for run in runs]
        median = statistics.median(ratios)
        worst = max(abs(r - median) / median for r in ratios) if median > 0 else 0.0
        worst_by_path[path] = max(worst_by_path.get(path, 0.0), worst)
        interval = runs[0][key]["ratio_interval"]
        cells = " | ".join(f"{r:.3f}" for r in ratios)
        print(f"| {scene} | {path} | {variant} | {cells} | {median:.3f} | {100 * worst:.1f}% | "
              f"{interval['low']:.2f}-{interval['high']:.2f} |")
    # Each path's interval half-widths in the first run, over every variant.
    half_widths = {}
    for row in runs[0].values():
        interval = row["ratio_interval"]
        if row["path"] != "flat" and row["ratio_to_flat"] > 0:
            half_widths.setdefault(row["path"], []).append(
                (interval["high"] - interval["low"]) / 2 / row["ratio_to_flat"])
    print("\n| path | worst deviation from the median | run 1's 95% interval, median / widest "
          "(every variant) |\n|---|---|---|")
    for path, worst in worst_by_path.items():
        widths = half_widths.get(path, [0.0])
        print(f"| {path} | {100 * worst:.1f}% | +-{100 * statistics.median(widths):.1f}% / "
              f"+-{100 * max(widths):.1f}% |")
    # How often the first run's interval holds the other runs' figures, over every variant:
    # what the interval says about another run (a row missing from a later run is skipped).
    held = total = 0
    for key, row in runs[0].items():
        if row["path"] == "flat":
            continue
        interval = row["ratio_interval"]
        for run in runs[1:]:
            if key in run:
                total += 1
                held += interval["low"] <= run[key]["ratio_to_flat"] <= interval["high"]
    print(f"\nrun 1's intervals hold the other runs' ratios in {held} of {total} cases")
    # Every variant, not only the defaults: how many lie within 5% of their median in every run.
    within = rows = 0
    for key, row in runs[0].items():
        if row["path"] == "flat" or any(key not in run for run in runs):
            continue
        ratios = [run[key]["ratio_to_flat"] for run in runs]
        median = statistics.median(ratios)
        rows += 1
        within += median > 0 and all(abs(r - median) <= 0.05 * median for r in ratios)
    print(f"every variant: {within} of {rows} rows within 5% of their median")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
