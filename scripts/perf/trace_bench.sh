#!/bin/bash
# The path tracer's performance (issue 36 part 6, docs/path-tracing.md "Performance"), in one run:
#  (b) samples per pixel per second at 640×360 and 1280×720 (`render --quality path`, every core);
#  (c) thread scaling: samples per second at THREADS threads (default 1 2 4 8 16, those over the machine's
#      cores left out unless THREADS is given) at 640×360, and the speed-up over one thread;
#  (d) peak memory (maximum resident set, /usr/bin/time -v) of the 1280×720 render: model, traced scene
#      (Embree BVH, textures, environment distribution) and the accumulation buffers;
#  aim: seconds until the 640×360 image is within 30 dB PSNR of its converged image (`bench --quality path`:
#      1, 4, 16, … samples against CONVERGED samples; the first step over 30 dB).
# Scene: the DamagedHelmet over the visible ground in the studio environment, 8 bounces.
# Usage: scripts/perf/trace_bench.sh [MODEL.glb]   (default ../shared/models/bench/helmet_1pt.glb).
#        SAMPLES (default 16: per timed render), CONVERGED (default 256), PATH_SAMPLES (default 64: the
#        ladder's top), THREADS ("1 2 4 8 16"), SIZES (the first table's sizes, "640x360 1280x720"),
#        SCALING_SIZE (the thread table's size, 640x360), AIM=0 (skips the aim). Needs a dev build
#        (LIGHTRIG_BUILD, default build/dev; or LIGHTRIG, the binary itself); no display (the path tier of
#        bench runs on the CPU alone). Without /usr/bin/time the memory column reads "–". Prints Markdown tables and
#        the load average. scripts/perf/trace_device.sh runs it on another machine from a bundle.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LIGHTRIG_BUILD:-$root/build/dev}
lightrig=${LIGHTRIG:-$build/lightrig}
model=${1:-$root/../shared/models/bench/helmet_1pt.glb}
[ -f "$model" ] || { echo "trace_bench.sh: $model not found (needs ../shared)" >&2; exit 1; }
[ -x "$lightrig" ] || { echo "trace_bench.sh: $lightrig not built" >&2; exit 1; }
samples=${SAMPLES:-16}
cores=$(nproc)
threads=${THREADS:-}
if [ -z "$threads" ]; then
    for t in 1 2 4 8 16; do [ "$t" -le "$cores" ] && threads="$threads $t"; done
fi
out=$(mktemp -d /tmp/lightrig-trace.XXXXXX)
timer=()
[ -x /usr/bin/time ] && timer=(/usr/bin/time -v)
scene=(--ground visible --environment studio --bounces 8)

# One render: prints "pixel-samples/s spp/s seconds max-rss-MiB".
render() { # size threads(0: all)
    local size=$1 t=$2 extra=()
    [ "$t" != 0 ] && extra=(--threads "$t")
    "${timer[@]}" "$lightrig" render "$model" --quality path --samples "$samples" --size "$size" \
        "${scene[@]}" "${extra[@]}" -o "$out/r.png" >"$out/r.txt" 2>"$out/r.err" || {
        cat "$out/r.err" >&2
        exit 1
    }
    python3 - "$out/r.txt" "$out/r.err" "$size" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
m = re.search(r"(\d+) samples per pixel, \d+ bounces, (\d+) threads, ([0-9.]+) s \((\d+) samples/s\)", text)
rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(sys.argv[2]).read())
w, h = map(int, sys.argv[3].split("x"))
spp, thr, sec, ps = int(m[1]), int(m[2]), float(m[3]), float(m[4])
print(f"{ps:.0f} {ps / (w * h):.3f} {sec:.2f} {int(rss[1]) / 1024 if rss else float('nan'):.0f} {thr}".replace("nan", "–"))
PY
}

echo "## Path tracer: $(basename "$model"), ground visible, studio environment, 8 bounces"
echo
echo "$(date -u +%Y-%m-%dT%H:%MZ), $cores cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), load average at start $(cut -d' ' -f1-3 /proc/loadavg), $samples samples per timed render"
echo
echo "| size | threads | samples/pixel/s | s/sample | Mpaths/s | peak RSS MiB |"
echo "|---|---:|---:|---:|---:|---:|"
for size in ${SIZES:-640x360 1280x720}; do
    read -r ps spps sec rss thr < <(render "$size" 0)
    echo "| $size | $thr | $spps | $(python3 -c "print(f'{1/$spps:.3f}')") | $(python3 -c "print(f'{$ps/1e6:.2f}')") | $rss |"
done
echo
scaling=${SCALING_SIZE:-640x360}
echo "| threads ($scaling) | samples/pixel/s | speed-up |"
echo "|---:|---:|---:|"
one=""
for t in $threads; do
    read -r ps spps sec rss thr < <(render "$scaling" "$t")
    [ -z "$one" ] && one=$spps
    echo "| $t | $spps | $(python3 -c "print(f'{$spps/$one:.2f}')")× |"
done
echo
if [ "${AIM:-1}" = 0 ]; then
    echo "load average at end $(cut -d' ' -f1-3 /proc/loadavg)"
    rm -rf "$out"
    exit 0
fi
"$lightrig" bench "$model" --quality path --size 640x360 "${scene[@]}" \
    --path-samples "${PATH_SAMPLES:-64}" --converged-samples "${CONVERGED:-256}" --json "$out/bench.json" \
    >"$out/bench.txt" 2>"$out/bench.err" || { cat "$out/bench.err" >&2; exit 1; }
python3 - "$out/bench.json" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
for p in doc["path"]:
    t = p["seconds_to_30db"]
    print(f"Aim, 640x360 within 30 dB of {p['converged_samples']} samples ({p['converged_seconds']:.0f} s): "
          + (f"{t:.2f} s" if t is not None else "not within the ladder") + f", {p['threads']} threads")
    print()
    print("| samples | seconds | noise | PSNR dB | mean err (levels) |")
    print("|---:|---:|---:|---:|---:|")
    for s in p["steps"]:
        noise = "–" if s["noise"] is None else f"{s['noise']:.4f}"
        psnr = "inf" if s["psnr_db"] is None else f"{s['psnr_db']:.1f}"
        print(f"| {s['samples']} | {s['seconds']:.2f} | {noise} | {psnr} | {s['mean_error_levels']:.3f} |")
PY
echo
echo "load average at end $(cut -d' ' -f1-3 /proc/loadavg)"
rm -rf "$out"
