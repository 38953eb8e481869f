#!/usr/bin/env python3
"""examples/ci/ as a studio runs it (ctest: Install.CiExamples).

Usage: ci_examples_test.py SOURCE_DIR BUILD_DIR

For each CI file of examples/ci/ (its *.yml: GitLab's `script:` items, GitHub Actions' `run:`
steps), the commands that start with `ltrender` run as written, through bash, from a studio's
repository (installed.make_studio, its goldens written once by the `--update` run
docs/regress.md prescribes), with an installed prefix's bin/ first on PATH and the source and
build trees unreadable, as one shard of one (CI_NODE_INDEX, SHARD and their totals 1). Each
exits 0; budget.json holds an ltrender-budget-2 record of the shader; junit.xml
has a passing testcase for the glsl and the gx path and the ltrender.versions property.
"""
import json
import os
import re
import sys

import installed
from installed import Failure, expect, expect_files

# A GitLab script item or a GitHub Actions run step whose command is ltrender's.
COMMAND = re.compile(r"^\s*(?:- |run: )(ltrender .*)$")


def commands_of(ci_file):
    commands = [m.group(1) for m in map(COMMAND.match, open(ci_file, encoding="utf-8"))
                if m]
    if not any(c.startswith("ltrender budget ") for c in commands) or not any(
            c.startswith("ltrender regress ") and "--junit" in c for c in commands):
        raise Failure("%s: no `ltrender budget` or no `ltrender regress --junit` command: %s" %
                      (ci_file, commands))
    return commands


def check_outputs(studio, ci_file):
    text = open(os.path.join(studio, "budget.json"), encoding="utf-8").read()
    budget, at, decoder = [], 0, json.JSONDecoder()
    while text[at:].strip():  # one object per file counted, however it is laid out
        at += len(text[at:]) - len(text[at:].lstrip())
        record, at = decoder.raw_decode(text, at)
        budget.append(record)
    if not budget or any(b.get("schema") != "ltrender-budget-2" for b in budget):
        raise Failure("%s: budget.json is not ltrender-budget-2 records: %s" % (ci_file, budget))
    junit = open(os.path.join(studio, "junit.xml"), encoding="utf-8").read()
    for needle in ('failures="0"', 'name="glsl:', 'name="gx:', 'name="ltrender.versions"'):
        if needle not in junit:
            raise Failure("%s: junit.xml has no %s:\n%s" % (ci_file, needle, junit))


def run_each_ci_file(source, build, work, hidden):
    folder = os.path.join(source, "examples", "ci")
    commands = {f: commands_of(os.path.join(folder, f)) for f in sorted(os.listdir(folder))
                if f.endswith(".yml")}
    if len(commands) < 2:
        raise Failure("examples/ci/ holds %d CI files, expected GitLab's and GitHub's" %
                      len(commands))
    prefix = os.path.join(work, "prefix")
    installed.install(build, prefix)
    # One shard of one, as the CI files' own variables say it (GitLab's parallel: N, the GitHub
    # matrix); GitHub's own variables unset, so no annotations.
    env = dict(os.environ, PATH=os.path.join(prefix, "bin") + ":" + os.environ["PATH"],
               CI_NODE_INDEX="1", CI_NODE_TOTAL="1", SHARD="1", SHARDS="1")
    for variable in ("GITHUB_ACTIONS", "GITHUB_STEP_SUMMARY"):
        env.pop(variable, None)
    for ci_file, ci_commands in commands.items():
        studio = os.path.join(work, ci_file)
        installed.make_studio(studio, os.path.join(prefix, "share", "ltrender"))
        expect(hidden.run("ltrender regress scenes --goldens goldens --update", studio, env,
                          shell=True), "the studio's goldens (regress --update)")
        for command in ci_commands:
            expect(hidden.run(command, studio, env, shell=True), ci_file + ": " + command)
        expect_files([os.path.join(studio, f) for f in ("budget.json", "junit.xml")], ci_file)
        check_outputs(studio, ci_file)
        print("%s: %d commands passed" % (ci_file, len(ci_commands)))
    return "the ltrender commands of " + ", ".join(commands)


if __name__ == "__main__":
    sys.exit(installed.main(sys.argv, "ci_examples_test.py SOURCE_DIR BUILD_DIR",
                            run_each_ci_file))
