#!/bin/bash
# Parity with three.js on the Khronos material-extension sample models (issue 42, item 4;
# docs/lighting-models.md "glTF material extensions"): each model (a .gltf is packed into a GLB first,
# gltf_to_glb.py), is centred and scaled to a bounding sphere of radius 1.5 (fit_scene.py), gets 8
# KHR_lights_punctual point lights on a ring and camera 0 (add_lights.py), then
# scripts/perf/parity.sh renders it with three.js r187 and `lightrig render` (camera 0, the file's lights,
# clamp tone map, --msaa 0, 1280x720) and prints PSNR over the pixels three.js covers.
# Usage: scripts/perf/extension_parity.sh [MODEL.gltf|MODEL.glb...]   (default: the extension models under
#        ../shared/models/gltf/khronos). LIGHTRIG_BUILD=DIR picks the build (default build/dev);
#        BASELINE=DIR also renders every scene with DIR/lightrig (another commit's build) and compares it with
#        the same three.js images, so one run gives before and after: a last table, scene, before, now (dB).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
peers=$root/../shared/peers/three
khronos=$root/../shared/models/gltf/khronos
[ -d "$peers" ] || { echo "extension_parity.sh: $peers not found (needs ../shared)" >&2; exit 1; }
models=("$@")
if [ ${#models[@]} -eq 0 ]; then
    for m in ClearCoatTest TransmissionTest SheenChair SpecularTest IridescenceLamp AnisotropyBarnLamp \
        TextureTransformTest MaterialsVariantsShoe MetalRoughSpheresNoTextures; do
        f=$(ls "$khronos/$m"/glTF-Binary/*.glb "$khronos/$m"/glTF/*.gltf 2>/dev/null | head -1 || true)
        [ -n "$f" ] && models+=("$f")
    done
fi
work=$(mktemp -d /tmp/lightrig-extparity.XXXXXX)
echo "scenes: $work" >&2
scenes=()
for m in "${models[@]}"; do
    name=$(basename "${m%.*}")
    glb=$work/$name.glb
    case "$m" in
    *.gltf) python3 "$root/scripts/perf/gltf_to_glb.py" "$m" "$glb" >/dev/null || { echo "skipped $name" >&2; continue; } ;;
    *) cp "$m" "$glb" ;;
    esac
    python3 "$root/scripts/perf/fit_scene.py" "$glb" "$work/${name}_fit.glb" >/dev/null
    python3 "$peers/add_lights.py" "$work/${name}_fit.glb" "$work/${name}_8pt.glb" 8 >/dev/null
    scenes+=("$work/${name}_8pt.glb")
done
"$root/scripts/perf/parity.sh" "${scenes[@]}" 2> >(tee "$work/parity.err" >&2) | tee "$work/parity.txt"
[ -n "${BASELINE:-}" ] || exit 0
images=$(sed -n 's/^images: //p' "$work/parity.err")
build=${LIGHTRIG_BUILD:-$root/build/dev}
printf '\n%-34s %9s %9s\n' scene before_db now_db
for s in "${scenes[@]}"; do
    name=$(basename "$s" .glb)
    xvfb-run -a "$BASELINE/lightrig" render "$s" --camera-index 0 --tonemap clamp --msaa 0 --size 1280x720 \
        -o "$work/baseline_$name.png" >/dev/null 2>&1
    before=$("$build/tests/render/parity_compare" "$work/baseline_$name.png" "$images/three_angle-gl-egl_$name.png" |
        python3 -c "import json,sys; print('%.2f' % json.load(sys.stdin)['psnrDb'])")
    now=$(awk -v n="$name" '$1 == n {print $2}' "$work/parity.txt")
    printf '%-34s %9s %9s\n' "$name" "$before" "$now"
done
