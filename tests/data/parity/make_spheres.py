#!/usr/bin/env python3
"""make_spheres.py OUT.glb — the physically based parity scene (tests/render/tst_parity.cpp).

Three UV spheres (radius 0.5, 32x16) in a row with glTF metal-rough materials (a rough red dielectric, a
polished gold metal, a mid-rough grey dielectric), lit by KHR_lights_punctual lights of all three types
(a point light with a range, a spot, a directional light) and seen by camera 0 (yfov 45°, aspect 4:3).
No textures: it checks the BRDF and the light units, nothing else. three.js's image of it:
    PEERS_OUT=. THREE_OPTS='w=320&h=240' ../../../../shared/peers/three/run.sh spheres.glb
(writes three_angle-gl-egl_spheres.png; committed as three_spheres.png)."""
import json, math, struct, sys

SEG, RINGS, R = 32, 16, 0.5
pos, nrm, idx = [], [], []
for j in range(RINGS + 1):
    v = j / RINGS
    th = v * math.pi
    for i in range(SEG + 1):
        u = i / SEG
        ph = u * 2 * math.pi
        n = (math.sin(th) * math.sin(ph), math.cos(th), math.sin(th) * math.cos(ph))
        nrm.append(n)
        pos.append(tuple(R * c for c in n))
for j in range(RINGS):
    for i in range(SEG):
        a = j * (SEG + 1) + i
        b = a + SEG + 1
        if j != 0:
            idx += [a, b, a + 1]
        if j != RINGS - 1:
            idx += [a + 1, b, b + 1]

blob = b''.join(struct.pack('<3f', *p) for p in pos)
nrm_off = len(blob)
blob += b''.join(struct.pack('<3f', *n) for n in nrm)
idx_off = len(blob)
blob += b''.join(struct.pack('<H', k) for k in idx)
while len(blob) % 4:
    blob += b'\0'
nv = len(pos)

materials = [
    {'name': 'red plastic', 'pbrMetallicRoughness': {'baseColorFactor': [0.8, 0.1, 0.08, 1], 'metallicFactor': 0.0, 'roughnessFactor': 0.55}},
    {'name': 'gold', 'pbrMetallicRoughness': {'baseColorFactor': [1.0, 0.77, 0.34, 1], 'metallicFactor': 1.0, 'roughnessFactor': 0.3}},
    {'name': 'grey', 'pbrMetallicRoughness': {'baseColorFactor': [0.45, 0.45, 0.45, 1], 'metallicFactor': 0.0, 'roughnessFactor': 0.8}},
]
meshes = [{'name': m['name'], 'primitives': [{'attributes': {'POSITION': 0, 'NORMAL': 1}, 'indices': 2, 'material': k}]}
          for k, m in enumerate(materials)]


def look_rotation(pos, target):
    """Quaternion turning the node's -Z towards target (yaw about Y, then pitch about X)."""
    f = [t - p for t, p in zip(target, pos)]
    l = math.sqrt(sum(c * c for c in f))
    fx, fy, fz = (c / l for c in f)
    yaw = math.atan2(-fx, -fz)
    pitch = math.asin(fy)
    cy, sy, cp, sp = math.cos(yaw / 2), math.sin(yaw / 2), math.cos(pitch / 2), math.sin(pitch / 2)
    return [cy * sp, sy * cp, -sy * sp, cy * cp]


lights = [
    {'name': 'key', 'type': 'point', 'color': [1.0, 0.96, 0.9], 'intensity': 25.0, 'range': 30.0},
    {'name': 'spot', 'type': 'spot', 'color': [0.6, 0.75, 1.0], 'intensity': 40.0,
     'spot': {'innerConeAngle': 0.25, 'outerConeAngle': 0.5}},
    {'name': 'sun', 'type': 'directional', 'color': [1.0, 1.0, 1.0], 'intensity': 1.2},
]
spot_pos = [-2.5, 1.0, 2.5]
nodes = [
    {'name': 'camera', 'camera': 0, 'translation': [0, 0.25, 3.5], 'rotation': look_rotation([0, 0.25, 3.5], [0, 0, 0])},
    {'name': 'red', 'mesh': 0, 'translation': [-1.15, 0, 0]},
    {'name': 'gold', 'mesh': 1, 'translation': [0, 0, 0]},
    {'name': 'grey', 'mesh': 2, 'translation': [1.15, 0, 0]},
    {'name': 'key', 'translation': [2.0, 2.0, 3.0], 'extensions': {'KHR_lights_punctual': {'light': 0}}},
    {'name': 'spot', 'translation': spot_pos, 'rotation': look_rotation(spot_pos, [-1.15, 0, 0]),
     'extensions': {'KHR_lights_punctual': {'light': 1}}},
    # The directional light shines down its node's -Z: from the upper left, towards the lower right.
    {'name': 'sun', 'rotation': look_rotation([0, 0, 0], [1.0, -1.0, -0.6]), 'extensions': {'KHR_lights_punctual': {'light': 2}}},
]
gltf = {
    'asset': {'version': '2.0', 'generator': 'LightRig tests/data/parity/make_spheres.py'},
    'extensionsUsed': ['KHR_lights_punctual'],
    'extensions': {'KHR_lights_punctual': {'lights': lights}},
    'scene': 0,
    'scenes': [{'nodes': list(range(len(nodes)))}],
    'nodes': nodes,
    'cameras': [{'type': 'perspective', 'perspective': {'yfov': math.radians(45), 'aspectRatio': 4 / 3, 'znear': 0.1, 'zfar': 50}}],
    'meshes': meshes,
    'materials': materials,
    'buffers': [{'byteLength': len(blob)}],
    'bufferViews': [
        {'buffer': 0, 'byteOffset': 0, 'byteLength': nrm_off, 'target': 34962},
        {'buffer': 0, 'byteOffset': nrm_off, 'byteLength': idx_off - nrm_off, 'target': 34962},
        {'buffer': 0, 'byteOffset': idx_off, 'byteLength': 2 * len(idx), 'target': 34963},
    ],
    'accessors': [
        {'bufferView': 0, 'componentType': 5126, 'count': nv, 'type': 'VEC3', 'min': [-R, -R, -R], 'max': [R, R, R]},
        {'bufferView': 1, 'componentType': 5126, 'count': nv, 'type': 'VEC3'},
        {'bufferView': 2, 'componentType': 5123, 'count': len(idx), 'type': 'SCALAR'},
    ],
}
js = json.dumps(gltf, separators=(',', ':')).encode()
while len(js) % 4:
    js += b' '
out = b'glTF' + struct.pack('<II', 2, 12 + 8 + len(js) + 8 + len(blob))
out += struct.pack('<II', len(js), 0x4E4F534A) + js + struct.pack('<II', len(blob), 0x004E4942) + blob
open(sys.argv[1], 'wb').write(out)
