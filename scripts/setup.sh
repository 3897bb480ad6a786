#!/usr/bin/env bash
# Shared by scripts/run and scripts/test: installs the Debian packages LightRig needs
# (only those missing; nothing at all when everything is there), then configures and builds a preset.
set -euo pipefail

LIGHTRIG_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
LIGHTRIG_PACKAGES=(qt6-base-dev libqt6opengl6-dev qt6-base-dev-tools libassimp-dev libglm-dev libmeshoptimizer-dev libembree-dev libopenexr-dev libstb-dev cmake g++
                   ninja-build ccache xvfb xauth libgl1-mesa-dri fonts-dejavu-core parallel
                   openimageio-tools)  # openimageio-tools: oiiotool, which tests read multi-layer EXRs with

lightrig_install_packages() {
    local missing=()
    for p in "${LIGHTRIG_PACKAGES[@]}" "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "lightrig: installing missing packages: ${missing[*]}" >&2
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -q
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# The Khronos glTF validator (npm gltf-validator) for the export tests (tests/export), in a cache folder outside
# the source tree: LIGHTRIG_GLTF_VALIDATOR (the tests read it too; this default otherwise). It needs node and
# npm: Debian's nodejs and npm are installed only when no node is there (NodeSource's nodejs brings npm).
export LIGHTRIG_GLTF_VALIDATOR="${LIGHTRIG_GLTF_VALIDATOR:-${XDG_CACHE_HOME:-$HOME/.cache}/lightrig/gltf-validator}"
LIGHTRIG_GLTF_VALIDATOR_VERSION=2.0.0-dev.3.10

lightrig_install_gltf_validator() {
    { command -v node && command -v npm; } >/dev/null || lightrig_install_packages nodejs npm
    [ -f "$LIGHTRIG_GLTF_VALIDATOR/node_modules/gltf-validator/package.json" ] && return 0
    echo "lightrig: installing gltf-validator@$LIGHTRIG_GLTF_VALIDATOR_VERSION into $LIGHTRIG_GLTF_VALIDATOR" >&2
    mkdir -p "$LIGHTRIG_GLTF_VALIDATOR"
    (cd "$LIGHTRIG_GLTF_VALIDATOR" && npm install --no-audit --no-fund --silent \
        "gltf-validator@$LIGHTRIG_GLTF_VALIDATOR_VERSION" >&2) ||
        echo "lightrig: could not install gltf-validator; the export validation test will say so" >&2
}

lightrig_build() {   # lightrig_build PRESET
    local preset="$1"
    cd "$LIGHTRIG_ROOT"
    # ccache: hash paths relative to the checkout, so build folders and clones share one cache
    export CCACHE_BASEDIR="$LIGHTRIG_ROOT" CCACHE_NOHASHDIR=1
    if [ ! -f "build/$preset/build.ninja" ]; then
        cmake --preset "$preset" >&2
    fi
    cmake --build --preset "$preset" -j"$(nproc)" >&2
}
