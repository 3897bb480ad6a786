#!/usr/bin/env python3
"""gltf_to_glb.py IN.gltf OUT.glb
Packs a .gltf and the buffers and images it references by relative URI (or data: URI) into one GLB: every
buffer's bytes and every image's file become bufferViews of the single BIN chunk, so that scripts which edit
GLBs (../shared/peers/three/add_lights.py, add_ground.py) work on the Khronos sample models shipped as .gltf."""
import base64, json, mimetypes, os, struct, sys
from urllib.parse import unquote

src, dst = sys.argv[1], sys.argv[2]
folder = os.path.dirname(os.path.abspath(src))
js = json.load(open(src, encoding='utf-8'))


def read_uri(uri):
    if uri.startswith('data:'):
        return base64.b64decode(uri.split(',', 1)[1])
    path = os.path.join(folder, unquote(uri))
    if not os.path.isfile(path):
        sys.exit('gltf_to_glb.py: %s: %s is missing' % (src, path))
    return open(path, 'rb').read()


blob = bytearray()


def append(data):
    while len(blob) % 4:
        blob.append(0)
    at = len(blob)
    blob.extend(data)
    return at


offsets = [append(read_uri(b['uri'])) if 'uri' in b else None for b in js.get('buffers', [])]
for view in js.get('bufferViews', []):
    start = offsets[view['buffer']]
    assert start is not None, 'a buffer without uri (already a GLB?)'
    view['buffer'] = 0
    view['byteOffset'] = view.get('byteOffset', 0) + start
for image in js.get('images', []):
    if 'uri' not in image:
        continue
    data = read_uri(image['uri'])
    mime = image.get('mimeType') or mimetypes.guess_type(image['uri'])[0] or 'image/png'
    js.setdefault('bufferViews', []).append({'buffer': 0, 'byteOffset': append(data), 'byteLength': len(data)})
    image['bufferView'] = len(js['bufferViews']) - 1
    image['mimeType'] = mime
    del image['uri']
while len(blob) % 4:
    blob.append(0)
js['buffers'] = [{'byteLength': len(blob)}]
j = json.dumps(js, separators=(',', ':')).encode()
j += b' ' * (-len(j) % 4)
body = struct.pack('<II', len(j), 0x4E4F534A) + j + struct.pack('<II', len(blob), 0x004E4942) + bytes(blob)
open(dst, 'wb').write(b'glTF' + struct.pack('<II', 2, 12 + len(body)) + body)
print(dst)
