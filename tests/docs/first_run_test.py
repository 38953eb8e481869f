#!/usr/bin/env python3
"""The README's first run, as a newcomer types it, so it cannot rot (ctest: Docs.FirstRun).

Usage: first_run_test.py SOURCE_DIR LTRENDER_BINARY

- The scene block under the README's `<!-- first-scene` marker is examples/first_scene.json,
  character for character, and at most five lines.
- The commands of the block under the `<!-- first-run` marker run as written from a folder laid
  out as the repository root (build/ltrender, examples/, meshes/), each exiting 0 and writing
  every file it names with -o / --heatmap.
- Every line of the output the README shows (the block after the commands, `...` skipped) is a
  line of what the last command printed: the figures a newcomer reads are the ones they get.
"""
import json
import os
import shlex
import subprocess
import sys
import tempfile


def fenced_block_after(lines, marker, readme):
    """The lines of the first fenced block after the line that starts with marker, and the
    index of its closing fence."""
    for i, line in enumerate(lines):
        if line.startswith(marker):
            start = next(j for j in range(i + 1, len(lines)) if lines[j].startswith("```"))
            end = next(j for j in range(start + 1, len(lines)) if lines[j].startswith("```"))
            return lines[start + 1:end], end
    raise SystemExit("%s: no line starting with %r" % (readme, marker))


def fail(message):
    print("FAIL: " + message)
    return 1


def main(argv):
    if len(argv) != 3:
        print("usage: first_run_test.py SOURCE_DIR LTRENDER_BINARY", file=sys.stderr)
        return 2
    source, binary = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    readme = os.path.join(source, "README.md")
    lines = open(readme, encoding="utf-8").read().split("\n")

    scene_lines, _ = fenced_block_after(lines, "<!-- first-scene", readme)
    scene_file = os.path.join(source, "examples", "first_scene.json")
    with open(scene_file, encoding="utf-8") as f:
        committed = f.read().rstrip("\n").split("\n")
    if scene_lines != committed:
        return fail("the README's scene differs from examples/first_scene.json")
    if len(scene_lines) > 5:
        return fail("the README's scene has %d lines; it promises five" % len(scene_lines))
    json.loads("\n".join(scene_lines))  # valid JSON, or the traceback says where

    commands, end = fenced_block_after(lines, "<!-- first-run", readme)
    # The output the README shows: the next fenced block after the commands.
    rest = lines[end + 1:]
    start = next(j for j, l in enumerate(rest) if l.startswith("```"))
    stop = next(j for j in range(start + 1, len(rest)) if rest[j].startswith("```"))
    shown = [l for l in rest[start + 1:stop] if l.strip() != "..."]

    with tempfile.TemporaryDirectory(prefix="ltrender_first_run_") as root:
        os.makedirs(os.path.join(root, "build"))
        os.symlink(binary, os.path.join(root, "build", "ltrender"))
        for folder in ("examples", "meshes"):
            os.symlink(os.path.join(source, folder), os.path.join(root, folder))
        output = ""
        for command in commands:
            argv_ = shlex.split(command)
            print("$ " + command, flush=True)
            run = subprocess.run(argv_, cwd=root, capture_output=True, text=True, timeout=600)
            print(run.stdout + run.stderr, end="", flush=True)
            if run.returncode != 0:
                return fail("exit %d from: %s" % (run.returncode, command))
            for flag in ("-o", "--heatmap"):
                if flag in argv_:
                    written = os.path.join(root, argv_[argv_.index(flag) + 1])
                    if not os.path.isfile(written) or os.path.getsize(written) == 0:
                        return fail("%s did not write %s" % (command, written))
            output = run.stdout
        printed = output.split("\n")
        missing = [l for l in shown if l not in printed]
        if missing:
            return fail("the README shows output lines the last command did not print:\n  " +
                        "\n  ".join(missing))
    print("the README's first run works as written: %d commands, %d output lines as shown" %
          (len(commands), len(shown)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
