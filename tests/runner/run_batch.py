#!/usr/bin/env python3
"""Runs a batch of GoogleTest cases in as few processes as it can, one ctest test per batch.

`run_batch.py --timeout SECONDS -- BINARY TEST...` runs BINARY with --gtest_filter naming the
tests, streaming its output. A process costs every test that runs in it ~0.1 s of CPU before
the test starts (Mesa's LLVM mapped, the image module loaded; docs/testing.md "Test time"), so a
batch shares it. What one process per test gave (piglit's rule) is kept the way dEQP's runners
keep it (deqp-runner, Mesa's CI): when a test crashes or passes its time limit, it is reported
as failed with the signal or the limit, and a new process runs the tests after it. So a crash
inside the GL context still fails one test, not the batch.

Exit status: 0 when every test passed or skipped, 77 when every test skipped (ctest's
SKIP_RETURN_CODE), 1 otherwise. The last line says what happened to each test that did not pass.
"""
import argparse
import os
import re
import resource
import selectors
import signal
import subprocess
import sys
import time

# GoogleTest's progress lines: `[ RUN      ] Suite.Test`, `[       OK ] Suite.Test (5 ms)`.
# The summary at the end repeats failures as `[  FAILED  ] Suite.Test, where GetParam() = ...`.
PROGRESS = re.compile(r"^\[ *(RUN|OK|FAILED|SKIPPED) *\] ([^ ,]+)")
ENDED = {"OK": "passed", "FAILED": "failed", "SKIPPED": "skipped"}


def kill_group(proc):
    """The test may have started children (Dolphin, Xvfb, ltrender's workers): end them all."""
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def describe_exit(code):
    if code < 0:
        return "crashed (signal %s)" % signal.Signals(-code).name
    return "crashed (exit status %d)" % code


def run_once(binary, tests, timeout, results):
    """One process over `tests` (all not yet run). Records what ended; returns True when the
    process ran at least one test, so a process that cannot start does not loop forever."""
    wanted = set(tests)
    proc = subprocess.Popen(
        [binary, "--gtest_filter=" + ":".join(tests)],
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        start_new_session=True,
    )
    selector = selectors.DefaultSelector()
    selector.register(proc.stdout, selectors.EVENT_READ)
    current, started_any = None, False
    deadline = time.monotonic() + timeout
    pending = b""
    timed_out = False
    while True:
        wait = deadline - time.monotonic()
        if wait <= 0:
            timed_out = True
            kill_group(proc)
            break
        if not selector.select(timeout=min(wait, 0.5)):
            if proc.poll() is not None:
                break  # the test process ended; a child it left may still hold the pipe open
            continue
        chunk = os.read(proc.stdout.fileno(), 65536)
        if not chunk:
            break
        sys.stdout.buffer.write(chunk)
        sys.stdout.buffer.flush()
        pending += chunk
        *lines, pending = pending.split(b"\n")
        for raw in lines:
            match = PROGRESS.match(raw.decode("utf-8", "replace"))
            if not match or match.group(2) not in wanted:
                continue
            event, name = match.groups()
            if event == "RUN":
                current, started_any = name, True
                deadline = time.monotonic() + timeout
            elif name not in results:
                results[name] = ENDED[event]
                current = None
    selector.close()
    code = proc.wait()
    kill_group(proc)  # whatever the test left running in its group
    if current is not None and current not in results:
        if timed_out:
            results[current] = "timed out after %g s" % timeout
        else:
            results[current] = describe_exit(code)
    elif timed_out:
        # Past the limit before any test started: the process itself hung.
        for name in tests:
            results.setdefault(name, "not run: the process hung for %g s before a test" % timeout)
    elif code != 0 and not started_any:
        for name in tests:
            results.setdefault(name, "not run: the process ended with %s" % describe_exit(code))
    return started_any


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--timeout", type=float, required=True, help="seconds per test")
    parser.add_argument("binary")
    parser.add_argument("tests", nargs="+")
    args = parser.parse_args()
    results = {}
    remaining = list(args.tests)
    processes = 0
    while remaining:
        processes += 1
        if not run_once(args.binary, remaining, args.timeout, results):
            break
        remaining = [name for name in remaining if name not in results]
    for name in remaining:
        results.setdefault(name, "not run: the binary did not start it (is it listed?)")

    passed = [name for name in args.tests if results[name] == "passed"]
    skipped = [name for name in args.tests if results[name] == "skipped"]
    bad = [(name, results[name]) for name in args.tests if name not in passed + skipped]
    # CPU of the test processes and what they waited for (Dolphin, ltrender's children): where
    # a suite's time goes (docs/testing.md "Test time" adds these lines up).
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    print("run_batch: %d tests: %d passed, %d skipped, %d failed; %.2f s CPU in %d process%s" % (
        len(args.tests), len(passed), len(skipped), len(bad), usage.ru_utime + usage.ru_stime,
        processes, "" if processes == 1 else "es"))
    for name, outcome in bad:
        print("run_batch: FAILED %s: %s" % (name, outcome))
    if bad:
        return 1
    return 77 if len(skipped) == len(args.tests) else 0


if __name__ == "__main__":
    sys.exit(main())
