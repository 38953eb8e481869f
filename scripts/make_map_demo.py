#!/usr/bin/env python3
# The thickness-map demo data (issue 13), deterministic: rerun with
#   scripts/make_map_demo.py scenes/maps
# - uv_sphere.glb: a unit UV sphere (48 segments x 24 rings, a seam column of duplicated
#   vertices), equirectangular UVs: u = longitude / 2 pi, v = 0 at the south pole, 1 at the north
#   (OpenGL's convention; written as glTF's TEXCOORD_0 = (u, 1 - v), which ltrender flips back).
# - sphere_thickness.png: 64x32 8-bit grey, smooth bands in u and v (linear data, no sRGB chunk).
# - sphere_rgb.png: 32x16 8-bit RGB, each channel its own smooth pattern.
# - zero_one.png: 8x4 8-bit grey checker of 0 and 255 (thickness zero and one).
# - warm_ramp.png: 16x1 8-bit RGB, an artist's lobe ramp (a warm tint rising with t).
# - albedo_checker.png: 32x16 8-bit RGB, a checker of 4x4-texel cells in two sRGB colours
#   (terracotta and cream): an albedo map (a picture, sRGB; scenes/albedo_checker.json).
import math, struct, sys, zlib, json, os

out = sys.argv[1]


def png(path, w, h, channels, pixel):
    rows = b''
    for y in range(h):
        rows += b'\0' + bytes(v for x in range(w) for v in pixel(x, y))
    def chunk(tag, data):
        c = tag + data
        return struct.pack('>I', len(data)) + c + struct.pack('>I', zlib.crc32(c) & 0xffffffff)
    colour_type = {1: 0, 3: 2}[channels]
    data = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, colour_type, 0, 0, 0))
    data += chunk(b'IDAT', zlib.compress(rows, 9)) + chunk(b'IEND', b'')
    open(os.path.join(out, path), 'wb').write(data)


def byte(v):
    return max(0, min(255, int(round(v * 255))))


# Images are written top row first: image row y holds v = 1 - (y + 0.5) / h.
png('sphere_thickness.png', 64, 32, 1, lambda x, y: [byte(
    0.1 + 0.8 * (0.5 + 0.5 * math.cos(2 * math.pi * 3 * (x + 0.5) / 64)) *
    (0.3 + 0.7 * math.sin(math.pi * (1 - (y + 0.5) / 32))))])
png('sphere_rgb.png', 32, 16, 3, lambda x, y: [
    byte(0.2 + 0.8 * (0.5 + 0.5 * math.cos(2 * math.pi * 2 * (x + 0.5) / 32))),
    byte(0.1 + 0.6 * (1 - (y + 0.5) / 16)),
    byte(0.05 + 0.4 * (0.5 + 0.5 * math.sin(2 * math.pi * (x + 0.5) / 32)))])
png('zero_one.png', 8, 4, 1, lambda x, y: [255 if (x + y) % 2 else 0])
png('warm_ramp.png', 16, 1, 3, lambda x, y: [
    byte(((x / 15) ** 2) * 1.0), byte(((x / 15) ** 3) * 0.8), byte(((x / 15) ** 5) * 0.6)])

png('albedo_checker.png', 32, 16, 3, lambda x, y:
    [196, 98, 60] if (x // 4 + y // 4) % 2 else [236, 226, 204])

# The UV sphere.
seg, rings = 48, 24
pos, nrm, uv, idx = [], [], [], []
for r in range(rings + 1):
    v = r / rings                    # 0 at the south pole
    theta = math.pi * (1 - v)        # polar angle from +Y
    for s in range(seg + 1):
        u = s / seg
        phi = 2 * math.pi * u
        p = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
        pos += p; nrm += p; uv += [u, 1 - v]  # glTF's v grows downwards
for r in range(rings):
    for s in range(seg):
        a = r * (seg + 1) + s; b = a + seg + 1
        if r != rings - 1: idx += [a, a + 1, b + 1]
        if r != 0: idx += [a, b + 1, b]
nv = len(pos) // 3
# One buffer view and accessor per attribute, each 4-byte aligned (glTF 2.0 §3.6.2.4).
attributes = [('f', pos, 5126, "VEC3"), ('f', nrm, 5126, "VEC3"), ('f', uv, 5126, "VEC2"),
              ('I', idx, 5125, "SCALAR")]
bin_, views, accs = b'', [], []
for fmt, vals, ctype, typ in attributes:
    bin_ += b'\0' * (-len(bin_) % 4)
    packed = struct.pack('<%d%s' % (len(vals), fmt), *vals)
    views.append({"buffer": 0, "byteOffset": len(bin_), "byteLength": len(packed)})
    count = len(vals) // {"VEC3": 3, "VEC2": 2, "SCALAR": 1}[typ]
    accs.append({"bufferView": len(views) - 1, "componentType": ctype, "type": typ, "count": count})
    bin_ += packed
accs[0]["min"] = [min(pos[i::3]) for i in range(3)]
accs[0]["max"] = [max(pos[i::3]) for i in range(3)]
P, N, T, I = range(4)
doc = {"asset": {"version": "2.0", "generator": "scripts/make_map_demo.py"},
       "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "name": "sphere"}],
       "meshes": [{"primitives": [{"attributes": {"POSITION": P, "NORMAL": N, "TEXCOORD_0": T},
                                   "indices": I}]}],
       "buffers": [{"byteLength": len(bin_)}], "bufferViews": views, "accessors": accs}
j = json.dumps(doc, separators=(',', ':')).encode()
while len(j) % 4: j += b' '
while len(bin_) % 4: bin_ += b'\0'
glb = b'glTF' + struct.pack('<II', 2, 12 + 8 + len(j) + 8 + len(bin_))
glb += struct.pack('<I', len(j)) + b'JSON' + j + struct.pack('<I', len(bin_)) + b'BIN\0' + bin_
open(os.path.join(out, 'uv_sphere.glb'), 'wb').write(glb)
