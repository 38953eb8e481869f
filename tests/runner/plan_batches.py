#!/usr/bin/env python3
"""Writes the ctest tests of one GoogleTest binary as batches (run by run_batch.py).

Run after the binary is linked (CMakeLists.txt, lt_test_binary): lists its cases with
--gtest_list_tests, applies tests/schedule.json's rules, and writes a file ctest includes with
one add_test per batch. A batch holds consecutive cases of one suite that share their rules, at
most `batch_size` of them (the schedule's, or a smaller one of a rule), split evenly; a case whose rule says `alone` is a batch of its own
and keeps its own name. A suite in one batch is named `Suite`, a suite in several
`Suite:2/13`, so `ctest -R '^Suite'` still picks a suite; one case is run with the binary's
--gtest_filter (CONTRIBUTING.md).
"""
import argparse
import json
import math
import re
import subprocess
import sys


def list_cases(binary):
    """Suite.Case names in the binary's order. Parameterised cases are listed as
    `  Case/param  # GetParam() = ...` and typed suites as `Suite/0.  # TypeParam = ...`."""
    out = subprocess.run([binary, "--gtest_list_tests"], check=True, capture_output=True,
                         text=True, timeout=60).stdout
    cases, suite = [], None
    for line in out.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            suite = line.split("#")[0].strip().rstrip(".")
        else:
            cases.append((suite, suite + "." + line.split("#")[0].strip()))
    return cases


def rules_for(name, rules):
    """Every rule that matches, merged: labels add up, the largest time limit and cost and the
    smallest batch win."""
    merged = {"labels": [], "alone": False}
    for rule in rules:
        if not re.search(rule["match"], name):
            continue
        for label in rule.get("labels", []):
            if label not in merged["labels"]:
                merged["labels"].append(label)
        merged["alone"] = merged["alone"] or rule.get("alone", False)
        for key in ("timeout", "cost"):
            if key in rule:
                merged[key] = max(merged.get(key, 0), rule[key])
        if "batch_size" in rule:
            merged["batch_size"] = min(merged.get("batch_size", rule["batch_size"]), rule["batch_size"])
        for key in ("fixtures_required", "environment"):
            if key in rule:
                merged[key] = rule[key]
    return merged


def group(cases, rules, batch_size):
    """[(suite, [names], rule)] runs of one suite and one rule, `alone` cases on their own."""
    runs = []
    for suite, name in cases:
        rule = rules_for(name, rules)
        last = runs[-1] if runs else None
        if rule["alone"] or not last or last[0] != suite or last[2] != rule or last[2]["alone"]:
            runs.append((suite, [name], rule))
        else:
            last[1].append(name)
    batches = []
    for suite, names, rule in runs:
        parts = math.ceil(len(names) / rule.get("batch_size", batch_size))
        size = math.ceil(len(names) / parts)
        for i in range(0, len(names), size):
            batches.append((suite, names[i:i + size], rule))
    return batches


def name_batches(batches):
    """Names as the module docstring says; a suite's batches are counted over the whole suite."""
    per_suite = {}
    for suite, names, rule in batches:
        if not rule["alone"]:
            per_suite[suite] = per_suite.get(suite, 0) + 1
    seen, named = {}, []
    for suite, names, rule in batches:
        if rule["alone"]:
            named.append((names[0], names, rule))
            continue
        seen[suite] = seen.get(suite, 0) + 1
        total = per_suite[suite]
        named.append((suite if total == 1 else "%s:%d/%d" % (suite, seen[suite], total), names, rule))
    return named


def quote(arg):
    """A CMake bracket argument: test names hold `/`, `.` and `=`, never `]==]`."""
    return "[==[" + arg + "]==]"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for flag in ("--binary", "--schedule", "--runner", "--python", "--build-dir", "--out"):
        parser.add_argument(flag, required=True)
    parser.add_argument("--timeout", type=float, required=True, help="default seconds per case")
    parser.add_argument("--label", action="append", default=[], help="a label of every batch")
    args = parser.parse_args()
    with open(args.schedule) as f:
        schedule = json.load(f)
    batches = name_batches(group(list_cases(args.binary), schedule["rules"], schedule["batch_size"]))
    lines = ["# Written by tests/runner/plan_batches.py from %s; do not edit." % args.binary]
    for name, cases, rule in batches:
        timeout = rule.get("timeout", args.timeout)
        command = [args.python, args.runner, "--timeout", "%g" % timeout, "--", args.binary] + cases
        lines.append("add_test(%s %s)" % (quote(name), " ".join(quote(c) for c in command)))
        props = {
            "LABELS": ";".join(args.label + [l for l in rule["labels"] if l not in args.label]),
            # The runner stops each case at its own limit; this is only ctest's backstop.
            "TIMEOUT": "%g" % (timeout * len(cases) + 30),
            "SKIP_RETURN_CODE": "77",
            "WORKING_DIRECTORY": args.build_dir,
        }
        if "cost" in rule:
            props["COST"] = str(rule["cost"])
        if "fixtures_required" in rule:
            props["FIXTURES_REQUIRED"] = rule["fixtures_required"]
        if "environment" in rule:
            props["ENVIRONMENT"] = ";".join(
                "%s=%s" % (k, v.replace("{build}", args.build_dir))
                for k, v in rule["environment"].items())
        props = {k: v for k, v in props.items() if v}
        lines.append("set_tests_properties(%s PROPERTIES %s)" % (
            quote(name), " ".join("%s %s" % (k, quote(v)) for k, v in props.items())))
    with open(args.out + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    import os
    os.replace(args.out + ".tmp", args.out)
    print("plan_batches: %s: %d cases in %d batches" % (
        args.binary, sum(len(c) for _, c, _ in batches), len(batches)))


if __name__ == "__main__":
    sys.exit(main())
