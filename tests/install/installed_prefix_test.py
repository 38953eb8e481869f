#!/usr/bin/env python3
"""ltrender installed and moved (ctest: Install.RelocatedPrefixWithoutTheTrees).

Usage: installed_prefix_test.py SOURCE_DIR BUILD_DIR

`cmake --install BUILD --prefix P`, then with the source and build trees unreadable
(installed.HiddenTrees): every command a CI user runs works from P/bin/ltrender (renders through
reference, glsl and gx, advise, whose hard-case scenes come from P/share, budget, `export gx
--format module`, regress --update then --junit), and again after P is moved elsewhere.
"""
import os
import shutil
import sys

import installed
from installed import Failure, expect, expect_files


def run_every_command(prefix, hidden, work):
    ltrender = os.path.join(prefix, "bin", "ltrender")
    share = os.path.join(prefix, "share", "ltrender")
    studio = os.path.join(work, "studio")
    scene = installed.make_studio(studio, share)

    def run(what, *args, code=0):
        return expect(hidden.run([ltrender] + list(args), cwd=studio), what, code)

    for path, out in (("reference", "r.exr"), ("glsl", "g.png"), ("gx", "x.png")):
        run("render --path " + path, "render", scene, "--path", path, "-o", out)
        expect_files([os.path.join(studio, out)], "render --path " + path)
    # d < 0 reaches model.md's hard case distortion_negative: advise renders
    # share/ltrender/scenes/hard/distortion_negative.json for it (advise/hard_cases.h).
    with open(scene, encoding="utf-8") as f:
        text = f.read().replace('"distortion": 0.2', '"distortion": -0.2')
    if '"distortion": -0.2' not in text:
        raise Failure("the first scene has no \"distortion\": 0.2 to turn negative")
    os.makedirs(os.path.join(work, "advise-scene"))
    hard = os.path.join(work, "advise-scene", "jade.json")  # outside scenes/: regress reads it
    with open(hard, "w", encoding="utf-8") as f:
        f.write(text.replace("../meshes/", os.path.join(studio, "meshes") + "/"))
    advised = run("advise", "advise", hard, "--target", "wii-tev", "--max-lsb", "8", "--width",
                  "32", "--json", "advise.json")
    if "distortion_negative" not in advised.stdout + open(
            os.path.join(studio, "advise.json"), encoding="utf-8").read():
        raise Failure("advise names no hard case distortion_negative:\n" + advised.stdout)
    run("budget of a scene", "budget", scene, "--path", "gx")
    run("budget of a program file", "budget", "shaders/tint.fp")
    run("export gx --format module", "export", "gx", scene, "--format", "module", "-o", "m.c")
    expect_files([os.path.join(studio, "m.c")], "export gx --format module")
    run("regress --update", "regress", "scenes", "--goldens", "goldens", "--update")
    run("regress --junit", "regress", "scenes", "--goldens", "goldens", "--junit", "junit.xml",
        "-o", "report")
    expect_files([os.path.join(studio, "junit.xml"), os.path.join(studio, "report", "index.html")],
                 "regress --junit -o report")
    junit = open(os.path.join(studio, "junit.xml"), encoding="utf-8").read()
    if 'failures="0"' not in junit or "<testcase " not in junit:
        raise Failure("regress --junit against the goldens it just wrote failed:\n" + junit)
    if '<property name="ltrender.versions" value="ltrender ' not in junit:
        raise Failure("the JUnit XML has no ltrender.versions property:\n" + junit)


def both_places(source, build, work, hidden):
    prefix = os.path.join(work, "prefix")
    installed.install(build, prefix)
    run_every_command(prefix, hidden, os.path.join(work, "first"))
    moved = os.path.join(work, "moved", "elsewhere")
    os.makedirs(os.path.dirname(moved))
    shutil.move(prefix, moved)
    run_every_command(moved, hidden, os.path.join(work, "second"))
    return "installed and moved, every command ran with the trees hidden"


if __name__ == "__main__":
    sys.exit(installed.main(sys.argv, "installed_prefix_test.py SOURCE_DIR BUILD_DIR",
                            both_places))
