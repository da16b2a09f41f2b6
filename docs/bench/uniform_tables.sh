#!/usr/bin/env bash
# Small tables in uniform buffers against compile time and frame time: every example rendered with
# `RTC_UNIFORM_TABLES=off` (every table a storage buffer, as compiled) and `=on` (`nodes` and
# `instances` as uniform buffers where they fit in 64 KiB; what `rtc` does by itself on lavapipe
# before Mesa 26, `runtime/src/scene/tables.rs`), alternating.
#
#   bash docs/bench/uniform_tables.sh [--current-lavapipe] [RUNS] [EXAMPLE...]
#
# What is measured and printed: `driver_ab.sh`, whose JSON goes to `uniform_tables.json` in the
# working directory. `EXEC=wavefront` measures the wavefront model; `SIZE=WxH` renders at that size;
# `GALLIVM_PERF=` (set and empty) keeps the optimising JIT for the cold 64x48 compile, which `rtc`
# would otherwise give the quick one.
set -euo pipefail
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(--current-lavapipe)
    shift
fi
JSON=${JSON:-uniform_tables.json} exec bash "$(dirname "$0")/driver_ab.sh" "${runner[@]}" \
    RTC_UNIFORM_TABLES storage=off uniform=on "$@"
