"""What the install tests share: a real `cmake --install`, a studio's small repository, and runs
of an installed ltrender with the source and build trees it was built from made unreadable.

The trees are hidden by bind-mounting an empty folder over each in a mount namespace of the
command's own (`unshare -m`, as root: tests run as root in CI), so a binary that still read a
scene, mesh or module from the tree it was built in fails here as it would on another machine.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

# Bind-mounts $1 (an empty folder) over the next $2 paths, then runs the rest.
_HIDE = ('set -e; empty=$1; n=$2; shift 2; while [ "$n" -gt 0 ]; do '
         'mount --bind "$empty" "$1"; shift; n=$((n - 1)); done; exec "$@"')


class Failure(Exception):
    pass


def install(build_dir, prefix):
    """`cmake --install BUILD --prefix PREFIX`, as a user runs it."""
    result = subprocess.run(["cmake", "--install", build_dir, "--prefix", prefix],
                            capture_output=True, text=True)
    if result.returncode != 0:
        raise Failure("cmake --install failed:\n" + result.stdout + result.stderr)


class HiddenTrees:
    """Runs commands with `trees` unreadable: an empty folder mounted over each."""

    def __init__(self, trees):
        self.empty = tempfile.mkdtemp(prefix="ltrender-empty-")
        # The deepest first: the build folder inside the source tree is hidden before its parent.
        self.trees = sorted({os.path.realpath(t) for t in trees}, key=len, reverse=True)
        for tree in self.trees:
            seen = self.run(["sh", "-c", 'ls -A "$1" | wc -l', "sh", tree], cwd=self.empty)
            if seen.returncode != 0 or seen.stdout.strip() != "0":
                raise Failure("cannot hide %s (unshare -m and mount need root): %s%s" %
                              (tree, seen.stdout, seen.stderr))

    def run(self, argv, cwd, env=None, shell=False):
        command = argv if not shell else ["bash", "-c", argv]
        full = ["unshare", "-m", "sh", "-c", _HIDE, "sh", self.empty,
                str(len(self.trees))] + self.trees + command
        return subprocess.run(full, cwd=cwd, env=env, capture_output=True, text=True)

    def close(self):
        os.rmdir(self.empty)


def make_studio(root, share):
    """A studio's repository as docs/regress.md and examples/ci/ expect it: scenes/ (the first
    run's jade sphere, at 64x48 so a render takes milliseconds), meshes/ and shaders/ (a
    hand-written ARB program of docs/budget.md's example), copied from an installed share/."""
    os.makedirs(os.path.join(root, "scenes"))
    os.makedirs(os.path.join(root, "meshes"))
    os.makedirs(os.path.join(root, "shaders"))
    with open(os.path.join(share, "examples", "first_scene.json"), encoding="utf-8") as f:
        scene = json.load(f)
    scene["image"] = {"width": 64, "height": 48}
    with open(os.path.join(root, "scenes", "jade.json"), "w", encoding="utf-8") as f:
        json.dump(scene, f)
    mesh = scene["objects"][0]["mesh"]  # "../meshes/NAME.ply", relative to the scene
    shutil.copy(os.path.join(share, "examples", mesh), os.path.join(root, "scenes", mesh))
    shutil.copy(os.path.join(share, "examples", "budget", "tint.fp"),
                os.path.join(root, "shaders", "tint.fp"))
    return os.path.join(root, "scenes", "jade.json")


def expect(result, what, code=0):
    """The command exited with `code`, or Failure naming it with its output."""
    if result.returncode != code:
        raise Failure("%s: exit %d (expected %d)\nstdout:\n%s\nstderr:\n%s" %
                      (what, result.returncode, code, result.stdout, result.stderr))
    return result


def expect_files(paths, what):
    for p in paths:
        if not os.path.isfile(p) or os.path.getsize(p) == 0:
            raise Failure("%s: wrote no %s" % (what, p))


def main(argv, usage, body, hide_trees=True):
    """A test's main: argv is [script, SOURCE_DIR, BUILD_DIR]; body(source, build, work,
    hidden) runs in a scratch folder `work` (removed after) with `hidden` a HiddenTrees over both
    trees (None when not hide_trees), and returns what passed. Exit 0 PASS, 1 FAIL (a Failure,
    printed), 2 usage."""
    if len(argv) != 3:
        print("usage: " + usage, file=sys.stderr)
        return 2
    source, build = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    work = tempfile.mkdtemp(prefix="ltrender-" + os.path.basename(argv[0]).split(".")[0] + "-")
    hidden = None
    try:
        hidden = HiddenTrees([source, build]) if hide_trees else None
        passed = body(source, build, work, hidden)
    except Failure as e:
        print("FAIL: %s" % e)
        return 1
    finally:
        if hidden:
            hidden.close()
        shutil.rmtree(work, ignore_errors=True)
    print("PASS: " + passed)
    return 0
