#!/usr/bin/env bash
# gpu_run.sh [BUNDLE.tar.xz]: runs `lightrig bench` on a GPU machine from the bundle made by gpu_bundle.sh
# (default .gpubundle/bundle.tar.xz), the helmet with 1..4096 point lights at 3840x2160 and 1280x720.
# Results go to $OUT (default /tmp/lightrig-gpu-out): bench.json (all runs), bench.md (table), log.txt.
#
# On the device machine (root; GL libraries from glvnd, the NVIDIA driver under /usr/local/nvidia):
#   for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig; LR_GPU_VENDOR=nvidia scripts/perf/gpu_run.sh
# Locally (checks the bundle; Mesa llvmpipe): LR_GPU_SIZES=320x180 LR_GPU_LIGHTS="1 8" scripts/perf/gpu_run.sh
# It tries the GL set-ups below in turn and measures with the first whose GL_RENDERER has LR_GPU_EXPECT in it.
# On the H100 machine (2026-11) only "egldev" renders on the GPU: see docs/performance.md, "GPU (H100)".
#
# Environment: LR_GPU_VENDOR (sets __GLX_VENDOR_LIBRARY_NAME, and names that vendor's EGL file, for lightrig
# only, never for Xvfb, whose GLX extension is Mesa's), LR_GPU_EXPECT (a string GL_RENDERER must contain, else nothing is measured: default
# NVIDIA when LR_GPU_VENDOR=nvidia), LR_GPU_SIZES (the first is the main size), LR_GPU_LIGHTS,
# LR_GPU_FRAMES (60), LR_GPU_BIG_FRAMES (frames for >= 1024 lights at the main size, 20),
# LR_GPU_LOCAL (a glTF range in model units: every scene's lights become localised lights of that range on
# a sphere around the helmet, scripts/perf/localize_lights.py, as the llvmpipe table's local_N scenes),
# LR_GPU_NOMSAA_SIZES (sizes also timed as `--quality exact --msaa 0`, like the llvmpipe table in
# docs/performance.md; default the last size), LR_GPU_TIMEOUT (s per bench run, 150), LR_GPU_BUDGET (s: no
# new run starts after this, 450). Order: the main size up to the second-largest count, the other sizes,
# the no-MSAA runs, then the largest count at the main size, so a slow last run loses the least.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
tarball="${1:-$root/.gpubundle/bundle.tar.xz}"
out="${OUT:-/tmp/lightrig-gpu-out}"
work="${LR_GPU_WORK:-/tmp/lightrig-gpu-work}"
vendor="${LR_GPU_VENDOR:-}"
expect="${LR_GPU_EXPECT:-$([ "$vendor" = nvidia ] && echo NVIDIA)}"
sizes="${LR_GPU_SIZES:-3840x2160 1280x720}"
counts="${LR_GPU_LIGHTS:-1 8 64 256 1024 4096}"
frames="${LR_GPU_FRAMES:-60}"
bigFrames="${LR_GPU_BIG_FRAMES:-20}"
noMsaaSizes="${LR_GPU_NOMSAA_SIZES-${sizes##* }}"
runTimeout="${LR_GPU_TIMEOUT:-150}"
budget="${LR_GPU_BUDGET:-450}"
mkdir -p "$out" "$work/json"
log="$out/log.txt"
exec > >(tee -a "$log") 2>&1
say() { echo "== $(date -u +%H:%M:%S) $*"; }

say "unpacking $tarball"
rm -rf "$work/lightrig-gpu"
tar -xJf "$tarball" -C "$work" 2>/dev/null ||
    python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$tarball" "$work" ||
    { echo "gpu_run.sh: cannot unpack $tarball"; exit 1; }
R="$work/lightrig-gpu"
libs="$R/lib"

say "machine"
uname -a
grep -m1 PRETTY_NAME /etc/os-release
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.sm,clocks.max.sm,temperature.gpu --format=csv
ldconfig -p | grep -E 'libGLX(_nvidia|_mesa)?\.so|libEGL_nvidia|libnvidia-glcore' | head
if [ "$vendor" = nvidia ] && ! ldconfig -p | grep -q libGLX_nvidia; then
    d="$(dirname "$(ls /usr/local/nvidia/lib64/libGLX_nvidia.so.* /usr/local/nvidia/lib/libGLX_nvidia.so.* 2>/dev/null | head -n1)")"
    [ "$d" != . ] && libs="$libs:$d" && echo "libGLX_nvidia is not in the loader cache; using $d"
