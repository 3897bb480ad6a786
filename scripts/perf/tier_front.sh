#!/bin/bash
# The tiers' promise measured in one bracketed run (issue 40 item 5): for each scene and each setting
# (plain; shadows; environment; both), three.js r187 (../shared/peers/three/run.sh), then `lightrig bench`
# held still, with a light dragged (--drag) and orbiting (--orbit 1), every tier each time, then three.js
# again, so each LightRig figure sits between two three.js runs taken within minutes. Writes one Markdown
# table: per scene, setting and tier the median ms per frame in each interaction, its share of exact's, the
# verdict (core/tieroffer.h: balanced at most exact's time, fast at most half, 20 % leeway), three.js's
# ms per frame (A / B) and the load average over the setting's runs.
# Usage: scripts/perf/tier_front.sh [SCENE.glb...]   (default: ../shared/models/bench/helmet_8spot.glb on a
#        ground, made by ../shared/peers/three/add_ground.py). SETTINGS="plain shadows env both" (default
#        all four), ENV=FILE (default ../shared/environments/studio.exr), FRAMES (default 30), COOLDOWN
#        seconds of rest before each run (default 10). Needs a dev build, xvfb-run and ../shared; run it on
#        an otherwise idle machine. Errors are not measured (--no-errors): `lightrig bench` without it
#        gives each tier's error against the double-precision reference.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LIGHTRIG_BUILD:-$root/build/dev}
shared=$root/../shared
three=$shared/peers/three/run.sh
[ -x "$three" ] || { echo "tier_front.sh: $three not found (needs ../shared)" >&2; exit 1; }
[ -x "$build/lightrig" ] || { echo "tier_front.sh: $build/lightrig not built" >&2; exit 1; }
out=$(mktemp -d /tmp/lightrig-tierfront.XXXXXX)
scenes=("$@")
if [ ${#scenes[@]} -eq 0 ]; then
    python3 "$shared/peers/three/add_ground.py" "$shared/models/bench/helmet_8spot.glb" \
        "$out/helmet_8spot_ground.glb" >/dev/null
    scenes=("$out/helmet_8spot_ground.glb")
fi
env_file=$(realpath "${ENV:-$shared/environments/studio.exr}")
frames=${FRAMES:-30}
rest() { sleep "${COOLDOWN:-10}"; }
load() { cut -d' ' -f1-3 /proc/loadavg; }
for s in "${scenes[@]}"; do
    name=$(basename "$s" .glb)
    for setting in ${SETTINGS:-plain shadows env both}; do
        three_opts=() lightrig=()
        case $setting in
        plain) ;;
        shadows) three_opts=(THREE_OPTS="shadows=1"); lightrig=(--shadows on) ;;
        env) three_opts=(THREE_ENV="$env_file" THREE_OPTS="env=scenes/$(basename "$env_file")&bg=1")
             lightrig=(--environment "$env_file") ;;
        both) three_opts=(THREE_ENV="$env_file" THREE_OPTS="shadows=1&env=scenes/$(basename "$env_file")&bg=1")
              lightrig=(--shadows on --environment "$env_file") ;;
        *) echo "tier_front.sh: unknown setting $setting" >&2; exit 1 ;;
        esac
        key=${name}_$setting
        echo "$key: load $(load)" >&2
        load >"$out/load_${key}_start"
        rest
        env "${three_opts[@]}" PEERS_OUT=$out FRAMES=$frames "$three" "$s" >"$out/three_${key}_a.json" \
            2>>"$out/three.err" || true
        for interaction in still drag orbit; do
            extra=()
            [ $interaction = drag ] && extra=(--drag)
            [ $interaction = orbit ] && extra=(--orbit 1)
            rest
            xvfb-run -a "$build/lightrig" bench "$s" --quality exact,balanced,fast --msaa 0 --frames "$frames" \
                --no-uber --no-errors "${lightrig[@]}" "${extra[@]}" \
                --json "$out/lightrig_${key}_$interaction.json" >/dev/null
        done
        rest
        env "${three_opts[@]}" PEERS_OUT=$out FRAMES=$frames "$three" "$s" >"$out/three_${key}_b.json" \
            2>>"$out/three.err" || true
        load >"$out/load_${key}_end"
    done
done
python3 - "$out" <<'PY'
import glob, json, os, sys
out = sys.argv[1]
def last_json(path):
    try:
        return json.loads(open(path).read().strip().splitlines()[-1])
    except (OSError, ValueError, IndexError):
        return None
def read(path):
    try:
        return {r["quality"]: r for r in json.load(open(path))["results"]}, json.load(open(path))["load_average"]
    except (OSError, ValueError, KeyError):
        return {}, ""
print("| scene | setting | tier | still ms | drag ms | orbit ms | × exact: still / drag / orbit "
      "| offered | three.js ms (A / B) | load average (start → end) |")
print("|---|---|---|---:|---:|---:|---|---|---|---|")
for start in sorted(glob.glob(os.path.join(out, "load_*_start"))):
    key = os.path.basename(start)[len("load_"):-len("_start")]
    scene, setting = key.rsplit("_", 1)
    runs = {i: read(os.path.join(out, "lightrig_%s_%s.json" % (key, i)))[0] for i in ("still", "drag", "orbit")}
    three = [t for t in (last_json(os.path.join(out, "three_%s_%s.json" % (key, x))) for x in "ab") if t]
    three_ms = " / ".join("%.1f" % t["msPerFrameMedian"] for t in three) or "failed"
    loads = "%s → %s" % (open(start).read().split()[0], open(start.replace("_start", "_end")).read().split()[0]
                         if os.path.exists(start.replace("_start", "_end")) else "?")
    for tier in ("exact", "balanced", "fast"):
        ms = [runs[i].get(tier, {}).get("ms_median", float("nan")) for i in ("still", "drag", "orbit")]
        ex = [runs[i].get("exact", {}).get("ms_median", float("nan")) for i in ("still", "drag", "orbit")]
        ratio = " / ".join("%.2f" % (m / e) if e == e and e > 0 else "–" for m, e in zip(ms, ex))
        verdicts = [runs[i].get(tier, {}).get("offered", True) for i in ("still", "drag", "orbit")]
        offered = "yes" if all(verdicts) else "**no** (%s)" % ", ".join(
            i for i, v in zip(("still", "drag", "orbit"), verdicts) if not v)
        print("| %s | %s | %s | %.1f | %.1f | %.1f | %s | %s | %s | %s |" % (
            scene, setting, tier, ms[0], ms[1], ms[2], ratio, offered,
            three_ms if tier == "exact" else "", loads if tier == "exact" else ""))
PY
echo "raw results: $out" >&2
