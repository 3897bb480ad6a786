#!/usr/bin/env bash
# Renders the same matrix of scenes with two lightrig executables and compares the PNGs byte for byte: the
# check that a refactoring moved no pixel. Every bundled preset on the bundled Suzanne and on a physically
# based model (tests/data/model/pbr.gltf, or the helmet when ../shared is there), in every quality tier,
# with the rig's own settings, again with shadows, a ground and the studio environment forced on, and with
# shadows over a shadow catcher in a transparent image.
#   scripts/perf/identical_sweep.sh BEFORE_LIGHTRIG AFTER_LIGHTRIG [OUT_DIR]
# PRESETS="default three-point" and TIERS="exact" narrow the matrix (default: every preset, every tier).
# Prints one line per image that differs and a summary `N identical, M differ`; exit 0 only when all match.
# Run under a display (xvfb-run -a) or let it start one. Example (2026-12-06, before/after a shader split):
#   cp build/dev/lightrig /tmp/lightrig-before   # at the old commit
#   scripts/perf/identical_sweep.sh /tmp/lightrig-before build/dev/lightrig
set -euo pipefail
before="${1:?usage: identical_sweep.sh BEFORE_LIGHTRIG AFTER_LIGHTRIG [OUT_DIR]}"
after="${2:?usage: identical_sweep.sh BEFORE_LIGHTRIG AFTER_LIGHTRIG [OUT_DIR]}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="${3:-$(mktemp -d)}"
mkdir -p "$out/before" "$out/after"
if [ -z "${DISPLAY:-}" ]; then exec xvfb-run -a -s "-screen 0 1280x1024x24" "$0" "$before" "$after" "$out"; fi
export LIBGL_ALWAYS_SOFTWARE=1 QT_QPA_PLATFORM=xcb

models=("$root/resources/models/suzanne/Suzanne.gltf" "$root/tests/data/model/pbr.gltf")
helmet="$root/../shared/models/bench/helmet_8spot.glb"
[ -f "$helmet" ] && models+=("$helmet")
extras=("" "--shadows on --ground visible --environment $root/resources/environments/studio.exr"
        "--shadows on --ground catcher --transparent")
same=0
differ=0
for model in "${models[@]}"; do
    [ -f "$model" ] || { echo "identical_sweep: no $model" >&2; exit 2; }
    for preset in ${PRESETS:-$(cd "$root/resources/presets" && ls *.json | sed 's/\.json$//')}; do
        rig="$root/resources/presets/$preset.json"
        for quality in ${TIERS:-fast balanced exact}; do
            for e in "${!extras[@]}"; do
                name="$(basename "${model%.*}")_$(basename "${rig%.json}")_${quality}_$e.png"
                # shellcheck disable=SC2086
                for side in before after; do
                    exe="$before"
                    [ "$side" = after ] && exe="$after"
                    "$exe" render "$model" --rig "$rig" --quality "$quality" --size 320x180 ${extras[$e]} \
                        -o "$out/$side/$name" >/dev/null 2>"$out/$side/$name.log" || echo "exit $? $side $name"
                done
                if cmp -s "$out/before/$name" "$out/after/$name"; then
                    same=$((same + 1))
                else
                    differ=$((differ + 1))
                    echo "differs: $name"
                fi
            done
        done
    done
done
echo "$same identical, $differ differ (images in $out)"
[ "$differ" -eq 0 ]
