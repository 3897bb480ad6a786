# sphere.py OUT.ply STACKS SLICES: binary little-endian PLY UV sphere, 2*STACKS*SLICES triangles (about).
import struct, math, sys
out, st, sl = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
verts = bytearray()
for i in range(st + 1):
    t = math.pi * i / st; y = math.cos(t); r = math.sin(t)
    for j in range(sl):
        p = 2 * math.pi * j / sl
        verts += struct.pack('<3f', r * math.cos(p), y, r * math.sin(p))
faces = bytearray()
nf = 0
for i in range(st):
    for j in range(sl):
        a = i * sl + j; b = i * sl + (j + 1) % sl; c = a + sl; d = b + sl
        if i > 0: faces += struct.pack('<B3i', 3, a, c, b); nf += 1
        if i < st - 1: faces += struct.pack('<B3i', 3, b, c, d); nf += 1
nv = (st + 1) * sl
hdr = f"ply\nformat binary_little_endian 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\nproperty float z\nelement face {nf}\nproperty list uchar int vertex_indices\nend_header\n"
open(out, 'wb').write(hdr.encode() + verts + faces)
print(out, nv, 'vertices', nf, 'triangles')
