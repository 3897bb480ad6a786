#!/usr/bin/env python3
"""Writes the small hand-made models of tests/model (CC0, made for LightRig). Run from anywhere:
python3 tests/data/model/make_test_data.py. Only the standard library is used."""
import base64, json, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png_bytes(rows):
    """rows: list of rows of (r, g, b, a) tuples, top row first."""
    h, w = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(c for px in row for c in px) for row in rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
    return data + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")


def png(path, rows):
    open(os.path.join(HERE, path), "wb").write(png_bytes(rows))


def text(path, s):
    open(os.path.join(HERE, path), "w", newline="\n").write(s)


# 2x2 texture: red green / blue white (top row first), to check the UV origin.
png("checker.png", [[(255, 0, 0, 255), (0, 255, 0, 255)], [(0, 0, 255, 255), (255, 255, 255, 255)]])
# Flat tangent-space normal map.
png("normal.png", [[(128, 128, 255, 255)] * 2] * 2)

# A quad in the XY plane facing +Z; OBJ UVs have their origin at the bottom-left of the image.
text("quad.mtl", """# CC0, LightRig test data
newmtl checker
Kd 0.5 0.25 1.0
Ks 0.2 0.2 0.2
Ns 50
map_Kd checker.png
""")
text("quad.obj", """# CC0, LightRig test data: a textured quad facing +Z
mtllib quad.mtl
v -1 -1 0
v 1 -1 0
v 1 1 0
v -1 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
usemtl checker
f 1/1/1 2/2/1 3/3/1 4/4/1
""")

# A regular tetrahedron, outward-facing counter-clockwise facets.
tv = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
faces = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]
def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
stl = "solid tetra\n"
for f in faces:
    a, b, c = (tv[i] for i in f)
    n = cross(sub(b, a), sub(c, a))
    assert sum(x * y for x, y in zip(n, a)) > 0  # outward
    l = sum(x * x for x in n) ** 0.5
    stl += "  facet normal %g %g %g\n    outer loop\n" % tuple(x / l for x in n)
    for v in (a, b, c):
        stl += "      vertex %g %g %g\n" % v
    stl += "    endloop\n  endfacet\n"
text("tetra.stl", stl + "endsolid tetra\n")

# A coloured square, two triangles.
text("colors.ply", """ply
format ascii 1.0
comment CC0, LightRig test data: vertex colours
element vertex 4
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
property uchar alpha
element face 2
property list uchar int vertex_indices
end_header
0 0 0 255 0 0 255
1 0 0 0 255 0 255
1 1 0 0 0 255 255
0 1 0 255 255 255 255
3 0 1 2
3 0 2 3
""")

