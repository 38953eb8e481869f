#!/usr/bin/env python3
"""A copy of the binary without its prefix (ctest: Install.ACopiedBinarySaysWhatIsMissing).

Usage: copied_binary_test.py SOURCE_DIR BUILD_DIR

build/ltrender copied alone to another folder is not installed, so it must not fall back on the
build or source tree (which another machine has not got): a PNG or an EXR it writes itself
(libpng, OpenEXR: image/png_file.h, image/exr_file.h), but a command that needs OpenImageIO
(`compare` of a PNG with alpha, read with its colour multiplied by alpha) fails
with one error line naming the module folder it looked in (../lib/ltrender/, as installed), and
advise, which checks the material on model.md's hard cases, fails naming a scene of
../share/ltrender/scenes/hard/. Both exit
2, neither crashes. The same copy placed in a prefix laid out by hand (bin/, lib/ltrender/,
share/ltrender/) works: where it looks is relative to the binary, nothing else.
"""
import json
import os
import shutil
import struct
import subprocess
import sys
import zlib

import installed
from installed import Failure, expect, expect_files


def write_rgba_png(path, width, height):
    """A PNG with an alpha channel (colour type 6), which `compare` reads through OpenImageIO."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    rows = b"".join(b"\0" + bytes([200, 100, 50, 128] * width) for _ in range(height))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" +
                chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def bare_and_in_a_prefix(source, build, work, _hidden):
    bare = os.path.join(work, "bare", "bin")
    os.makedirs(bare)
    shutil.copy2(os.path.join(build, "ltrender"), bare)
    scene = os.path.join(work, "jade.json")
    with open(os.path.join(source, "examples", "first_scene.json"), encoding="utf-8") as f:
        s = json.load(f)
    s["image"] = {"width": 32, "height": 24}
    s["objects"][0]["mesh"] = os.path.join(source, "meshes", "sphere_s4.ply")
    with open(scene, "w", encoding="utf-8") as f:
        json.dump(s, f)

    def run(binary, *args):
        return subprocess.run([os.path.join(binary, "ltrender")] + list(args), cwd=work,
                              capture_output=True, text=True)

    rgba = os.path.join(work, "rgba.png")
    write_rgba_png(rgba, 4, 3)
    for args, missing in (
            (["compare", rgba, rgba],
             os.path.join(work, "bare", "lib", "ltrender", "libltrender_imageio.so")),
            (["advise", scene, "--target", "wii-tev", "--max-lsb", "8", "--width", "16"],
             os.path.join(work, "bare", "share", "ltrender", "scenes", "hard") + "/")):
        r = expect(run(bare, *args), "a bare copy: " + args[0], code=2)
        lines = r.stderr.strip().split("\n")
        if len(lines) != 1 or not lines[0].startswith("ltrender: error: ") or \
                missing not in lines[0]:
            raise Failure("a bare copy's %s: expected one error line naming %s, got:\n%s" %
                          (args[0], missing, r.stderr))

    for image in ("bare.png", "bare.exr"):
        expect(run(bare, "render", scene, "--path", "reference", "-o", image),
               "a bare copy: render to " + image)
        expect_files([os.path.join(work, image)], "a bare copy: render to " + image)

    prefix = os.path.join(work, "by-hand")
    os.makedirs(os.path.join(prefix, "lib", "ltrender"))
    shutil.copytree(bare, os.path.join(prefix, "bin"))
    shutil.copy2(os.path.join(build, "libltrender_imageio.so"),
                 os.path.join(prefix, "lib", "ltrender"))
    os.makedirs(os.path.join(prefix, "share", "ltrender"))
    shutil.copytree(os.path.join(source, "scenes"),
                    os.path.join(prefix, "share", "ltrender", "scenes"))
    shutil.copytree(os.path.join(source, "meshes"),
                    os.path.join(prefix, "share", "ltrender", "meshes"))
    by_hand = os.path.join(prefix, "bin")
    expect(run(by_hand, "render", scene, "--path", "reference", "-o", "r.exr"),
           "a prefix by hand: render")
    expect_files([os.path.join(work, "r.exr")], "a prefix by hand: render")
    expect(run(by_hand, "compare", rgba, rgba), "a prefix by hand: compare of a PNG with alpha")
    expect(run(by_hand, "advise", scene, "--target", "wii-tev", "--max-lsb", "8", "--width",
               "16"), "a prefix by hand: advise")
    return "a bare copy names what it misses; in a prefix it works"


if __name__ == "__main__":
    sys.exit(installed.main(sys.argv, "copied_binary_test.py SOURCE_DIR BUILD_DIR",
                            bare_and_in_a_prefix, hide_trees=False))
