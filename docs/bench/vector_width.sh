#!/usr/bin/env bash
# llvmpipe's SIMD width against compile time and frame time: every example rendered with
# `LP_NATIVE_VECTOR_WIDTH=256` (Mesa's default on AVX2 and AVX-512 CPUs: 8 invocations a batch) and
# `=128` (4 a batch; what `rtc` sets for itself on lavapipe before Mesa 26 unless the variable is set, see
# `runtime/src/gpu/cpu.rs`), alternating.
#
#   bash docs/bench/vector_width.sh [--current-lavapipe] [RUNS] [EXAMPLE...]
#
# What is measured and printed: `driver_ab.sh`, whose JSON goes to `vector_width.json` in the working
# directory. `EXEC=wavefront` measures the wavefront model; `SIZE=WxH` renders at that size.
set -euo pipefail
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(--current-lavapipe)
    shift
fi
JSON=${JSON:-vector_width.json} exec bash "$(dirname "$0")/driver_ab.sh" "${runner[@]}" \
    LP_NATIVE_VECTOR_WIDTH 256=256 128=128 "$@"