fi

# Xvfb runs xkbcomp from its compiled-in /usr/bin; on a machine without one, add ours (nothing is replaced).
if [ ! -x /usr/bin/xkbcomp ] && [ -w /usr/bin ]; then cp "$R/xserver/xkbcomp" /usr/bin/xkbcomp; fi
disp=99
while [ -e "/tmp/.X11-unix/X$disp" ] || [ -e "/tmp/.X$disp-lock" ]; do disp=$((disp + 1)); done
say "starting Xvfb :$disp"
LD_LIBRARY_PATH="$libs" LIBGL_DRIVERS_PATH="$R/dri" "$R/xserver/Xvfb" ":$disp" -screen 0 1920x1080x24 \
    -nolisten tcp -xkbdir "$R/xkb" +extension GLX >"$work/xvfb.log" 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null' EXIT
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$disp" ] && break; sleep 0.2; done
if ! kill -0 $xvfb 2>/dev/null || [ ! -e "/tmp/.X11-unix/X$disp" ]; then
    echo "gpu_run.sh: Xvfb did not start:"; cat "$work/xvfb.log"; exit 1
fi

say "scenes"
for n in $counts; do
    python3 "$R/scenes/add_lights.py" "$R/scenes/DamagedHelmet.glb" "$R/scenes/helmet_${n}pt.glb" "$n" || exit 1
    if [ -n "${LR_GPU_LOCAL:-}" ]; then
        python3 "$R/scenes/localize_lights.py" "$R/scenes/helmet_${n}pt.glb" "$R/scenes/tmp.glb" "$LR_GPU_LOCAL" &&
            mv "$R/scenes/tmp.glb" "$R/scenes/helmet_${n}pt.glb" || exit 1
    fi
done

# lightrig's environment per mode: "glx" (Qt's xcb platform, GLX), "egldev" (xcb platform with EGL, but
# DISPLAY unset and the X display passed as Qt's -display argument: EGL on the X11 platform fails on a
# GPU machine without nvidia-drm, and Qt's retry with EGL_DEFAULT_DISPLAY then gets NVIDIA's device
# platform, rendering into pbuffers and FBOs; that platform has no window-capable configs, so the shim
# eglpbuffer.so makes Qt's config choice ask for pbuffer-capable ones), "egl" (the same with DISPLAY set), "offscreen" (Qt's
# offscreen platform, GLX through Xlib). NVIDIA's EGL vendor file is named where one exists.
lr() {
    local mode="$1"
    shift
    local -a env=(LD_LIBRARY_PATH="$libs" QT_PLUGIN_PATH="$R/plugins"
                  QT_QPA_PLATFORM_PLUGIN_PATH="$R/plugins/platforms") pre=() post=()
    [ -n "$vendor" ] && env+=(__GLX_VENDOR_LIBRARY_NAME="$vendor")
    case "$mode" in
    glx) env+=(DISPLAY=":$disp" QT_QPA_PLATFORM=xcb QT_XCB_GL_INTEGRATION=xcb_glx) ;;
    offscreen) env+=(DISPLAY=":$disp" QT_QPA_PLATFORM=offscreen) ;;
    egl | egldev)
        env+=(QT_QPA_PLATFORM=xcb QT_XCB_GL_INTEGRATION=xcb_egl)
        if [ "$mode" = egldev ]; then
            pre=(-u DISPLAY) post=(-display ":$disp")
            env+=(LD_PRELOAD="$(dirname "$tarball")/eglpbuffer.so")
        else
            env+=(DISPLAY=":$disp")
        fi
        local icd
        for icd in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json \
                   /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
            [ -n "$vendor" ] && [ -e "$icd" ] && env+=(__EGL_VENDOR_LIBRARY_FILENAMES="$icd") && break
        done ;;
    esac
    env "${pre[@]}" "${env[@]}" timeout "$runTimeout" "$R/bin/lightrig" "$@" "${post[@]}"
}

# What GLX offers on the display, and whether a bare 3.3 core context renders (glxprobe, built by
# gpu_bundle.sh next to the tarball).
probe="$(dirname "$tarball")/glxprobe"
if [ -x "$probe" ]; then
    say "glxprobe${vendor:+ (vendor $vendor)}"
    ls -l /dev/nvidia* /dev/dri 2>&1 | head -n 12
    env LD_LIBRARY_PATH="$libs" DISPLAY=":$disp" ${vendor:+__GLX_VENDOR_LIBRARY_NAME=$vendor} timeout 30 "$probe"
