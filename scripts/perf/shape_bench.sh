#!/bin/bash
# What light shaping costs (issue 39, docs/light-shaping.md): `lightrig bench` on the helmet with each rig of
# scripts/perf/shape/ (a shadowed key spot and a rect softbox on a visible ground), in turn REPEATS times:
#   helmet-plain  no shaping (the baseline);
#   helmet-ies    the key with an IES profile (tests/data/ies/full.ies);
#   helmet-gobo   the key with a gobo (scripts/perf/shape/window.png);
#   helmet-barn   the softbox with barn doors (angle 30, length 0.5).
# Per rig: the median ms/frame of the raster tiers (exact, balanced, fast; --msaa 0, deferred) and the path
# tracer's median seconds per sample, each with its change from helmet-plain.
# Usage: scripts/perf/shape_bench.sh [MODEL.glb]  (default ../shared/models/bench/helmet_1pt.glb). SIZE
#        (1280x720, raster), PATH_SIZE (640x360), FRAMES (30), PATH_SAMPLES (16), REPEATS (3), LIGHTRIG (default
#        build/dev/lightrig). Runs under xvfb-run when there is no DISPLAY.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
lightrig=${LIGHTRIG:-$root/build/dev/lightrig}
model=${1:-$root/../shared/models/bench/helmet_1pt.glb}
[ -f "$model" ] || { echo "shape_bench.sh: $model not found (needs ../shared)" >&2; exit 1; }
[ -x "$lightrig" ] || { echo "shape_bench.sh: $lightrig not built" >&2; exit 1; }
size=${SIZE:-1280x720}
pathSize=${PATH_SIZE:-640x360}
frames=${FRAMES:-30}
samples=${PATH_SAMPLES:-16}
repeats=${REPEATS:-3}
x=()
[ -z "${DISPLAY:-}" ] && x=(xvfb-run -a -s "-screen 0 1920x1080x24 -noreset")
out=$(mktemp -d /tmp/lightrig-shape.XXXXXX)
rigs="plain ies gobo barn"

echo "## Light shaping: $(basename "$model"), raster $size --msaa 0, path traced $pathSize"
echo
echo "$(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, load average at start $(cut -d' ' -f1-3 /proc/loadavg); $repeats rounds"
for round in $(seq "$repeats"); do
    for rig in $rigs; do
        LIBGL_ALWAYS_SOFTWARE=1 "${x[@]}" "$lightrig" bench "$model" --rig "$root/scripts/perf/shape/helmet-$rig.json" \
            --quality exact,balanced,fast --no-errors --no-uber --msaa 0 --frames "$frames" --size "$size" \
            --json "$out/$rig.$round.raster.json" >"$out/$rig.$round.raster.txt" 2>&1 ||
            { cat "$out/$rig.$round.raster.txt" >&2; exit 1; }
        QT_QPA_PLATFORM=offscreen "$lightrig" bench "$model" --rig "$root/scripts/perf/shape/helmet-$rig.json" \
            --quality path --path-samples "$samples" --converged-samples 1 --size "$pathSize" \
            --json "$out/$rig.$round.path.json" >"$out/$rig.$round.path.txt" 2>&1 ||
            { cat "$out/$rig.$round.path.txt" >&2; exit 1; }
    done
done
echo "load average at end $(cut -d' ' -f1-3 /proc/loadavg)"
echo
python3 - "$out" "$repeats" $rigs <<'PY'
import json, statistics, sys
out, repeats, rigs = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def raster(rig, r, q):
    return next(x["ms_median"] for x in json.load(open(f"{out}/{rig}.{r}.raster.json"))["results"] if x["quality"] == q)
def path(rig, r):
    return json.load(open(f"{out}/{rig}.{r}.path.json"))["path"][0]["seconds_per_sample"]
med = lambda f: statistics.median(f(r) for r in range(1, repeats + 1))
base = {q: med(lambda r: raster("plain", r, q)) for q in ("exact", "balanced", "fast")}
basePath = med(lambda r: path("plain", r))
print("| rig | exact ms | balanced ms | fast ms | path s/sample |")
print("|---|---:|---:|---:|---:|")
for rig in rigs:
    cells = [f"{med(lambda r: raster(rig, r, q)):.1f} ({med(lambda r: raster(rig, r, q)) / base[q] - 1:+.0%})" for q in ("exact", "balanced", "fast")]
    p = med(lambda r: path(rig, r))
    print(f"| helmet-{rig} | {' | '.join(cells)} | {p:.4f} ({p / basePath - 1:+.0%}) |")
PY
