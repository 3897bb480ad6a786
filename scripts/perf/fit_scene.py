#!/usr/bin/env python3
"""fit_scene.py IN.glb OUT.glb [RADIUS]
Writes a copy of a GLB whose default scene sits under one new root node that centres its bounds on the origin
and scales them to a bounding sphere of RADIUS (default 1.5), so that add_lights.py's ring of lights (radius
2.5) and camera (z = 4.5) frame any model: the Khronos sample models range from 0.0007 units
(MetalRoughSpheresNoTextures) to hundreds. Bounds: every mesh's POSITION min/max through its node's world
transform (translation, rotation, scale or matrix)."""
import json, math, struct, sys

src, dst = sys.argv[1], sys.argv[2]
radius = float(sys.argv[3]) if len(sys.argv) > 3 else 1.5
b = open(src, 'rb').read()
assert b[:4] == b'glTF'
off, js, bin_ = 12, None, b''
while off < len(b):
    ln, typ = struct.unpack('<II', b[off:off + 8])
    data = b[off + 8:off + 8 + ln]
    if typ == 0x4E4F534A:
        js = json.loads(data)
    elif typ == 0x004E4942:
        bin_ = data
    off += 8 + ln


def mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def local(node):
    if 'matrix' in node:
        m = node['matrix']
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    t = node.get('translation', [0, 0, 0])
    x, y, z, w = node.get('rotation', [0, 0, 0, 1])
    s = node.get('scale', [1, 1, 1])
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[i][0] * s[0], r[i][1] * s[1], r[i][2] * s[2], t[i]] for i in range(3)] + [[0, 0, 0, 1]]


lo, hi = [math.inf] * 3, [-math.inf] * 3


def visit(index, parent):
    node = js['nodes'][index]
    world = mul(parent, local(node))
    if 'mesh' in node:
        for prim in js['meshes'][node['mesh']]['primitives']:
            acc = js['accessors'][prim['attributes']['POSITION']]
            mn, mx = acc['min'], acc['max']
            for corner in range(8):
                p = [mx[k] if corner >> k & 1 else mn[k] for k in range(3)] + [1]
                q = [sum(world[i][k] * p[k] for k in range(4)) for i in range(3)]
                for k in range(3):
                    lo[k], hi[k] = min(lo[k], q[k]), max(hi[k], q[k])
    for child in node.get('children', []):
        visit(child, world)


scene = js['scenes'][js.get('scene', 0)]
identity = [[float(i == j) for j in range(4)] for i in range(4)]
for n in scene['nodes']:
    visit(n, identity)
centre = [(lo[k] + hi[k]) / 2 for k in range(3)]
half = math.sqrt(sum((hi[k] - lo[k]) ** 2 for k in range(3))) / 2
scale = radius / half if half > 0 else 1.0
js['nodes'].append({'name': 'fit', 'children': scene['nodes'], 'scale': [scale] * 3,
                    'translation': [-c * scale for c in centre]})
scene['nodes'] = [len(js['nodes']) - 1]
j = json.dumps(js, separators=(',', ':')).encode()
j += b' ' * (-len(j) % 4)
bin_ += b'\0' * (-len(bin_) % 4)
out = struct.pack('<II', len(j), 0x4E4F534A) + j
if bin_:
    out += struct.pack('<II', len(bin_), 0x004E4942) + bin_
open(dst, 'wb').write(b'glTF' + struct.pack('<II', 2, 12 + len(out)) + out)
print(dst, 'scale', scale)
