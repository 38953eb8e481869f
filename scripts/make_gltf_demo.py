#!/usr/bin/env python3
# The glTF demo scene (issue 14): meshes/blob_baked.ply (binary PLY, double x/y/z, float normals,
# uchar colours, as ltrender bake writes it) as a .glb with KHR_materials_volume,
# KHR_materials_diffuse_transmission, KHR_lights_punctual and a camera. Deterministic: rerun with
#   scripts/make_gltf_demo.py meshes/blob_baked.ply scenes/gltf/blob.glb
import struct, json, math, sys
src, out = sys.argv[1], sys.argv[2]
data = open(src, 'rb').read()
hdr_end = data.index(b'end_header\n') + len(b'end_header\n')
header = data[:hdr_end].decode()
nv = int(header.split('element vertex ')[1].split()[0])
nf = int(header.split('element face ')[1].split()[0])
off = hdr_end
pos, nrm, col = [], [], []
for i in range(nv):
    x, y, z, nx, ny, nz, r, g, b = struct.unpack_from('<dddfffBBB', data, off); off += 24 + 12 + 3
    pos += [x, y, z]; nrm += [nx, ny, nz]; col += [r, g, b]
idx = []
for i in range(nf):
    n = data[off]; off += 1
    idx += list(struct.unpack_from('<%di' % n, data, off)); off += 4 * n
bin_ = b''
views, accs = [], []
def add(fmt, vals, ctype, typ, count, normalized=False, mn=None, mx=None):
    global bin_
    while len(bin_) % 4: bin_ += b'\0'
    o = len(bin_)
    bin_ += struct.pack('<%d%s' % (len(vals), fmt), *vals)
    views.append({"buffer": 0, "byteOffset": o, "byteLength": len(bin_) - o})
    a = {"bufferView": len(views) - 1, "componentType": ctype, "type": typ, "count": count}
    if normalized: a["normalized"] = True
    if mn: a["min"], a["max"] = mn, mx
    accs.append(a)
    return len(accs) - 1
mn = [min(pos[i::3]) for i in range(3)]; mx = [max(pos[i::3]) for i in range(3)]
p = add('f', pos, 5126, "VEC3", nv, mn=mn, mx=mx)
n = add('f', nrm, 5126, "VEC3", nv)
c = add('B', col, 5121, "VEC3", nv, True)
i = add('I', idx, 5125, "SCALAR", len(idx))
q = lambda axis, deg: [axis[0]*math.sin(math.radians(deg)/2), axis[1]*math.sin(math.radians(deg)/2), axis[2]*math.sin(math.radians(deg)/2), math.cos(math.radians(deg)/2)]
doc = {
 "asset": {"version": "2.0", "generator": "ltrender issue 14 demo"},
 "extensionsUsed": ["KHR_materials_volume", "KHR_materials_diffuse_transmission", "KHR_lights_punctual"],
 "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3]}],
 "nodes": [
   {"name": "Blob", "mesh": 0, "rotation": q((0, 1, 0), 20)},
   {"name": "Back", "rotation": q((0, 1, 0), 170), "extensions": {"KHR_lights_punctual": {"light": 0}}},
   {"name": "Fill", "translation": [1.5, 1.0, 2.0], "extensions": {"KHR_lights_punctual": {"light": 1}}},
   {"name": "EyeNode", "translation": [0, 0, 4], "camera": 0}],
 "cameras": [{"name": "front", "type": "perspective", "perspective": {"yfov": 0.698, "aspectRatio": 1.3333, "znear": 0.1, "zfar": 100}}],
 "materials": [{"name": "jade", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.85, 0.65, 1], "metallicFactor": 0, "roughnessFactor": 0.6},
   "extensions": {"KHR_materials_volume": {"thicknessFactor": 0.4, "attenuationDistance": 0.8, "attenuationColor": [0.5, 0.9, 0.6]},
                  "KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": 0.1, "diffuseTransmissionColorFactor": [0.9, 1, 0.9]}},
   "extras": {"ltrender": {"power": 6, "distortion": 0.25}}}],
 "meshes": [{"name": "blob", "primitives": [{"attributes": {"POSITION": p, "NORMAL": n, "COLOR_0": c}, "indices": i, "material": 0}]}],
 "extensions": {"KHR_lights_punctual": {"lights": [
   {"name": "back", "type": "directional", "intensity": 4.0, "color": [1, 0.95, 0.9], "extras": {"ltrender": {"scale": 2}}},
   {"name": "fill", "type": "point", "intensity": 6.0, "range": 8, "color": [0.5, 0.55, 0.6]}]}},
 "accessors": accs, "bufferViews": views, "buffers": [{"byteLength": len(bin_), "uri": "blob.bin"}],
}
doc2 = dict(doc); doc2["buffers"] = [{"byteLength": len(bin_)}]
j = json.dumps(doc2).encode()
while len(j) % 4: j += b' '
b = bin_
while len(b) % 4: b += b'\0'
glb = b'glTF' + struct.pack('<II', 2, 12 + 8 + len(j) + 8 + len(b)) + struct.pack('<II', len(j), 0x4E4F534A) + j + struct.pack('<II', len(b), 0x004E4942) + b
open(out, 'wb').write(glb)
print(nv, nf, len(glb))
