#!/bin/bash
# Parity with three.js (issue 13, docs/lighting-models.md "Differences from three.js"): each glTF scene is
# rendered by three.js r187 (../shared/peers/three/run.sh: camera 0, the file's own lights, no tone mapping,
# no antialiasing, 1280x720) and by `lightrig render` with the same settings (camera 0, own lights, clamp
# tone map, --msaa 0), then compared over the pixels three.js covers (tests/render/parity.h).
# Usage: scripts/perf/parity.sh [SCENE.glb...]   (default: ../shared/models/bench/helmet_{1,8,64}pt.glb and
#        helmet_8spot.glb). Needs a dev build (build/dev: lightrig and parity_compare) and xvfb-run.
#        ENV=FILE.exr|.hdr (issue 15): both also light the scene with that environment, not shown behind it
#        (three.js: THREE_ENV + env=…, PMREM, its background colour; LightRig: --environment FILE
#        --environment-background color), so the comparison is again over the pixels three.js covers.
# Prints one line per scene: name, PSNR (dB), mean and max difference (8-bit levels), compared pixels.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LIGHTRIG_BUILD:-$root/build/dev}
three=$root/../shared/peers/three/run.sh
[ -x "$three" ] || { echo "parity.sh: $three not found (needs ../shared)" >&2; exit 1; }
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=("$root"/../shared/models/bench/helmet_{1pt,8pt,64pt,8spot}.glb)
out=$(mktemp -d /tmp/lightrig-parity.XXXXXX)
three_env=() lightrig_env=()
if [ -n "${ENV:-}" ]; then
    env_file=$(realpath "$ENV")
    three_env=(THREE_ENV="$env_file" THREE_OPTS="env=scenes/$(basename "$env_file")")
    lightrig_env=(--environment "$env_file" --environment-background color)
fi
env "${three_env[@]}" PEERS_OUT=$out FRAMES=${FRAMES:-5} "$three" "${scenes[@]}" >"$out/three.jsonl"
printf '%-16s %8s %8s %6s %9s\n' scene psnr_db mean max pixels
for s in "${scenes[@]}"; do
    name=$(basename "$s" .glb)
    xvfb-run -a "$build/lightrig" render "$s" --camera-index 0 --tonemap clamp --msaa 0 --size 1280x720 \
        "${lightrig_env[@]}" -o "$out/lightrig_$name.png" 2>"$out/lightrig_$name.err"
    "$build/tests/render/parity_compare" "$out/lightrig_$name.png" "$out/three_angle-gl-egl_$name.png" |
        python3 -c "import json,sys; f=json.load(sys.stdin); print('%-16s %8.2f %8.2f %6d %9d' % ('$name', f['psnrDb'], f['meanLevels'], f['maxLevels'], f['pixels']))"
done
echo "images: $out" >&2
