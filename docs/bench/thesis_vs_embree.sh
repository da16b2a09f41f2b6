#!/usr/bin/env bash
# The thesis workload (1920x1080, one camera ray and two shadow rays per pixel, 105,980 triangles)
# traced by Embree 4 (the anchor in ../shared/bench, 2 threads) and by rtc on the default adapter,
# one right after the other, with the ratio of their rays per second.
#
#   bash docs/bench/thesis_vs_embree.sh [--current-lavapipe] [RUNS]
#
# `--current-lavapipe` runs rtc on the current Mesa release's lavapipe (Debian trixie-backports',
# unpacked by docs/bench/current_lavapipe.sh) instead of the system's Vulkan driver.
#
# Needs ../shared/bench and ../shared/models next to the repository (the project's shared folder),
# python3-venv, and a release build of rtc (built here if missing). The Embree side installs
# embreex and numpy into a virtual environment under ${TMPDIR:-/tmp}.
set -euo pipefail
cd "$(dirname "$0")/../.."
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(bash docs/bench/current_lavapipe.sh)
    shift
fi
runs=${1:-3}
shared=../shared
venv=${TMPDIR:-/tmp}/rtc-embree-venv
if [[ ! -x $venv/bin/python ]]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet embreex numpy
fi
cargo build --release --quiet -p rtc
source docs/bench/host.sh
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
out=$(mktemp -d)
"$venv/bin/python" "$shared/bench/embree_bench.py" --models "$shared/models" --scenes thesis \
    --runs "$runs" --out "$out/embree.json" | grep -E "build|thread"
embree_ms=$("$venv/bin/python" -c "
import json
d = json.load(open('$out/embree.json'))
print(d['scenes'][0]['per_threads']['2']['frame_ms'])
")
"${runner[@]}" target/release/rtc render examples/thesis_scene/scene.rt -o "$out/thesis.png" 2>&1 |
    grep -E '^(adapter|host)'
times=()
for _ in $(seq "$runs"); do
    ms=$("${runner[@]}" target/release/rtc render examples/thesis_scene/scene.rt -o "$out/thesis.png" 2>&1 |
        awk '/^  render/ {print $2}')
    echo "rtc render: $ms ms"
    times+=("$ms")
done
median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}')
ratio=$(awk -v e="$embree_ms" -v r="$median" 'BEGIN { printf "%.3f", e / r }')
echo "Embree frame $embree_ms ms (2 threads, median), rtc frame $median ms (median of $runs):" \
    "rtc traces $ratio of Embree's rays per second (goal: 0.5)"
