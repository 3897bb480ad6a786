# localize.py IN.glb OUT.glb RANGE [N]: lights on a Fibonacci sphere of radius 1 around the origin, each with
# the given glTF range (inverse-square windowed), keeping only the first N lights (default: all).
import json, math, struct, sys
src, dst, rng = sys.argv[1], sys.argv[2], float(sys.argv[3])
b = open(src, 'rb').read(); off = 12; chunks = []
while off < len(b):
    ln, typ = struct.unpack('<II', b[off:off+8]); chunks.append([typ, b[off+8:off+8+ln]]); off += 8 + ln
js = json.loads(chunks[0][1])
lights = js['extensions']['KHR_lights_punctual']['lights']
n = int(sys.argv[4]) if len(sys.argv) > 4 else len(lights)
idx = 0
for nd in js['nodes']:
    e = nd.get('extensions', {}).get('KHR_lights_punctual')
    if e is None: continue
    i = e['light']; k = (i + 0.5) / max(n, 1)
    y = 1 - 2 * k; r = math.sqrt(max(0, 1 - y * y)); a = i * math.pi * (3 - math.sqrt(5))
    nd['translation'] = [1.05 * r * math.cos(a), 1.05 * y, 1.05 * r * math.sin(a)]
for L in lights: L['range'] = rng; L['intensity'] = 2.0
if n < len(lights):  # drop the light nodes beyond n
    keep = [nd for nd in js['nodes']]
    for nd in keep:
        e = nd.get('extensions', {}).get('KHR_lights_punctual')
        if e is not None and e['light'] >= n: del nd['extensions']; nd['name'] += '_off'
    js['extensions']['KHR_lights_punctual']['lights'] = lights[:n]
j = json.dumps(js, separators=(',', ':')).encode(); j += b' ' * (-len(j) % 4)
out = struct.pack('<II', len(j), 0x4E4F534A) + j
for typ, data in chunks[1:]: out += struct.pack('<II', len(data), typ) + data
open(dst, 'wb').write(b'glTF' + struct.pack('<II', 2, 12 + len(out)) + out)
print(dst, n, 'lights, range', rng)
