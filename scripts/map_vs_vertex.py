#!/usr/bin/env python3
"""The error of replacing a thickness map by vertex colours, per tessellation (issue 13).

For each ring count R: `ltrender meshgen --uvsphere R` (R rings, 2R segments), one vertex bake and
one UV-map bake of that mesh (same rays, seed and defaults), the backlit sphere's scene
(scenes/backlit_sphere.json: camera, lights, material) with "thickness": "vertex" and with the
map, both rendered by the reference (float EXR), and `ltrender compare` of the vertex image
against the map image over covered pixels: what a Wii porter loses by dropping the map at that
density. Both bakes are 8-bit (vertex colours as uchar, the map as PNG), as the demo ships them.

Prints a markdown table (or JSON with --json); --table FILE writes the table there too. Work
files go to a temporary folder (kept with --keep DIR). Standard library only.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(args):
    """Runs ltrender (or anything), failing loudly with its stderr."""
    r = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit(f"map_vs_vertex: {' '.join(args)} exited {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def ply_vertex_count(path):
    with open(path, "rb") as f:
        for line in f:
            if line.startswith(b"element vertex "):
                return int(line.split()[2])
            if line.startswith(b"end_header"):
                break
    sys.exit(f"map_vs_vertex: {path}: no vertex count in the PLY header")


def scene_with(thickness, mesh, width, height):
    """scenes/backlit_sphere.json with the sphere replaced by `mesh` and its thickness by
    `thickness` (the JSON value), at width x height."""
    with open(os.path.join(REPO, "scenes", "backlit_sphere.json")) as f:
        scene = json.load(f)
    scene["image"]["width"], scene["image"]["height"] = width, height
    scene["materials"]["marble"]["translucency"]["thickness"] = thickness
    scene["objects"] = [{"mesh": mesh, "material": "marble"}]
    return scene


def measure(ltrender, work, rings, rays, map_size, width, height):
    """One row: the vertex count and compare's covered-pixel figures for R = rings."""
    d = os.path.join(work, f"r{rings}")
    run([ltrender, "meshgen", "--uvsphere", str(rings), d])
    mesh = os.path.join(d, "uvsphere.ply")
    bake = ["--rays", str(rays), "--seed", "1"]
    run([ltrender, "bake", mesh, "-o", os.path.join(d, "vertex.ply")] + bake)
    run([ltrender, "bake", mesh, "--texture", map_size, "-o", os.path.join(d, "map.png")] + bake)
    images = {}
    for name, thickness, scene_mesh in (("vertex", "vertex", "vertex.ply"),
                                        ("map", {"texture": "map.png"}, "uvsphere.ply")):
        scene_file = os.path.join(d, name + ".json")
        with open(scene_file, "w") as f:
            json.dump(scene_with(thickness, scene_mesh, width, height), f, indent=1)
        images[name] = os.path.join(d, name + ".exr")
        run([ltrender, "render", scene_file, "--path", "reference", "-o", images[name]])
    # A measurement, not a verdict: every pixel may exceed compare's 1 LSB without failing it.
    covered = json.loads(run([ltrender, "compare", "--json", "--fail-percent", "100",
                              images["vertex"], images["map"]]))
    covered = covered["covered"]
    return {"rings": rings, "vertices": ply_vertex_count(mesh), "max_lsb": covered["max_lsb"],
            "mean_lsb": covered["mean_lsb"], "p99_lsb": covered["p99_lsb"]}


def markdown(rows, args, seconds):
    lines = [
        f"Map vs vertex colours on the UV sphere (`scripts/map_vs_vertex.py`: {args.rays} rays, "
        f"map {args.map}, {args.width}x{args.height}, reference against reference, covered "
        f"pixels; {seconds:.1f} s)",
        "",
        "| rings R | vertices | max LSB | mean LSB | p99 LSB |",
        "|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(f"| {r['rings']} | {r['vertices']} | {r['max_lsb']:.2f} | "
                     f"{r['mean_lsb']:.3f} | {r['p99_lsb']:.2f} |")
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bin", default=os.path.join(REPO, "build", "ltrender"), help="ltrender")
    p.add_argument("--rings", default="4,8,16,32,64", help="comma-separated R of --uvsphere")
    p.add_argument("--rays", type=int, default=256, help="rays per vertex and per texel")
    p.add_argument("--map", default="512x256", help="the map bake's WxH")
    p.add_argument("--width", type=int, default=640)
    p.add_argument("--height", type=int, default=480)
    p.add_argument("--table", help="also write the markdown table to this file")
    p.add_argument("--json", action="store_true", help="print the rows as JSON instead")
    p.add_argument("--keep", help="work in this folder and keep it (default: a temporary one)")
    args = p.parse_args()
    rings = [int(r) for r in args.rings.split(",")]
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="map_vs_vertex_") as tmp:
        work = args.keep or tmp
        os.makedirs(work, exist_ok=True)
        rows = [measure(args.bin, work, r, args.rays, args.map, args.width, args.height)
                for r in rings]
    seconds = time.monotonic() - start
    if args.json:
        print(json.dumps(rows, indent=1))
    table = markdown(rows, args, seconds)
    if not args.json:
        print(table, end="")
    if args.table:
        os.makedirs(os.path.dirname(os.path.abspath(args.table)), exist_ok=True)
        with open(args.table, "w") as f:
            f.write(table)


if __name__ == "__main__":
    main()
