#!/usr/bin/env bash
# lavapipe's quick JIT (`GALLIVM_PERF=nopt`, LLVM's optimisation passes off: what `rtc render
# --cpu-jit quick` and `auto` on small renders set, see `runtime/src/gpu/cpu.rs`) against its
# optimising JIT (Mesa's default): every example's cold compile, time to first pixel and frame time
# with each, alternating, and the render size (pixels times spp) at which the quick JIT's compile
# saving is used up by its slower frames.
#
#   bash docs/bench/cpu_jit.sh [--current-lavapipe] [RUNS] [EXAMPLE...]
#
# What is measured and printed: `driver_ab.sh`, whose JSON goes to `cpu_jit.json` in the working
# directory. `EXEC=wavefront` measures the wavefront model; `SIZE=WxH` renders at that size.
set -euo pipefail
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(--current-lavapipe)
    shift
fi
JSON=${JSON:-cpu_jit.json} exec bash "$(dirname "$0")/driver_ab.sh" "${runner[@]}" \
    GALLIVM_PERF optimized= quick=nopt "$@"
