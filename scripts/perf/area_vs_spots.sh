#!/bin/bash
# Area lights against spots (issue 16 part 6, docs/performance.md "Area lights against spots"): ms/frame of
# 1, 4 and 16 rect lights against as many spot lights on one model at 1280×720, in one `lightrig bench` run
# (the procedural ring of core/proceduralrig.h: softboxes of 1 × 0.6 model radii facing the centre, spots
# at the same places), every tier with its error against the double-precision reference (the rects'
# integrated by Monte Carlo, core/areaintegrate.h), then a Markdown table per tier of the rect/spot ratio.
# Target (reported, not asserted): 16 rects ≤ 3× the 16 spots' cost in the exact tier.
# Usage: scripts/perf/area_vs_spots.sh [MODEL.glb]   (default ../shared/models/bench/helmet_1pt.glb, the
#        DamagedHelmet; its own lights are replaced). FRAMES (default 60), SIZE (default 1280x720),
#        ERRORS=0 skips the reference (it takes minutes at 1280×720 with 16 rects), JSON=FILE keeps the
#        bench's JSON. Needs a dev build and xvfb-run; run it on an otherwise idle machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LIGHTRIG_BUILD:-$root/build/dev}
model=${1:-$root/../shared/models/bench/helmet_1pt.glb}
[ -f "$model" ] || { echo "area_vs_spots.sh: $model not found (needs ../shared)" >&2; exit 1; }
out=$(mktemp -d /tmp/lightrig-area.XXXXXX)
json=${JSON:-$out/bench.json}
extra=()
[ "${ERRORS:-1}" = 0 ] && extra+=(--no-errors)
MESA_SHADER_CACHE_DISABLE=true xvfb-run -a "$build/lightrig" bench "$model" --light-type spot,rect \
    --lights 1,4,16 --size "${SIZE:-1280x720}" --frames "${FRAMES:-60}" --no-uber "${extra[@]}" \
    --json "$json" >"$out/bench.txt"
sed -n '/^Area lights integrated/,$p' "$out/bench.txt"
python3 - "$json" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
rows = {}
for r in doc["results"]:
    if r["shader"] != "specialised":
        continue
    kind = "rect" if " rect" in r["scene"] else "spot"
    rows[(r["quality"], r["lights"], kind)] = r
print(f"\n{doc['gl']}, {doc['options']['width']}x{doc['options']['height']}, "
      f"{doc['options']['frames']} frames, load average {doc['load_average']}\n")
def err(r):
    if r.get("mean_error_levels") is None:
        return "–"
    psnr = r.get("psnr_db")
    return f"{r['mean_error_levels']:.2f} / {r['max_error_levels']} / {psnr:.1f}" if psnr else \
        f"{r['mean_error_levels']:.2f} / {r['max_error_levels']} / ∞"
print("| tier | lights | spots ms | rects ms | rects/spots | spots CPU ms | rects CPU ms | CPU ratio "
      "| spots error (mean / max levels / PSNR dB) | rects error |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---|---|")
for tier in doc["options"]["tiers"]:
    for n in (1, 4, 16):
        s, a = rows.get((tier, n, "spot")), rows.get((tier, n, "rect"))
        if not s or not a:
            continue
        print(f"| {tier} | {n} | {s['ms_median']:.2f} | {a['ms_median']:.2f} | {a['ms_median'] / s['ms_median']:.2f} "
              f"| {s['cpu_ms_median']:.1f} | {a['cpu_ms_median']:.1f} | {a['cpu_ms_median'] / s['cpu_ms_median']:.2f} "
              f"| {err(s)} | {err(a)} |")
ex = rows.get(("exact", 16, "rect")), rows.get(("exact", 16, "spot"))
if all(ex):
    ratio = ex[0]["ms_median"] / ex[1]["ms_median"]
    print(f"\nexact, 16 rects / 16 spots: {ratio:.2f}× (target ≤ 3×: {'met' if ratio <= 3 else 'not met'})")
PY
