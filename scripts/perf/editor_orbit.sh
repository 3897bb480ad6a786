#!/usr/bin/env bash
# editor_orbit.sh [BUILD_DIR]: the editor's own frame rate while orbiting (issue 40) on the heavy scene:
# DamagedHelmet on a visible ground, 8 shadow-casting spots (scripts/perf/ring_rig.py) and studio.exr, a
# 1280x720 viewport. Runs build/dev/tests/app/editor_orbit with "While moving" at full size (0) and at 30
# frames per second, ROUNDS times each, interleaved, and prints one table row per run with the load
# average before and after. Needs ../shared (the helmet and the environment) and an X display with
# OpenGL: run it under xvfb-run, e.g.
#   xvfb-run -a -s "-screen 0 1920x1080x24" scripts/perf/editor_orbit.sh
# Environment: ROUNDS (2), SECONDS_EACH (6), RATES ("0 30"), MODEL, ENV, SHADER_CACHE (warm: Mesa's shader
# cache in a fresh folder, filled by one untimed run first, as on a user's machine after the first use of
# a scene's programs; cold: no cache, so the first moving frame also compiles the moving path's programs,
# ~1-3 s on llvmpipe).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build/dev}"
shared="$root/../shared"
model="${MODEL:-$shared/models/bench/helmet_1pt.glb}"
envfile="${ENV:-$shared/environments/studio.exr}"
rounds="${ROUNDS:-2}"
seconds="${SECONDS_EACH:-6}"
rates="${RATES:-0 30}"
tool="$build/tests/app/editor_orbit"
[ -x "$tool" ] || { echo "editor_orbit.sh: no $tool (build the dev preset)" >&2; exit 1; }
[ -f "$model" ] && [ -f "$envfile" ] || { echo "editor_orbit.sh: needs $model and $envfile" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
python3 "$root/scripts/perf/ring_rig.py" "$work/ring8.json" 8 --environment "$envfile" >/dev/null
export LIBGL_ALWAYS_SOFTWARE=1
if [ "${SHADER_CACHE:-warm}" = cold ]; then
    export MESA_SHADER_CACHE_DISABLE=true
else
    export MESA_SHADER_CACHE_DIR="$work/mesa-cache"
    "$tool" "$model" "$work/ring8.json" --seconds 2 --moving-fps 30 >/dev/null 2>&1 || true
    "$tool" "$model" "$work/ring8.json" --seconds 2 --moving-fps 0 >/dev/null 2>&1 || true
fi
echo "Shader cache: ${SHADER_CACHE:-warm}"
echo "| round | While moving | fps | frame ms (median / max) | input ms (median / max) | drawn at (frames) | still frame ms | load before / after |"
echo "|---|---|---:|---|---|---|---:|---|"
for round in $(seq 1 "$rounds"); do
    for rate in $rates; do
        before="$(cut -d' ' -f1 /proc/loadavg)"
        line="$("$tool" "$model" "$work/ring8.json" --seconds "$seconds" --moving-fps "$rate" 2>/dev/null | tail -n1)"
        after="$(cut -d' ' -f1 /proc/loadavg)"
        python3 - "$round" "$rate" "$before" "$after" "$line" <<'PY'
import json, sys
r, rate, before, after, line = sys.argv[1:6]
d = json.loads(line)
drawn = ', '.join('%s (%d)' % (k, v) for k, v in sorted(d['drawn'].items(), key=lambda kv: -kv[1]))
print('| %s | %s | %.1f | %.0f / %.0f | %.0f / %.0f | %s | %.0f | %s / %s |' % (
    r, 'full size' if rate == '0' else rate + ' fps', d['fps'], d['frame_ms_median'], d['frame_ms_max'],
    d['input_ms_median'], d['input_ms_max'], drawn, d['still_ms'], before, after))
PY
    done
done
