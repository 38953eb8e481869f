#!/usr/bin/env python3
"""A studio-sized set of scenes for measuring `ltrender regress` at scale (docs/regress.md
"Speed and scale"): COUNT scenes made from the demo scenes (scenes/*.json) in turn, the k-th
copy's camera turned by 7 degrees x k about its target so that no two render alike. Every file a
scene names (meshes, maps, glTF) is written as an absolute path, so the set works from any folder.

    scripts/make_scale_scenes.py COUNT OUT_DIR
"""
import json
import math
import os
import sys


def absolute_files(value, base):
    """Every string that names a file beside the source scene, made absolute."""
    if isinstance(value, dict):
        return {k: absolute_files(v, base) for k, v in value.items()}
    if isinstance(value, list):
        return [absolute_files(v, base) for v in value]
    if isinstance(value, str) and os.path.isfile(os.path.join(base, value)):
        return os.path.normpath(os.path.join(base, value))
    return value


def turned(camera, degrees):
    eye, target = camera["eye"], camera.get("target", [0, 0, 0])
    dx, dz = eye[0] - target[0], eye[2] - target[2]
    a = math.radians(degrees)
    camera["eye"] = [target[0] + dx * math.cos(a) + dz * math.sin(a), eye[1],
                     target[2] - dx * math.sin(a) + dz * math.cos(a)]
    return camera


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    count, out = int(sys.argv[1]), sys.argv[2]
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes")
    demos = sorted(f for f in os.listdir(source) if f.endswith(".json"))
    os.makedirs(out, exist_ok=True)
    for i in range(count):
        name = demos[i % len(demos)]
        with open(os.path.join(source, name)) as f:
            scene = absolute_files(json.load(f), os.path.normpath(source))
        copy = i // len(demos)
        if copy:
            scene["camera"] = turned(scene["camera"], 7.0 * copy)
        with open(os.path.join(out, "s%04d_%s" % (i, name)), "w") as f:
            json.dump(scene, f, indent=1)


if __name__ == "__main__":
    main()
