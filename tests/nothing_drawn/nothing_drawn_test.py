#!/usr/bin/env python3
"""A frame with nothing drawn is never silent (ctest: NothingDrawn.<Case>).

Usage: nothing_drawn_test.py LTRENDER_BINARY CASE

Each gx case renders a scene through the gx path with a hand-written program file, as a
porter does (`ltrender render SCENE --path gx --program FILE.c`, 64x48); each GlPaths case
renders it through every path GL rasterises. Each reads stderr: one warning names the path and
pass, the count and the cause, whose figures come from the inputs (the triangles of the mesh the
test writes, the line of the program that set the cull mode), not from the run.
The render itself still succeeds (exit 0): the warning says why the frame is empty.
"""
import os
import re
import subprocess
import sys
import tempfile

# A flat colour, as docs/spec/gx.md's example draws it; {cull} and {extra} are filled per case.
PROGRAM = """\
{cull}GX_SetNumChans(1);
GX_SetChanCtrl(GX_COLOR0A0, GX_DISABLE, GX_SRC_REG, GX_SRC_REG, GX_LIGHTNULL, GX_DF_NONE, GX_AF_NONE);
GX_SetChanMatColor(GX_COLOR0A0, (GXColor){{200, 120, 40, 255}});
GX_SetNumTexGens(0);
GX_SetNumTevStages(1);
GX_SetTevOrder(GX_TEVSTAGE0, GX_TEXCOORDNULL, GX_TEXMAP_NULL, GX_COLOR0A0);
GX_SetTevColorIn(GX_TEVSTAGE0, GX_CC_ZERO, GX_CC_ZERO, GX_CC_ZERO, GX_CC_RASC);
GX_SetTevColorOp(GX_TEVSTAGE0, GX_TEV_ADD, GX_TB_ZERO, GX_CS_SCALE_1, GX_TRUE, GX_TEVPREV);
{extra}"""

# A unit cube, 12 triangles (two a face, each with its face's normal).
CUBE = ("v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
        "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n" +
        "".join("f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n" %
                (a, n, b, n, c, n, a, n, c, n, d, n)
                for n, (a, b, c, d) in enumerate([(1, 4, 3, 2), (5, 6, 7, 8), (1, 2, 6, 5),
                                                  (4, 8, 7, 3), (1, 5, 8, 4), (2, 3, 7, 6)], 1)))
MESHES = {"cube": (CUBE, 12)}
# A square facing the camera at +z, wound counter-clockwise as GL's front faces are: GX_Init's
# GX_CULL_BACK removes both of its triangles (gx_state.h).
MESHES["quad"] = ("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n"
                  "f 1//1 3//1 4//1\n", 2)

CULL_NONE = "GX_SetCullMode(GX_CULL_NONE);\n"
CASES = {
    # name: (mesh, the gx program's cull line and extra calls (None: the GL paths, their own
    # programs), camera target, expected cause as a regex)
    "CulledByGxInitDefault": ("quad", "", "", [0, 0, 0],
                              r"all {n} triangles culled by GX_CULL_BACK, GX_Init's default"),
    "CulledBySetCullMode": ("cube", "GX_SetCullMode(GX_CULL_ALL);\n", "", [0, 0, 0],
                            r"all {n} triangles culled by GX_CULL_ALL, set by GX_SetCullMode at "
                            r"\S*program\.c:1\b"),
    "OutsideTheView": ("cube", CULL_NONE, "", [0, 0, 8],
                       r"all {n} triangles outside the view volume"),
    "DepthTestFailed": ("cube", CULL_NONE, "GX_SetZMode(GX_TRUE, GX_EQUAL, GX_FALSE);\n",
                        [0, 0, 0], r"all [1-9]\d* covered pixels failed the depth test"),
    # The quad: nothing in front of another, so no pixel fails the depth test first (the cube's
    # far side would: early z writes depth before the alpha test discards [DSW Draw]).
    "AlphaTestFailed": ("quad", CULL_NONE,
                        "GX_SetAlphaCompare(GX_NEVER, 0, GX_AOP_AND, GX_NEVER, 0);\n", [0, 0, 0],
                        r"all [1-9]\d* covered pixels failed the alpha test"),
    "DrawnFrameIsSilent": ("cube", CULL_NONE, "", [0, 0, 0], None),
    # The paths GL rasterises cull nothing; a camera looking away leaves their frame empty.
    "GlPathsClippedAway": ("cube", None, None, [0, 0, 8],
                           r"no fragment of its {n} triangles passed \(GL_SAMPLES_PASSED 0"),
    "GlPathsDrawnFrameIsSilent": ("cube", None, None, [0, 0, 0], None),
}
# The paths GL rasterises (their own program, no --program): every one but gx.
GL_PATHS = ["glsl", "arbfp", "combiners", "flat", "reference", "half"]


def main(argv):
    if len(argv) != 3 or argv[2] not in CASES:
        print("usage: nothing_drawn_test.py LTRENDER_BINARY CASE (%s)" %
              ", ".join(CASES), file=sys.stderr)
        return 2
    binary, case = os.path.abspath(argv[1]), argv[2]
    mesh, cull, extra, target, cause = CASES[case]
    with tempfile.TemporaryDirectory(prefix="ltrender-nothing-drawn-") as work:
        text, triangles = MESHES[mesh]
        mesh_file = os.path.join(work, mesh + ".obj")
        with open(mesh_file, "w") as f:
            f.write(text)
        scene = os.path.join(work, "scene.json")
        with open(scene, "w") as f:
            f.write('{"image": {"width": 64, "height": 48}, "camera": {"eye": [0, 0, 4], '
                    '"target": %s}, "materials": {"m": {"albedo": [0.5, 0.9, 0.6]}}, '
                    '"objects": [{"mesh": "%s", "material": "m"}]}' % (target, mesh_file))
        if cull is None:
            runs = [(path, []) for path in GL_PATHS]
        else:
            program = os.path.join(work, "program.c")
            with open(program, "w") as f:
                f.write(PROGRAM.format(cull=cull, extra=extra))
            runs = [("gx", ["--program", program])]
        failures = [check(binary, scene, path, options, work, cause, triangles)
                    for path, options in runs]
    failures = [f for f in failures if f]
    if failures:
        print("FAIL: " + "\n".join(failures))
        return 1
    print("PASS: %s on %s" % (case, ", ".join(p for p, _ in runs)))
    return 0


def check(binary, scene, path, options, work, cause, triangles):
    """None when `ltrender render` through `path` exits 0 with the expected warning (or none);
    otherwise what went wrong."""
    result = subprocess.run([binary, "render", scene, "--path", path, "-o",
                             os.path.join(work, path + ".png")] + options,
                            capture_output=True, text=True)
    if result.returncode != 0:
        return "%s: exit %d\n%s" % (path, result.returncode, result.stderr)
    warnings = [l for l in result.stderr.split("\n") if "drew nothing" in l]
    if cause is None:
        return "%s: a frame that draws warned: %s" % (path, warnings) if warnings else None
    # gx names its pass and program; a GL path its whole frame (its later passes draw where
    # pass 0 did: first_frame_fragments.h).
    who = r"gx pass 0 \(\S+\)" if path == "gx" else r".*\b%s\b.* frame" % path
    expected = re.compile(r"^ltrender: warning: %s drew nothing: " % who +
                          cause.format(n=triangles))
    if len(warnings) != 1 or not expected.search(warnings[0]):
        return "%s: expected one warning matching %r, stderr:\n%s" % (
            path, expected.pattern, result.stderr)
    print(warnings[0])
    return None


if __name__ == "__main__":
    sys.exit(main(sys.argv))
