#!/usr/bin/env python3
"""Writes scenes/hard/*.json: one scene per hard case of model.md. Rerun after editing; the
scenes are data, this is how they were made. Light levels keep most pixels below 1 so the cases
are judged on real gradients, not on saturated white (saturating_scale is the exception)."""
import json
import os

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "hard")


def scene(name, materials, lights, objects, camera=None, ambient=(0.02, 0.02, 0.02), size=(160, 120)):
    cam = camera or {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0],
                     "projection": "perspective", "fov_y_deg": 40, "near": 0.1, "far": 100}
    s = {"image": {"width": size[0], "height": size[1], "background": [0, 0, 0]}, "camera": cam,
         "ambient_light": list(ambient), "materials": materials, "lights": lights, "objects": objects}
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        f.write(json.dumps(s, indent=2) + "\n")


def tr(power=4, distortion=0.2, ambient=0.05, thickness=0.8, **kw):
    d = {"power": power, "distortion": distortion, "ambient": ambient, "thickness": thickness}
    d.update(kw)
    return d


def mat(**kw):
    return {"albedo": [0.6, 0.6, 0.6], "translucency": tr(**kw)}


BACK = {"type": "directional", "direction": [0.2, 0.1, 1], "color": [1, 1, 1], "intensity": 0.7,
        "translucency_scale": 1.5}
FRONT = {"type": "directional", "direction": [-0.3, -0.2, -1], "color": [1, 1, 1], "intensity": 0.4,
         "translucency_scale": 0.5}
SPHERE = "../../meshes/sphere_s3.ply"
one = [{"mesh": SPHERE, "material": "m"}]
pair = [{"mesh": SPHERE, "material": "m", "transform": {"translate": [-1.1, 0, 0]}},
        {"mesh": SPHERE, "material": "n", "transform": {"translate": [1.1, 0, 0]}}]

# 0^0: p = 0, d = 0, front-lit so t = 0 over most of the visible sphere.
scene("zero_pow_zero", {"m": mat(power=0, distortion=0, ambient=0)}, [FRONT, BACK], one)
scene("power_128", {"m": mat(power=128)}, [BACK, FRONT], one)
scene("power_1024", {"m": mat(power=1024)}, [BACK, FRONT], one)
scene("power_fractional", {"m": mat(power=2.37)}, [BACK, FRONT], one)
scene("distortion_large", {"m": mat(distortion=3.5), "n": mat(distortion=3.5, normalize_distorted_light=True)},
      [BACK, FRONT], pair)
scene("distortion_negative", {"m": mat(distortion=-1.5), "n": mat(distortion=-1.0, normalize_distorted_light=True)},
      [BACK, FRONT], pair)
scene("zero_normals", {"m": mat()}, [BACK, FRONT], [{"mesh": "../../meshes/hard/zero_normals.ply", "material": "m"}])
scene("nonunit_normals", {"m": mat()}, [BACK, FRONT], [{"mesh": "../../meshes/hard/nonunit_normals.ply", "material": "m"}])
scene("degenerate_triangles", {"m": mat()}, [BACK, FRONT], [{"mesh": "../../meshes/hard/degenerate.ply", "material": "m"}])
# A point light exactly on the quad's centre vertex with kc = 0: distance 0 and a zero denominator.
scene("point_light_at_vertex", {"m": mat()},
      [{"type": "point", "position": [0, 0, 0], "color": [1, 1, 1], "intensity": 0.05, "translucency_scale": 2,
        "attenuation": {"constant": 0, "linear": 0, "quadratic": 1}}],
      [{"mesh": "../../meshes/quad.ply", "material": "m"}])
scene("light_inside_mesh", {"m": mat(power=3, distortion=0.3)},
      [{"type": "point", "position": [0, 0, 0], "color": [1, 0.8, 0.6], "intensity": 1, "translucency_scale": 1.5,
        "attenuation": {"constant": 1, "linear": 0, "quadratic": 1}}], one)
scene("saturating_scale", {"m": mat(power=2, ambient=0.5)}, [dict(BACK, translucency_scale=40), FRONT], one)
scene("thickness_zero_and_one", {"m": mat(thickness=0), "n": mat(thickness=1)}, [BACK, FRONT], pair)
scene("coordinates_1e6", {"m": mat()},
      [BACK, FRONT, {"type": "point", "position": [1000001.5, 1000001.0, 1000002.0], "color": [1, 1, 1],
                     "intensity": 0.5, "translucency_scale": 1,
                     "attenuation": {"constant": 1, "linear": 0, "quadratic": 0.5}}],
      [{"mesh": "../../meshes/hard/far_1e6.ply", "material": "m"}],
      camera={"eye": [1000000, 1000000, 1000004], "target": [1000000, 1000000, 1000000], "up": [0, 1, 0],
              "projection": "perspective", "fov_y_deg": 40, "near": 0.1, "far": 100})
scene("coordinates_1e-6", {"m": mat()},
      [BACK, FRONT, {"type": "point", "position": [1.5e-6, 1e-6, 2e-6], "color": [1, 1, 1], "intensity": 0.5,
                     "translucency_scale": 1, "attenuation": {"constant": 1, "linear": 0, "quadratic": 0}}],
      [{"mesh": "../../meshes/hard/tiny_1e-6.ply", "material": "m"}],
      camera={"eye": [0, 0, 4e-6], "target": [0, 0, 0], "up": [0, 1, 0], "projection": "perspective",
              "fov_y_deg": 40, "near": 1e-7, "far": 1e-4})
