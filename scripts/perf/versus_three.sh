#!/bin/bash
# Speed against three.js, like for like (issue 13, docs/performance.md): for each scene in turn, three.js
# r187 (../shared/peers/three/run.sh), then `lightrig bench` (exact, balanced, fast; --msaa 0, 60 frames),
# then three.js again, so every LightRig figure is bracketed by two three.js runs taken within a minute:
# wall-time medians on a shared VM drift by ±20 % over minutes, a bracketed ratio much less.
# Usage: scripts/perf/versus_three.sh [ROUNDS] [SCENE.glb...]   (default: 1 round of
#        ../shared/models/bench/helmet_{1pt,8pt,64pt,8spot}.glb). Needs a dev build and xvfb-run; run it on
#        an otherwise idle machine. Prints a Markdown table: three.js A / B, LightRig's tiers, the ratios
#        exact/three.js and fast/three.js (against the mean of A and B, and the range against each), the
#        first frames, and the fast tier's PSNR against the double-precision reference. LightRig runs twice:
#        with the still camera three.js has (after the first draw the G-buffer and the background are
#        kept: the frame of a light being dragged) and with --orbit 1 (the camera turns a degree a frame,
#        nothing view-dependent is kept: the frame of a user orbiting, like for like with three.js, which
#        re-renders everything every frame). Each run starts after
#        COOLDOWN seconds (default 20) of rest: the run after Chromium exits was otherwise up to 15 % slower.
#        ENV=FILE.exr|.hdr (issue 15): both light the scene with that environment, shown as the background
#        (three.js: THREE_ENV + env=…&bg=1, PMREM; LightRig: --environment FILE; its first frame is the
#        first draw, during which the environment is decoded and prefiltered: the CLI starts that after
#        the model's upload, and the renderer waits for it at the first pass that samples it); LightRig's
#        errors are then skipped (--no-errors): the integrated reference at 1280×720 takes minutes, and
#        docs/performance.md measures it at 320×180 instead.
#        SHADOWS=1 (issue 14): every light casts on both sides (three.js: shadows=1, 1024² PCFSoft maps
#        re-rendered every frame; LightRig: --shadows on, maps cached), errors skipped as for ENV.
#        A third LightRig run (--drag, exact) moves the first light every frame: the frame of a light
#        being dragged, its shadow map rendered again.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LIGHTRIG_BUILD:-$root/build/dev}
three=$root/../shared/peers/three/run.sh
[ -x "$three" ] || { echo "versus_three.sh: $three not found (needs ../shared)" >&2; exit 1; }
rounds=${1:-1}
[ $# -gt 0 ] && shift
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=("$root"/../shared/models/bench/helmet_{1pt,8pt,64pt,8spot}.glb)
out=$(mktemp -d /tmp/lightrig-versus.XXXXXX)
three_env=() three_opts=() lightrig_env=() orbit_env=()
if [ -n "${ENV:-}" ]; then
    env_file=$(realpath "$ENV")
    three_env=(THREE_ENV="$env_file")
    three_opts+=("env=scenes/$(basename "$env_file")&bg=1")
    lightrig_env=(--environment "$env_file" --no-errors)
    orbit_env=(--environment "$env_file")
fi
if [ -n "${SHADOWS:-}" ]; then
    three_opts+=("shadows=1")
    lightrig_env+=(--shadows on --no-errors)
    orbit_env+=(--shadows on)
fi
if [ ${#three_opts[@]} -gt 0 ]; then
    three_env+=(THREE_OPTS="$(IFS='&'; echo "${three_opts[*]}")")
fi
rest() { sleep "${COOLDOWN:-20}"; }
for r in $(seq "$rounds"); do
    for s in "${scenes[@]}"; do
        name=$(basename "$s" .glb)
        rest
        env "${three_env[@]}" PEERS_OUT=$out FRAMES=60 "$three" "$s" >"$out/three_${name}_${r}_a.json" 2>>"$out/three.err" || true
        rest
        MESA_SHADER_CACHE_DISABLE=true xvfb-run -a "$build/lightrig" bench "$s" --quality exact,balanced,fast \
            --msaa 0 --frames 60 --no-uber "${lightrig_env[@]}" --json "$out/lightrig_${name}_${r}.json" >/dev/null
        MESA_SHADER_CACHE_DISABLE=true xvfb-run -a "$build/lightrig" bench "$s" --quality exact,fast --orbit 1 \
            --msaa 0 --frames 60 --no-uber --no-errors "${orbit_env[@]}" \
            --json "$out/orbit_${name}_${r}.json" >/dev/null
        MESA_SHADER_CACHE_DISABLE=true xvfb-run -a "$build/lightrig" bench "$s" --quality exact --drag \
            --msaa 0 --frames 60 --no-uber --no-errors "${orbit_env[@]}" \
            --json "$out/drag_${name}_${r}.json" >/dev/null
        rest
        env "${three_env[@]}" PEERS_OUT=$out FRAMES=60 "$three" "$s" >"$out/three_${name}_${r}_b.json" 2>>"$out/three.err" || true
    done
done
python3 - "$out" <<'PY'
import glob, json, os, statistics, sys
out = sys.argv[1]
def three(path):
    try:
        return json.loads(open(path).read().strip().splitlines()[-1])
    except (OSError, ValueError, IndexError):
        return None
print("| scene | three.js ms (A / B) | exact | balanced | fast | exact / three.js | fast / three.js "
      "| orbiting: exact, fast | orbiting / three.js: exact, fast | dragging: exact (/ three.js) "
      "| three.js first frame (load) | LightRig first draw (upload; import) | fast PSNR |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for path in sorted(glob.glob(os.path.join(out, "lightrig_*.json"))):
    key = os.path.basename(path)[len("lightrig_"):-len(".json")]
    q = {r["quality"]: r for r in json.load(open(path))["results"]}
    ab = [t for t in (three(os.path.join(out, "three_%s_%s.json" % (key, x))) for x in "ab") if t]
    if not ab:
        print("| %s | three.js failed (see %s/three.err) |" % (key, out))
        continue
    ms = [t["msPerFrameMedian"] for t in ab]
    mean = statistics.mean(ms)
    e, b, f = q["exact"], q["balanced"], q["fast"]
    try:
        o = {r["quality"]: r for r in json.load(open(os.path.join(out, "orbit_%s.json" % key)))["results"]}
        oe, of = o["exact"]["ms_median"], o["fast"]["ms_median"]
    except (OSError, ValueError, KeyError):
        oe = of = float("nan")
    try:
        de = json.load(open(os.path.join(out, "drag_%s.json" % key)))["results"][0]["ms_median"]
    except (OSError, ValueError, KeyError, IndexError):
        de = float("nan")
    first = "%.2f s (%.2f s; %.2f s)" % (e["first_draw_ms"] / 1000, e["upload_ms"] / 1000, e["load_ms"] / 1000)
    if "environment_prefilter_ms" in e:  # ENV: the first frame also waits for the decoding and prefiltering
        env_ms = e["environment_decode_ms"] + e["environment_prefilter_ms"]
        if e.get("environment_concurrent"):  # loaded during the first draw, which includes it
            first += " with the environment (%.2f s of loading beside it) = **%.2f s**" % (
                env_ms / 1000, e["first_draw_ms"] / 1000)
        else:
            first += " + environment %.2f s = **%.2f s**" % (env_ms / 1000, (e["first_draw_ms"] + env_ms) / 1000)
    print("| %s | %s | %.1f | %.1f | %.1f | **%.2f** (%.2f–%.2f) | **%.2f** | %.1f, %.1f | **%.2f**, %.2f | %.1f (**%.2f**) | %.2f s (%.2f s) | %s | %.1f dB |"
          % (key, " / ".join("%.1f" % m for m in ms), e["ms_median"], b["ms_median"], f["ms_median"],
             e["ms_median"] / mean, e["ms_median"] / max(ms), e["ms_median"] / min(ms), f["ms_median"] / mean,
             oe, of, oe / mean, of / mean, de, de / mean,
             ab[0]["firstFrameMs"] / 1000, ab[0]["loadMs"] / 1000, first, f.get("psnr_db") or float("nan")))
PY
echo "raw results: $out" >&2
