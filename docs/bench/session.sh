#!/usr/bin/env bash
# The live session against rebuilding (issue 17), in one run: a 1-spp frame after a camera move
# through one long-lived renderer against a fresh `Renderer::new` + render; a frame with every
# object of the scene moving against a static frame; the scene-level rebuild of 10,000 moved
# instances. Medians of RUNS alternating runs (runtime/examples/session_bench.rs).
#
#   bash docs/bench/session.sh [--current-lavapipe] [RUNS] [SCENE.rt] [--size WxH]
#
# Default: examples/thesis_scene/scene.rt at 960x540, 7 runs. Prints the CPU (model, AVX2 /
# AVX-512), the adapter and driver, the table and a JSON line. `RTC_PREBUILT=1` uses
# target/release/examples/session_bench as it is, without building it (docs/bench/gpu.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(bash docs/bench/current_lavapipe.sh)
    shift
fi
runs=${1:-7}
shift || true
[[ -n ${RTC_PREBUILT:-} ]] || cargo build --release --quiet -p rtc-runtime --example session_bench
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
source docs/bench/host.sh
"${runner[@]}" target/release/examples/session_bench --runs "$runs" "$@"
