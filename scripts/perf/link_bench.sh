#!/bin/bash
# What light and shadow linking cost the path tracer (issue 38, docs/path-tracing.md "Light and shadow
# linking"): `lightrig bench --quality path` on the helmet with each rig of scripts/perf/link/, taken in
# turn REPEATS times, and the median seconds per sample of each against the rig without links.
#   helmet-plain    a key and a fill, no links (the baseline: linking inactive, nothing set);
#   helmet-neutral  the fill "linked" to every part: linking active (masks on every ray, the per-light
#                   test at every shading point) with the image unchanged — linking's own cost;
#   helmet-linked   the fill lights the helmet only, and the helmet casts no shadow of the key.
# Usage: scripts/perf/link_bench.sh [MODEL.glb]  (default ../shared/models/bench/helmet_1pt.glb, whose mesh
#        node the rigs name). SIZE (640x360), PATH_SAMPLES (16: the ladder 1 … 16, 31 samples timed),
#        REPEATS (3), THREADS (default: every core), LIGHTRIG (default build/dev/lightrig), BASELINE (another
#        build's binary, e.g. of the commit before linking: adds a row of helmet-plain rendered by it, whose
#        rig it must read). No display.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
lightrig=${LIGHTRIG:-$root/build/dev/lightrig}
model=${1:-$root/../shared/models/bench/helmet_1pt.glb}
[ -f "$model" ] || { echo "link_bench.sh: $model not found (needs ../shared)" >&2; exit 1; }
[ -x "$lightrig" ] || { echo "link_bench.sh: $lightrig not built" >&2; exit 1; }
size=${SIZE:-640x360}
samples=${PATH_SAMPLES:-16}
repeats=${REPEATS:-3}
extra=()
[ -n "${THREADS:-}" ] && extra=(--threads "$THREADS")
export QT_QPA_PLATFORM=${QT_QPA_PLATFORM:-offscreen}
out=$(mktemp -d /tmp/lightrig-link.XXXXXX)
rigs="plain neutral linked"
[ -n "${BASELINE:-}" ] && rigs="baseline $rigs"

echo "## Light linking in the path tracer: $(basename "$model"), $size, studio environment, 8 bounces"
echo
echo "$(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), load average at start $(cut -d' ' -f1-3 /proc/loadavg); $repeats rounds of bench --quality path --path-samples $samples"
for round in $(seq "$repeats"); do
    for rig in $rigs; do
        binary=$lightrig file=$rig
        [ "$rig" = baseline ] && binary=$BASELINE file=plain
        "$binary" bench "$model" --rig "$root/scripts/perf/link/helmet-$file.json" --quality path \
            --path-samples "$samples" --converged-samples 1 --size "$size" --environment studio \
            "${extra[@]}" --json "$out/$rig.$round.json" >"$out/$rig.$round.txt" 2>&1 || {
            cat "$out/$rig.$round.txt" >&2
            exit 1
        }
    done
done
echo "load average at end $(cut -d' ' -f1-3 /proc/loadavg)"
echo
python3 - "$out" "$repeats" $rigs <<'PY'
import json, statistics, sys
out, repeats, rigs = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def seconds(rig, r):
    return json.load(open(f"{out}/{rig}.{r}.json"))["path"][0]["seconds_per_sample"]
print("| rig | s/sample (median) | each round | vs plain |")
print("|---|---:|---|---:|")
medians = {rig: statistics.median(seconds(rig, r) for r in range(1, repeats + 1)) for rig in rigs}
for rig in rigs:
    s = [seconds(rig, r) for r in range(1, repeats + 1)]
    name = "helmet-plain, BASELINE binary" if rig == "baseline" else f"helmet-{rig}"
    print(f"| {name} | {medians[rig]:.4f} | {', '.join(f'{x:.4f}' for x in s)} | {medians[rig] / medians['plain'] - 1:+.1%} |")
PY
