#!/bin/bash
# Throughput of a batch catalog (issue 17, docs/batch.md): images per minute of `lightrig render` run by
# GNU parallel with 1 and 2 jobs at a time (each job one line of the catalog: a model and a rig, two views),
# and, for comparison, the whole catalog in one `lightrig render` call (one process, one GL context).
# Usage: scripts/perf/catalog_throughput.sh [JOBS...]   (default: 1 2). Environment: SIZE (640x360),
#        VIEWS (front,three-quarter), LIGHTRIG_BUILD (build/dev). Catalog: the bench helmets
#        (../shared/models/bench/helmet_{1pt,8pt,64pt,8spot}.glb) × the pbr-three-point and pbr-rim-heavy
#        presets. Runs itself under xvfb-run -a without a display. Prints one line per run.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ -z "${DISPLAY:-}" ] && [ -z "${CATALOG_THROUGHPUT_XVFB:-}" ]; then
    CATALOG_THROUGHPUT_XVFB=1 exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$0" "$@"
fi
build=${LIGHTRIG_BUILD:-$root/build/dev}
lightrig=$build/lightrig
size=${SIZE:-640x360}
views=${VIEWS:-front,three-quarter}
jobs=("$@")
[ ${#jobs[@]} -gt 0 ] || jobs=(1 2)
command -v parallel >/dev/null || { echo "catalog_throughput.sh: GNU parallel is missing (scripts/setup.sh)" >&2; exit 1; }
models=("$root"/../shared/models/bench/helmet_{1pt,8pt,64pt,8spot}.glb)
[ -f "${models[0]}" ] || { echo "catalog_throughput.sh: ${models[0]} not found (needs ../shared)" >&2; exit 1; }
rigs=("$root"/resources/presets/{pbr-three-point,pbr-rim-heavy}.json)
work=$(mktemp -d /tmp/lightrig-catalog.XXXXXX)
catalog=$work/catalog.tsv # one job a line: MODEL<TAB>RIG
for m in "${models[@]}"; do for r in "${rigs[@]}"; do printf '%s\t%s\n' "$m" "$r"; done; done >"$catalog"
nviews=$(tr ',' '\n' <<<"$views" | wc -l)
expected=$(($(wc -l <"$catalog") * nviews))
echo "catalog: ${#models[@]} models x ${#rigs[@]} rigs x $nviews views = $expected images at $size; $(nproc) CPUs;" \
     "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN { print b - a }'; }
report() { # NAME OUT SECONDS
    local ok
    ok=$(grep -c '"status":"ok"' "$2/summary.jsonl" || true)
    awk -v n="$1" -v ok="$ok" -v all="$expected" -v s="$3" \
        'BEGIN { printf "%-28s %3d/%d images %7.1f s %7.1f images/min\n", n, ok, all, s, ok * 60 / s }'
}
for j in "${jobs[@]}"; do
    out=$work/j$j
    mkdir -p "$out"
    start=$(date +%s.%N)
    parallel -j"$j" --colsep '\t' "$lightrig" render {1} --rig {2} --view "$views" --size "$size" -o "$out/" \
        --summary - :::: "$catalog" >"$out/summary.jsonl" 2>"$out/stderr.txt" || true
    report "parallel -j$j" "$out" "$(since "$start")"
done
out=$work/one
mkdir -p "$out"
rigargs=()
for r in "${rigs[@]}"; do rigargs+=(--rig "$r"); done
start=$(date +%s.%N)
"$lightrig" render "${models[@]}" "${rigargs[@]}" --view "$views" --size "$size" -o "$out/" \
    --summary "$out/summary.jsonl" >/dev/null 2>"$out/stderr.txt" || true
report "one process, whole catalog" "$out" "$(since "$start")"
echo "images and summaries: $work" >&2
