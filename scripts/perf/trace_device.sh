#!/usr/bin/env bash
# trace_device.sh [BUNDLE.tar.xz]: the path tracer's thread scaling (issue 36, item 6c) on another machine,
# from the bundle scripts/perf/gpu_bundle.sh makes (default .gpubundle/bundle.tar.xz): unpacks it, makes
# the helmet_1pt scene from the bundled DamagedHelmet (python3), and runs scripts/perf/trace_bench.sh with
# the bundled binary, no display (the path tracer needs no OpenGL) and THREADS (default 1 2 4 8 16, and the
# machine's core count when it is larger), then the aim (bench's path ladder). Results: $OUT/trace.md (default /tmp/lightrig-trace-out).
#   SAMPLES (per timed render, default 16), SIZES, SCALING_SIZE as trace_bench.sh takes them.
# On this machine, to check the bundle: scripts/perf/gpu_bundle.sh && THREADS="1 2" scripts/perf/trace_device.sh
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
tarball="${1:-$root/.gpubundle/bundle.tar.xz}"
out="${OUT:-/tmp/lightrig-trace-out}"
work="${LR_TRACE_WORK:-/tmp/lightrig-trace-work}"
mkdir -p "$out" "$work"
rm -rf "$work/lightrig-gpu"
tar -xJf "$tarball" -C "$work" 2>/dev/null ||
    python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$tarball" "$work"
R="$work/lightrig-gpu"
python3 "$R/scenes/add_lights.py" "$R/scenes/DamagedHelmet.glb" "$R/scenes/helmet_1pt.glb" 1 >/dev/null
cores=$(nproc)
threads=${THREADS:-"1 2 4 8 16$([ "$cores" -le 16 ] || echo " $cores")"}
export LD_LIBRARY_PATH="$R/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" QT_PLUGIN_PATH="$R/plugins"
export QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$work/xdg}"
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
{
    echo "Machine: $(uname -sr), $(grep -m1 PRETTY_NAME /etc/os-release | cut -d= -f2 | tr -d '"'), $cores cores"
    echo
    LIGHTRIG="$R/bin/lightrig" THREADS="$threads" "$root/scripts/perf/trace_bench.sh" "$R/scenes/helmet_1pt.glb"
} 2>&1 | tee "$out/trace.md"
