#!/usr/bin/env python3
"""The Debian package (ctest: Install.DebianPackage).

Usage: package_test.py SOURCE_DIR BUILD_DIR

`cpack -G DEB` of the build makes one .deb; `dpkg-deb -f` shows a Depends generated from the
linked libraries (it names libosmesa6, which ltrender links for OSMesa, and libc6) and the
run-time tools as Recommends; the package unpacked into a scratch root (`dpkg -x`) runs
docs/install.md's installed first run, as written there with the root in front of /usr, from a
scratch folder with the source and build trees unreadable.
"""
import glob
import os
import re
import shlex
import subprocess
import sys

import installed
from installed import Failure, expect, expect_files

MARKER = "<!-- installed-first-run"


def first_run_commands(source):
    """The commands of the fenced block after docs/install.md's marker."""
    doc = os.path.join(source, "docs", "install.md")
    lines = open(doc, encoding="utf-8").read().split("\n")
    start = next((i for i, l in enumerate(lines) if l.startswith(MARKER)), None)
    if start is None:
        raise Failure("%s: no line starting with %s" % (doc, MARKER))
    fence = next(j for j in range(start + 1, len(lines)) if lines[j].startswith("```"))
    end = next(j for j in range(fence + 1, len(lines)) if lines[j].startswith("```"))
    commands = [l for l in lines[fence + 1:end] if l.strip()]
    if not commands or any(not c.startswith("ltrender ") for c in commands):
        raise Failure("%s: the first run's commands must each start with 'ltrender '" % doc)
    return commands


def field(deb, name):
    return subprocess.run(["dpkg-deb", "-f", deb, name], capture_output=True,
                          text=True).stdout.strip()


def package_and_run(source, build, work, hidden):
    commands = first_run_commands(source)
    packages = os.path.join(work, "packages")
    expect(subprocess.run(["cpack", "-G", "DEB", "--config",
                           os.path.join(build, "CPackConfig.cmake"), "-B", packages],
                          capture_output=True, text=True), "cpack -G DEB")
    debs = glob.glob(os.path.join(packages, "*.deb"))
    if len(debs) != 1:
        raise Failure("cpack -G DEB made %d packages, expected one: %s" % (len(debs), debs))
    deb = debs[0]
    depends = field(deb, "Depends")
    for library in ("libosmesa6", "libc6"):
        if not re.search(r"(^|, )%s( |,|$)" % re.escape(library), depends):
            raise Failure("Depends does not name %s: %r" % (library, depends))
    recommends = field(deb, "Recommends")
    for tool in ("dolphin-emu", "xvfb", "gcc-powerpc-linux-gnu"):
        if tool not in recommends:
            raise Failure("Recommends does not name %s: %r" % (tool, recommends))
    print("package %s\nDepends: %s\nRecommends: %s" % (os.path.basename(deb), depends,
                                                       recommends))

    root = os.path.join(work, "root")
    expect(subprocess.run(["dpkg", "-x", deb, root], capture_output=True, text=True), "dpkg -x")
    usr = os.path.join(root, "usr")
    scratch = os.path.join(work, "anywhere")
    os.makedirs(scratch)
    for command in commands:
        args = shlex.split(command.replace("/usr/", usr + "/"))
        args[0] = os.path.join(usr, "bin", "ltrender")
        result = expect(hidden.run(args, cwd=scratch), command)
        if args[1:2] == ["--version"] and not result.stdout.startswith("ltrender "):
            raise Failure("%s printed %r" % (command, result.stdout))
        outputs = [args[i + 1] for i, a in enumerate(args[:-1]) if a in ("-o", "--heatmap")]
        expect_files([os.path.join(scratch, o) for o in outputs], command)
    return "the package installs into a scratch root and runs the installed first run"


if __name__ == "__main__":
    sys.exit(installed.main(sys.argv, "package_test.py SOURCE_DIR BUILD_DIR", package_and_run))
