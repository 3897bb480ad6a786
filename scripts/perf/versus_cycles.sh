#!/bin/bash
# LightRig's path tracer side by side with an independent one, Blender's Cycles (issue 36, items 5 and 6a;
# docs/path-tracing.md, "Against Cycles"). The same scene in both: MODEL's meshes, its glTF camera and its
# KHR_lights_punctual lights, LightRig's visible ground, ENV as the environment and background; Cycles'
# side is built by scripts/perf/cycles_scene.py (its header says how each thing is matched).
# Usage: scripts/perf/versus_cycles.sh [OUTDIR]   (default: a new /tmp/lightrig-cycles.XXXXXX)
#   MODEL=…glb (default ../shared/models/bench/helmet_1pt.glb)  ENV=…exr (default resources/environments/studio.exr)
#   SIZE=WxH (320x180)  SPP=N (1024: both images of the side by side, and each renderer's own reference for
#   the equal-time part)  BOUNCES=B (8, LightRig's count: Cycles gets B - 1)  THREADS=T (2)
#   GROUND_BSDF=lambert|principled (Cycles' ground: lambert, a Diffuse BSDF of albedo 0.8 at roughness 0, is
#   within 1 % of LightRig's glTF ground of roughness 1 where it is lit alone; principled, Principled BSDF
#   0.8 / roughness 1 / specular 0.5, is what Blender's glTF importer would make of such a material, and
#   its Disney diffuse with retro-reflection plus a specular layer added on top reads 10 to 45 % brighter at
#   this grazing view, docs/path-tracing.md)
#   TIMES="5 20 60" (equal time: seconds of tracing; empty skips it)  SIDE=0 skips the side by side and
#   reuses OUTDIR's references.
# Prints Markdown: the side by side's PSNR (8-bit sRGB, the images each writes; LightRig writes 8 bits
# only), the mean linear colour of the whole image and of three regions in each, and the equal-time table:
# PSNR of each renderer's image after T seconds (seed 1) against its own SPP-sample image (seed 0). LightRig
# is given a sample count rather than --time-limit (a time limit ends mid-pass and the samples would differ per pixel): it gets the sample count its last run's rate fits in T seconds (refitted while its
# tracing time is off T by more than 15 %), and its real tracing time is printed beside. Cycles gets scene.cycles.time_limit = T; its tracing time is read from its log.
# Needs a dev build; installs blender (Debian's, 3.4), python3-numpy (its glTF importer imports numpy) and
# oiiotool (openimageio-tools) when they are missing.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
lightrig=${LIGHTRIG_BUILD:-$root/build/dev}/lightrig
model=$(realpath "${MODEL:-$root/../shared/models/bench/helmet_1pt.glb}")
envmap=$(realpath "${ENV:-$root/resources/environments/studio.exr}")
size=${SIZE:-320x180} spp=${SPP:-1024} bounces=${BOUNCES:-8} threads=${THREADS:-2}
ground_bsdf=${GROUND_BSDF:-lambert}
times=${TIMES-5 20 60}
out=${1:-$(mktemp -d /tmp/lightrig-cycles.XXXXXX)}
mkdir -p "$out"
# The peers come from Debian like the rest (scripts/setup.sh installs only what is missing).
# shellcheck source=../setup.sh
source "$root/scripts/setup.sh"
lightrig_install_packages blender python3-numpy openimageio-tools
[ -x "$lightrig" ] || { echo "versus_cycles.sh: $lightrig not built" >&2; exit 1; }
w=${size%x*} h=${size#*x}

lr() { # lr OUT.png SAMPLES SEED: LightRig's image; prints its tracing seconds and samples per second
    "$lightrig" render "$model" --quality path --samples "$2" --seed "$3" --bounces "$bounces" --threads "$threads" \
        --size "$size" --ground visible --environment "$envmap" --environment-background visible -o "$1" >"$1.log" 2>&1
    sed -n 's/.* \([0-9.]*\) s (\([0-9]*\) samples\/s).*/\1 \2/p' "$1.log"
}
cy() { # cy OUT.png SAMPLES SEED TIME_LIMIT: Cycles' image; prints its tracing seconds and samples reached
    blender -b --factory-startup --python "$root/scripts/perf/cycles_scene.py" -- "$model" "$envmap" "$1" \
        --size "$size" --samples "$2" --seed "$3" --time-limit "$4" --bounces "$bounces" --threads "$threads" \
        --ground-bsdf "$ground_bsdf" >"$1.log" 2>&1
    # Tracing time: from the first status line that counts samples to "Finished" (the sync before it, BVH
    # and images, is left out, as LightRig's figure leaves out its loading); samples: the most counted.
    local s n
    s=$(grep -a '^Fra:.*| \(Sample [0-9]*/\|Finished\)' "$1.log" | sed 's/.*Time:\([0-9]*\):\([0-9.]*\) .*/\1 \2/' |
        awk 'NR == 1 { a = $1 * 60 + $2 } { b = $1 * 60 + $2 } END { printf "%.2f", b - a }')
    n=$(grep -ao 'Sample [0-9]*/' "$1.log" | tr -dc '0-9\n' | sort -n | tail -1)
    echo "$s ${n:-?}"
}
psnr() { # psnr A.png B.png: PSNR in dB over R, G, B of the 8-bit sRGB images
    oiiotool "$1" --ch R,G,B "$2" --ch R,G,B --diff 2>&1 | sed -n 's/.*Peak SNR = \([0-9.inf]*\).*/\1/p'
}
mean() { # mean IMG.png [X0 Y0 X1 Y1]: mean linear R G B (sRGB decoded) of the image or of a box
    local cut=()
    [ $# -gt 1 ] && cut=(--cut "$(($4 - $2))x$(($5 - $3))+$2+$3")
    oiiotool "$1" --ch R,G,B "${cut[@]}" --colorconvert sRGB linear --printstats 2>&1 |
        sed -n 's/^ *Stats Avg: \(.*\) (float)/\1/p' | head -1
}

echo "## LightRig against Cycles: $(date -u +%F), $(uname -m), $(nproc) cores"
echo
echo "Load before: $(uptime | sed 's/.*load average/load average/'). Model $(basename "$model"), environment $(basename "$envmap"), $size, $bounces bounces, $threads threads, Cycles' ground $ground_bsdf. $(blender --version 2>/dev/null | head -1), Cycles CPU."
echo
if [ "${SIDE:-1}" != 0 ]; then
    read -r lr_s lr_rate < <(lr "$out/lightrig_ref.png" "$spp" 0)
    read -r cy_s _ < <(cy "$out/cycles_ref.png" "$spp" 0 0)
    echo "$lr_rate" >"$out/lightrig_rate"
    echo "| image | samples per pixel | seconds (tracing) |"
    echo "|---|---|---|"
    echo "| LightRig | $spp | $lr_s ($lr_rate samples/s) |"
    echo "| Cycles | $spp | $cy_s |"
    echo
    echo "PSNR LightRig against Cycles (8-bit sRGB): **$(psnr "$out/lightrig_ref.png" "$out/cycles_ref.png") dB**"
    echo
    echo "| region (pixels) | LightRig mean linear RGB | Cycles mean linear RGB |"
    echo "|---|---|---|"
    regions=("whole image|" "background, top quarter|0 0 $w $((h / 4))"
             "ground, bottom fifth|0 $((h * 4 / 5)) $w $h" "helmet, centre box|$((w * 2 / 5)) $((h * 3 / 10)) $((w * 3 / 5)) $((h * 7 / 10))")
    for r in "${regions[@]}"; do
        name=${r%%|*} box=${r#*|}
        # shellcheck disable=SC2086
        echo "| $name ${box:+($box)} | $(mean "$out/lightrig_ref.png" $box) | $(mean "$out/cycles_ref.png" $box) |"
    done
    oiiotool "$out/lightrig_ref.png" --ch R,G,B "$out/cycles_ref.png" --ch R,G,B --mosaic 1x2 -o "$out/side_by_side.png"
    oiiotool "$out/lightrig_ref.png" --ch R,G,B "$out/cycles_ref.png" --ch R,G,B --absdiff --mulc 4 -o "$out/diff_x4.png"
    echo
fi
if [ -n "$times" ]; then
    rate=$(cat "$out/lightrig_rate")
    echo "Equal time (each against its own $spp-sample image of seed 0; the timed images use seed 1). Load: $(uptime | sed 's/.*load average/load average/')."
    echo
    echo "| seconds | LightRig spp | LightRig tracing s | LightRig PSNR dB | Cycles spp | Cycles tracing s | Cycles PSNR dB |"
    echo "|---|---|---|---|---|---|---|"
    for t in $times; do
        # The rate drifts with the machine's load: the sample count is fitted again (twice at most) until
        # the tracing time is within 15 % of T.
        n=$(awk -v r="$rate" -v t="$t" -v p=$((w * h)) 'BEGIN { n = int(r * t / p); print n < 1 ? 1 : n }')
        for try in 1 2 3; do
            read -r ls rate < <(lr "$out/lightrig_${t}s.png" "$n" 1)
            awk -v s="$ls" -v t="$t" 'BEGIN { exit !(s > 0.85 * t && s < 1.15 * t) }' && break
            [ "$try" = 3 ] || n=$(awk -v r="$rate" -v t="$t" -v p=$((w * h)) 'BEGIN { n = int(r * t / p); print n < 1 ? 1 : n }')
        done
        read -r cs cn < <(cy "$out/cycles_${t}s.png" 1000000 1 "$t")
        echo "| $t | $n | $ls | $(psnr "$out/lightrig_${t}s.png" "$out/lightrig_ref.png") | $cn | $cs | $(psnr "$out/cycles_${t}s.png" "$out/cycles_ref.png") |"
    done
    echo
fi
echo "Load after: $(uptime | sed 's/.*load average/load average/'). Images and logs in $out."
