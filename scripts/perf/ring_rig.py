#!/usr/bin/env python3
"""ring_rig.py OUT.json N [--environment FILE.exr] [--no-shadows]
Writes a LightRig rig of N shadow-casting spots on the ring ../shared/peers/three/add_lights.py uses (radius
2.5 around the origin, heights 1.2 sin(3.1 i), aimed at the origin, cones 0.3/0.6 rad), physically based,
on a visible ground, optionally lit by an environment image: the editor's heavy orbit scene of issue 40
with the DamagedHelmet (scripts/perf/editor_orbit.sh)."""
import colorsys, json, math, os, sys

args = [a for a in sys.argv[1:]]
env = None
if '--environment' in args:
    i = args.index('--environment'); env = os.path.abspath(args[i + 1]); del args[i:i + 2]
shadows = '--no-shadows' not in args
args = [a for a in args if a != '--no-shadows']
out, n = args[0], int(args[1])
lights = []
for i in range(n):
    r, g, b = colorsys.hsv_to_rgb(i / max(n, 1), 0.35, 1.0)
    a = 2 * math.pi * i / n
    pos = [2.5 * math.sin(a), 1.2 * math.sin(3.1 * i) if n > 1 else 1.0, 2.5 * math.cos(a) if n > 1 else 2.5]
    length = math.sqrt(sum(c * c for c in pos))
    light = {'name': 'Spot %d' % (i + 1), 'type': 'spot', 'color': [round(c, 4) for c in (r, g, b)],
             'intensity': round(40.0 / n, 4), 'position': [round(c, 4) for c in pos],
             'direction': [round(-c / length, 4) for c in pos], 'falloff': {'model': 'inverse-square'},
             'cone': {'model': 'smooth', 'inner': round(math.degrees(0.3), 3), 'outer': round(math.degrees(0.6), 3)}}
    if shadows: light['shadow'] = {'enabled': True, 'size': 0.1}
    lights.append(light)
rig = {'format': 'lightrig', 'version': 4, 'name': '%d spots on a ring' % n, 'space': 'world',
       'shading': {'model': 'pbr'}, 'ground': {'mode': 'visible'}, 'lights': lights}
if env: rig['environment'] = {'source': 'image', 'file': env, 'background': 'visible'}
with open(out, 'w') as f:
    json.dump(rig, f, indent=2)
print(out, n, 'spots', 'with shadows' if shadows else '', env or '')