# glTF: one square mesh (normals, UVs, COLOR_0, normal map), instanced by a scaled child of a translated
# parent and by a mirrored node; a spot light, a directional light and a camera (KHR_lights_punctual).
pos = [(-0.5, -0.5, 0), (0.5, -0.5, 0), (0.5, 0.5, 0), (-0.5, 0.5, 0)]
nrm = [(0, 0, 1)] * 4
uv = [(0, 1), (1, 1), (1, 0), (0, 0)]  # glTF: origin at the top-left
col = [(1, 0, 0, 1), (0, 1, 0, 1), (0, 0, 1, 1), (1, 1, 1, 0.5)]
idx = [0, 1, 2, 0, 2, 3]
blob = b"".join(struct.pack("<3f", *p) for p in pos) + b"".join(struct.pack("<3f", *n) for n in nrm)
blob += b"".join(struct.pack("<2f", *t) for t in uv) + b"".join(struct.pack("<4f", *c) for c in col)
blob += struct.pack("<6H", *idx) + b"\0\0"
views = [(0, 48), (48, 48), (96, 32), (128, 64), (192, 12)]
gltf = {
    "asset": {"version": "2.0", "generator": "LightRig make_test_data.py", "copyright": "CC0"},
    "extensionsUsed": ["KHR_lights_punctual"],
    "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "spot", "name": "spot", "color": [1.0, 0.5, 0.25], "intensity": 8.0, "range": 20.0,
         "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
        {"type": "directional", "name": "sun", "color": [0.5, 1.0, 1.0], "intensity": 3.0}]}},
    "scene": 0,
    "scenes": [{"nodes": [0, 3, 4, 5]}],
    "nodes": [
        {"name": "parent", "translation": [10, 0, 0], "children": [1, 2]},
        {"name": "child", "mesh": 0, "scale": [2, 2, 2]},
        {"name": "mirror", "mesh": 0, "scale": [-1, 1, 1], "translation": [0, 5, 0]},
        {"name": "spotNode", "translation": [0, 0, 5], "rotation": [0.7071067811865476, 0, 0, 0.7071067811865476],
         "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "sunNode", "rotation": [-0.3826834323650898, 0, 0, 0.9238795325112867],
         "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"name": "camNode", "translation": [1, 2, 3], "camera": 0}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "aspectRatio": 2.0, "znear": 0.1, "zfar": 50}}],
    "meshes": [{"name": "square", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2,
                                                                  "COLOR_0": 3}, "indices": 4, "material": 0}]}],
    "materials": [{"name": "bumpy", "doubleSided": True, "emissiveFactor": [0.1, 0.2, 0.3],
                   "normalTexture": {"index": 0},
                   "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0]}}],
    "textures": [{"source": 0}],
    "images": [{"uri": "normal.png"}],
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": l} for o, l in views],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC4"},
        {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"}],
}
text("scene.gltf", json.dumps(gltf, indent=1) + "\n")

# glTF metal-rough materials (issue 13): one square with two UV sets, one primitive per material, each
# material referenced in order (Assimp numbers materials in the order primitives reference them).
# Textures are data URIs of distinct sizes, so a test can tell the roles apart by size.
def data_uri(rows):
    return "data:image/png;base64," + base64.b64encode(png_bytes(rows)).decode()

uv1 = [(0.5, 0.5)] * 4
blob = b"".join(struct.pack("<3f", *p) for p in pos) + b"".join(struct.pack("<3f", *n) for n in nrm)
blob += b"".join(struct.pack("<2f", *t) for t in uv) + b"".join(struct.pack("<2f", *t) for t in uv1)
blob += struct.pack("<6H", *idx) + b"\0\0"
views = [(0, 48), (48, 48), (96, 32), (128, 32), (160, 12)]
BC, MR, OC, NM, EM = range(5)
images = [
    [[(255, 0, 0, 255), (0, 255, 0, 255)], [(0, 0, 255, 255), (255, 255, 255, 255)]],  # base colour 2x2
    [[(0, 64, 192, 255), (0, 128, 0, 255), (0, 255, 255, 255)]],                          # metal-rough 3x1
    [[(200, 0, 0, 255)], [(100, 0, 0, 255)], [(50, 0, 0, 255)]],                          # occlusion 1x3
    [[(128, 128, 255, 255)]],                                                             # normal 1x1
    [[(255, 255, 0, 255), (0, 255, 255, 255)], [(0, 0, 0, 255)] * 2, [(9, 9, 9, 255)] * 2],  # emissive 2x3
]
def xf(**k):
    return {"KHR_texture_transform": k}
materials = [
    {"name": "metalRough", "doubleSided": True, "alphaMode": "MASK", "alphaCutoff": 0.3,
     "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.7, 1.0], "metallicFactor": 0.25,
                              "roughnessFactor": 0.75,
                              "metallicRoughnessTexture": {"index": MR, "extensions": xf(offset=[0.5, 0.0])}},
     "normalTexture": {"index": NM, "scale": 0.5},
     "occlusionTexture": {"index": OC, "strength": 0.6, "extensions": xf(scale=[4.0, 4.0])}},
    {"name": "blend", "alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.5, 0.25, 0.4]}},
    {"name": "transformed", "emissiveFactor": [1.0, 0.5, 0.25],
     "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4.0}},
     "pbrMetallicRoughness": {"baseColorTexture": {"index": BC, "extensions": xf(
         offset=[0.25, 0.5], rotation=0.3, scale=[2.0, 3.0])}},
     "emissiveTexture": {"index": EM, "extensions": xf(rotation=-1.2, offset=[-0.125, 0.75])}},
    {"name": "secondUv", "occlusionTexture": {"index": OC, "texCoord": 1},
     "pbrMetallicRoughness": {"baseColorTexture": {"index": BC}}},
    {"name": "outOfRange", "alphaMode": "MASK", "alphaCutoff": -1.0, "emissiveFactor": [1.0, 1.0, 1.0],
     "pbrMetallicRoughness": {"metallicFactor": -0.5, "roughnessFactor": 2.5},
     "occlusionTexture": {"index": OC, "strength": 3.0}},
]
gltf = {
    "asset": {"version": "2.0", "generator": "LightRig make_test_data.py", "copyright": "CC0"},
    "extensionsUsed": ["KHR_texture_transform", "KHR_materials_emissive_strength"],
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "squares", "mesh": 0}],
    "meshes": [{"name": "square", "primitives": [
        {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3}, "indices": 4,
         "material": i} for i in range(len(materials))]}],
    "materials": materials,
    "textures": [{"source": i} for i in range(len(images))],
    "images": [{"uri": data_uri(rows)} for rows in images],
    "buffers": [{"byteLength": len(blob),
                 "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": l} for o, l in views],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"}],
}
text("pbr.gltf", json.dumps(gltf, indent=1) + "\n")

# OBJ materials for the specular/shininess -> metal-rough conversion, MTL's PBR keys (Pr, Pm), and separate
# roughness/metallic maps (map_Pr, map_Pm), which the packed metallic-roughness texture cannot hold.
text("shiny.mtl", """# CC0, LightRig test data: Blinn-Phong and PBR MTL materials
newmtl glossy
Kd 0.5 0.5 0.5
Ks 0.5 0.5 0.5
Ns 98
newmtl authored
Kd 0.8 0.2 0.2
Pr 0.3
Pm 0.8
newmtl matte
Kd 0.2 0.8 0.2
newmtl separateMaps
Kd 0.5 0.5 0.5
Pr 0.5
map_Pr checker.png
map_Pm checker.png
""")
text("shiny.obj", """# CC0, LightRig test data: four triangles, one per material
mtllib shiny.mtl
v 0 0 0
v 1 0 0
v 0 1 0
vn 0 0 1
usemtl glossy
f 1//1 2//1 3//1
usemtl authored
f 1//1 2//1 3//1
usemtl matte
f 1//1 2//1 3//1
usemtl separateMaps
f 1//1 2//1 3//1
""")
