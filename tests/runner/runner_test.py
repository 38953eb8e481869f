#!/usr/bin/env python3
"""The batch runner and planner (tests/runner/) against a real GoogleTest binary whose cases
pass, fail, skip, abort, segfault, exit midway and hang (runner_cases.cpp).

`runner_test.py RUNNER_CASES_BINARY`: exits non-zero with a line naming what went wrong."""
import json
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)


def run_batch(binary, tests, timeout):
    started = time.monotonic()
    proc = subprocess.run([sys.executable, os.path.join(HERE, "run_batch.py"), "--timeout",
                           str(timeout), "--", binary] + tests, capture_output=True, text=True)
    return proc.returncode, proc.stdout, time.monotonic() - started


def runner_reports_every_ending(binary):
    names = ["Cases." + n for n in ("Passes", "Fails", "Skips", "Aborts", "RunsAfterTheAbort",
                                    "Segfaults", "ExitsMidway", "Hangs", "RunsAfterTheHang")]
    code, out, seconds = run_batch(binary, names, 2)
    check(code == 1, "a batch with failures exits 1, got %d" % code)
    # Five processes: one each ends at the abort, the segfault, the exit and the hang; the last
    # runs the case after the hang.
    check(re.search(r"^run_batch: 9 tests: 3 passed, 1 skipped, 5 failed; [0-9.]+ s CPU in 5 processes$",
                    out, re.M), "summary line:\n" + out)
    expected = {
        "Cases.Fails": "failed",
        "Cases.Aborts": "crashed (signal SIGABRT)",
        "Cases.Segfaults": "crashed (signal SIGSEGV)",
        "Cases.ExitsMidway": "crashed (exit status 0)",
        "Cases.Hangs": "timed out after 2 s",
    }
    for name, outcome in expected.items():
        check("run_batch: FAILED %s: %s\n" % (name, outcome) in out, "%s: %s" % (name, outcome))
    # The cases after a crash and after the hang ran, in new processes, and passed.
    for name in ("Cases.RunsAfterTheAbort", "Cases.RunsAfterTheHang", "Cases.Passes"):
        check(re.search(r"^\[       OK \] %s " % re.escape(name), out, re.M), name + " ran")
        check("FAILED %s:" % name not in out, name + " is not reported failed")
    check(seconds < 20, "the hang was stopped at its limit: the batch took %.1f s" % seconds)
    # The hung case's child (`sleep 31`) was killed with its process group.
    leftover = subprocess.run(["pgrep", "-f", "^sleep 31$"], capture_output=True, text=True)
    check(leftover.stdout.strip() == "", "the hung case's child outlived it: " + leftover.stdout)


def all_skipped_is_ctest_skip(binary):
    code, out, _ = run_batch(binary, ["Skipping.First", "Skipping.Second"], 10)
    check(code == 77, "a batch that only skipped exits 77 (SKIP_RETURN_CODE), got %d" % code)
    code, out, _ = run_batch(binary, ["Skipping.First", "Cases.Passes"], 10)
    check(code == 0, "a batch that passed and skipped exits 0, got %d" % code)


def a_child_left_running_does_not_hold_the_batch(binary):
    code, out, seconds = run_batch(binary, ["Leaving.AChildThatHoldsTheOutputOpen"], 60)
    check(code == 0, "a case that leaves a child passes, got %d:\n%s" % (code, out))
    check(seconds < 15, "the batch ended with its process, not its limit: %.1f s" % seconds)
    leftover = subprocess.run(["pgrep", "-f", "^sleep 32$"], capture_output=True, text=True)
    check(leftover.stdout.strip() == "", "the left child outlived the batch: " + leftover.stdout)


def a_missing_case_fails(binary):
    code, out, _ = run_batch(binary, ["Cases.Passes", "Cases.NoSuchCase"], 10)
    check(code == 1 and "FAILED Cases.NoSuchCase: not run" in out, "a case the binary lacks:\n" + out)


def planner_batches_suites(binary):
    with tempfile.TemporaryDirectory() as tmp:
        schedule = os.path.join(tmp, "schedule.json")
        with open(schedule, "w") as f:
            json.dump({"batch_size": 4, "rules": [
                {"match": r"^Cases\.Hangs$", "alone": True, "labels": ["slow"], "timeout": 7,
                 "cost": 5},
                {"match": r"^Skipping\.", "environment": {"WHERE": "{build}/x"}, "batch_size": 1}]}, f)
        out = os.path.join(tmp, "plan.cmake")
        subprocess.run([sys.executable, os.path.join(HERE, "plan_batches.py"), "--binary", binary,
                        "--schedule", schedule, "--runner", "RUNNER", "--python", "PY",
                        "--build-dir", "/B", "--out", out, "--timeout", "3", "--label", "unit"],
                       check=True, capture_output=True)
        text = open(out).read()
    tests = re.findall(r"^add_test\(\[==\[([^]]+)\]==\] (.*)\)$", text, re.M)
    names = [name for name, _ in tests]
    # Cases: 7 before the alone case (4 + 3, split evenly as 4 and 3), the alone one, 1 after;
    # Skipping's rule asks for batches of one.
    check(names == ["Cases:1/3", "Cases:2/3", "Cases.Hangs", "Cases:3/3", "Skipping:1/2",
                    "Skipping:2/2", "Leaving"],
          "batch names: %s" % names)
    commands = dict(tests)
    check(commands["Cases:1/3"].count("[==[Cases.") == 4, "first batch holds 4 cases")
    check("[==[--timeout]==] [==[7]==]" in commands["Cases.Hangs"], "the rule's time limit")
    check(re.search(r"Cases\.Hangs\]==\] PROPERTIES LABELS \[==\[unit;slow\]==\].*COST \[==\[5\]==\]",
                    text), "the alone case's labels and cost:\n" + text)
    check("ENVIRONMENT [==[WHERE=/B/x]==]" in text, "the environment with the build folder")


def main():
    binary = os.path.abspath(sys.argv[1])
    runner_reports_every_ending(binary)
    all_skipped_is_ctest_skip(binary)
    a_missing_case_fails(binary)
    a_child_left_running_does_not_hold_the_batch(binary)
    planner_batches_suites(binary)
    for failure in failures:
        print("runner_test: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
