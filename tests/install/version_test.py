#!/usr/bin/env python3
"""`ltrender --version` (ctest: Install.Version).

Usage: version_test.py LTRENDER_BINARY PROJECT_VERSION SOURCE_DIR

One line, exit 0: "ltrender X.Y.Z[ (git DESCRIBE)]; GL VERSION on RENDERER; OpenImageIO A.B.C;
Embree A.B.C; Dolphin V" (or "Dolphin not found"), X.Y.Z being CMake's project(VERSION) and
DESCRIBE `git describe` of the source tree. Each library's figure is checked against what the
machine says it runs, not against ltrender's output: the upstream version of the installed Debian
package (dpkg-query) of libosmesa6, OpenImageIO, Embree and dolphin-emu.
"""
import re
import subprocess
import sys

LINE = re.compile(r"^ltrender (?P<version>\d+\.\d+\.\d+)(?: \(git (?P<describe>[^)]+)\))?; "
                  r"GL (?P<gl>.+) on (?P<renderer>.+); OpenImageIO (?P<oiio>\d+\.\d+\.\d+); "
                  r"Embree (?P<embree>\d+\.\d+\.\d+); "
                  r"(?:Dolphin (?P<dolphin>\S+)|Dolphin not found)$")


def package_version(pattern):
    """The upstream version ("22.3.6" of "22.3.6-1+deb12u1") of the installed package whose
    name matches `pattern` (a dpkg-query pattern), or None."""
    out = subprocess.run(["dpkg-query", "-W", "-f", "${db:Status-Abbrev} ${Version}\n", pattern],
                         capture_output=True, text=True).stdout
    for line in out.split("\n"):
        if line.startswith("ii "):
            version = line.split()[1]
            version = version.split(":", 1)[-1]  # without an epoch
            if "-" in version:
                version = version.rsplit("-", 1)[0]  # and the Debian revision
            return re.split(r"[+~]", version)[0]  # and a repack's +dfsg
    return None


def main(argv):
    if len(argv) != 4:
        print("usage: version_test.py LTRENDER_BINARY PROJECT_VERSION SOURCE_DIR", file=sys.stderr)
        return 2
    binary, project_version, source = argv[1:]
    result = subprocess.run([binary, "--version"], capture_output=True, text=True)
    lines = result.stdout.rstrip("\n").split("\n")
    problems = []
    if result.returncode != 0:
        problems.append("exit %d, stderr %r" % (result.returncode, result.stderr))
    if len(lines) != 1:
        problems.append("%d lines, expected one" % len(lines))
    m = LINE.match(lines[0])
    if not m:
        print("FAIL: not the form of docs/install.md: %r" % result.stdout)
        return 1
    if m["version"] != project_version:
        problems.append("version %s, CMake's project(VERSION) is %s" %
                        (m["version"], project_version))
    described = subprocess.run(["git", "-C", source, "describe", "--always", "--tags"],
                               capture_output=True, text=True)
    if described.returncode == 0:
        # The build may be older than a later commit or edit: its describe must name a commit.
        if not m["describe"]:
            problems.append("built from a checkout, yet no (git ...) in the line")
    expected = {
        "Mesa (GL_VERSION)": (package_version("libosmesa6"), m["gl"]),
        "OpenImageIO": (package_version("libopenimageio2*"), m["oiio"]),
        "Embree": (package_version("libembree3-3"), m["embree"]),
        "Dolphin": (package_version("dolphin-emu"), m["dolphin"] or ""),
    }
    for name, (installed, shown) in expected.items():
        if installed is None:
            continue  # not installed here: nothing to hold the line to
        # OpenImageIO's 2.4.7.1 reports itself as 2.4.7 (major, minor, patch).
        if installed not in shown and not installed.startswith(shown + "."):
            problems.append("%s: the installed package is %s, the line says %r" %
                            (name, installed, shown))
    if package_version("dolphin-emu") is None and m["dolphin"]:
        problems.append("Dolphin is not installed, yet the line names %r" % m["dolphin"])
    if problems:
        print("FAIL: %r\n  " % lines[0] + "\n  ".join(problems))
        return 1
    print("PASS: " + lines[0])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
