#!/usr/bin/env python3
"""crop_png.py IN.png OUT.png W H — the top-left W×H pixels of an 8-bit RGB/RGBA PNG (no dependencies).
three.js's harness screenshots the whole 1280×720 page; a smaller canvas sits at its top-left corner."""
import struct, sys, zlib

src, dst, W, H = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
d = open(src, 'rb').read()
assert d[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
off, idat, hdr = 8, b'', None
while off < len(d):
    n, t = struct.unpack('>I4s', d[off:off + 8])
    body = d[off + 8:off + 8 + n]
    if t == b'IHDR':
        hdr = struct.unpack('>IIBBBBB', body)
    elif t == b'IDAT':
        idat += body
    off += 12 + n
w, h, depth, ctype, _, _, interlace = hdr
assert depth == 8 and ctype in (2, 6) and interlace == 0, 'only 8-bit RGB/RGBA, not interlaced'
bpp = 3 if ctype == 2 else 4
raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], (prev[i - bpp] if i >= bpp else 0)
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line)
    prev = line
out = b''.join(b'\0' + bytes(rows[y][:W * bpp]) for y in range(H))
def chunk(t, body): return struct.pack('>I', len(body)) + t + body + struct.pack('>I', zlib.crc32(t + body))
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', W, H, 8, ctype, 0, 0, 0))
png += chunk(b'IDAT', zlib.compress(out, 9)) + chunk(b'IEND', b'')
open(dst, 'wb').write(png)