fi

say "probe: which GL does lightrig get?"
mode=""
for m in glx egldev egl offscreen; do
    QT_LOGGING_RULES="qt.qpa.gl=true;qt.glx=true" lr "$m" bench "$R/scenes/helmet_${counts%% *}pt.glb" --size 320x180 --frames 3 --warmup 1 --quality fast \
        --no-errors --no-uber --json "$work/probe-$m.json" >"$work/probe-$m.txt" 2>&1
    rc=$?
    renderer="$(grep -m1 '^lightrig bench: .*OpenGL' "$work/probe-$m.txt")" # not the estimate line of a large scene
    echo "$m: rc=$rc ${renderer:-$(tail -n3 "$work/probe-$m.txt")}"
    grep -E 'qt\.(glx|qpa\.gl|egl)|EGL|GLX|error' "$work/probe-$m.txt" | grep -vE 'XDG_RUNTIME|priority' | head -n 8
    if [ $rc = 0 ] && [[ "$renderer" == *"$expect"* ]]; then mode=$m; break; fi
done
if [ -z "$mode" ]; then
    echo "gpu_run.sh: lightrig got no OpenGL renderer containing '$expect'; not measuring. Xvfb log:"
    cat "$work/xvfb.log"
    cp "$work"/probe-*.txt "$work/xvfb.log" "$out/" 2>/dev/null
    LD_LIBRARY_PATH="$libs" ldd "$R/bin/lightrig" | grep -iE 'not found|GL' || true
    exit 1
fi
say "measuring through $mode: $renderer"

# One bench run: SIZE LIGHTS FRAMES TAG [extra bench options].
run() {
    local size="$1" n="$2" f="$3" tag="$4"
    shift 4
    if [ "$SECONDS" -ge "$budget" ]; then say "skipped $size $n $tag: past the ${budget}s budget"; return; fi
    say "$size, $n lights, $f frames $*"
    lr "$mode" bench "$R/scenes/helmet_${n}pt.glb" --size "$size" --frames "$f" --no-errors --no-uber "$@" \
        --json "$work/json/${tag}_${size}_${n}.json" || echo "gpu_run.sh: run $size $n $* failed (rc=$?)"
}
main="${sizes%% *}"
largest="${counts##* }"
for n in $counts; do
    [ "$n" = "$largest" ] && [ "$n" != "${counts%% *}" ] && continue
    run "$main" "$n" "$([ "$n" -ge 1024 ] && echo "$bigFrames" || echo "$frames")" tiers
done
for size in ${sizes#"$main"}; do for n in $counts; do run "$size" "$n" "$frames" tiers; done; done
for size in $noMsaaSizes; do
    for n in $counts; do run "$size" "$n" "$frames" nomsaa --quality exact --msaa 0; done
done
[ "$largest" != "${counts%% *}" ] &&
    run "$main" "$largest" "$([ "$largest" -ge 1024 ] && echo "$bigFrames" || echo "$frames")" tiers

say "summary"
python3 - "$work/json" "$out/bench.json" "$out/bench.md" <<'PY'
import json, os, sys
src, jout, mout = sys.argv[1:]
runs = []
for name in sorted(os.listdir(src)):
    with open(os.path.join(src, name)) as f:
        runs.append(json.load(f))
runs.sort(key=lambda r: (-r["options"]["width"], len(r["options"]["tiers"]) == 1,
                         r["results"][0]["lights"] if r["results"] else 0))
json.dump(runs, open(jout, "w"), indent=1)
def num(v, d=2):
    return "—" if v is None else f"{v:.{d}f}"
lines = [f"GL: {runs[0]['gl'] if runs else '?'}", "",
         "| size | lights | tier | MSAA | ms/frame median (min–max) | GPU timer ms | CPU ms/frame | first frame ms |",
         "|---|---|---|---|---|---|---|---|"]
for r in runs:
    o = r["options"]
    for x in r["results"]:
        lines.append(f"| {o['width']}×{o['height']} | {x['lights']} | {x['quality']} | {x['msaa_samples']} | "
                     f"{num(x['ms_median'])} ({num(x['ms_min'])}–{num(x['ms_max'])}) | {num(x['gpu_ms_median'])} | "
                     f"{num(x['cpu_ms_median'])} | {num(x['first_frame_ms'], 0)} |")
open(mout, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
