#!/bin/bash
# glTF export round trip (issue 17, docs/export.md): `lightrig export` writes each scene with a physically based
# rig's lights, three.js r187 renders the export (../shared/peers/three/run.sh: camera 0, no tone mapping, no
# antialiasing, 1280x720), `lightrig render` renders the source with the same rig (camera 0, clamp, --msaa 0,
# --shading pbr), and tests/render/parity_compare gives the figures over the pixels three.js covers.
# Usage: scripts/perf/export_roundtrip.sh [--rig RIG|--own-lights] [--view NAME] [SCENE.glb...]
#        (default: the pbr-three-point preset on ../shared/models/bench/helmet_1pt.glb and helmet_8spot.glb;
#        --own-lights: the scene's own lights, re-exported; --view: a standard view exported as camera 0)
# Needs a dev build (build/dev: lightrig and parity_compare), xvfb-run and ../shared. Prints one line per
# scene: name, PSNR (dB), mean and max difference (8-bit levels), compared pixels, lights exported.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LIGHTRIG_BUILD:-$root/build/dev}
three=$root/../shared/peers/three/run.sh
[ -x "$three" ] || { echo "export_roundtrip.sh: $three not found (needs ../shared)" >&2; exit 1; }
rigargs=(--rig :/resources/presets/pbr-three-point.json)
viewargs=(--camera-index 0)
exportview=()
while [ $# -gt 0 ]; do
    case "$1" in
    --rig) rigargs=(--rig "$2"); shift 2 ;;
    --own-lights) rigargs=(); shift ;;
    --view) viewargs=(--view "$2"); exportview=(--view "$2"); shift 2 ;;
    *) break ;;
    esac
done
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=("$root"/../shared/models/bench/helmet_{1pt,8spot}.glb)
out=$(mktemp -d /tmp/lightrig-export-roundtrip.XXXXXX)
exports=()
for s in "${scenes[@]}"; do
    name=$(basename "$s" .glb)
    "$build/lightrig" export "$s" "${rigargs[@]}" "${exportview[@]}" -o "$out/export_$name.glb" >"$out/export_$name.out" 2>"$out/export_$name.err"
    exports+=("$out/export_$name.glb")
done
PEERS_OUT=$out FRAMES=${FRAMES:-5} "$three" "${exports[@]}" >"$out/three.jsonl"
printf '%-16s %8s %8s %6s %9s %7s\n' scene psnr_db mean max pixels lights
for s in "${scenes[@]}"; do
    name=$(basename "$s" .glb)
    xvfb-run -a "$build/lightrig" render "$s" "${rigargs[@]}" --shading pbr "${viewargs[@]}" --tonemap clamp \
        --msaa 0 --size 1280x720 -o "$out/lightrig_$name.png" 2>"$out/lightrig_$name.err" >/dev/null
    lights=$(sed -n 's/.*: \([0-9]*\) lights.*/\1/p' "$out/export_$name.out")
    "$build/tests/render/parity_compare" "$out/lightrig_$name.png" "$out/three_angle-gl-egl_export_$name.png" |
        python3 -c "import json,sys; f=json.load(sys.stdin); print('%-16s %8.2f %8.2f %6d %9d %7s' % ('$name', f['psnrDb'], f['meanLevels'], f['maxLevels'], f['pixels'], '$lights'))"
done
echo "images and exports: $out" >&2
