#!/usr/bin/env python3
"""How far each default variant's ratio to flat repeats over several bench runs (issue 11).

Usage: scripts/ratio_repeatability.py RUN_DIR RUN_DIR [RUN_DIR ...]
where each RUN_DIR holds the report.json of one `ltrender bench ... -o RUN_DIR` of the same
scenes. Prints, as markdown, every scene's default variant (each path's first variant) with its
ratio in every run, the median of the runs, the worst deviation from that median and the first
run's 95% interval; then each path's worst deviation over the scenes. Only the standard library.
"""
import json
import statistics
import sys
from pathlib import Path


def main(run_dirs):
    if len(run_dirs) < 2:
        sys.exit("usage: ratio_repeatability.py RUN_DIR RUN_DIR [RUN_DIR ...]")
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
    print("\n| path | worst deviation from the median |\n|---|---|")
    for path, worst in worst_by_path.items():
        print(f"| {path} | {100 * worst:.1f}% |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
