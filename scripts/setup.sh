#!/usr/bin/env bash
# Shared by scripts/run and scripts/test: installs the Debian packages LightRig needs
# (only those missing; nothing at all when everything is there), then configures and builds a preset.
set -euo pipefail

LIGHTRIG_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
LIGHTRIG_PACKAGES=(qt6-base-dev libqt6opengl6-dev qt6-base-dev-tools libassimp-dev libglm-dev libmeshoptimizer-dev libembree-dev libopenexr-dev libstb-dev cmake g++
                   ninja-build ccache xvfb xauth libgl1-mesa-dri fonts-dejavu-core parallel)

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
