#!/usr/bin/env bash
# Every example's default render (its scene's own size and samples), cold, with the JIT `rtc`
# chooses (`--cpu-jit auto`) against the optimising one (`--cpu-jit optimized`, what `auto` gave
# such renders before the choice looked at the compiled scene; docs/bench/compile.md, "The quick
# JIT for a scene's own size (2026-12-04)"), alternated: wall time of the whole command, whether
# `auto` chose the quick JIT, and whether the two images are byte-identical.
#
#   bash docs/bench/default_renders.sh [--current-lavapipe] [RUNS] [EXAMPLE...]
#
# Cold: `MESA_SHADER_CACHE_DISABLE=true RTC_PIPELINE_CACHE=off`. RUNS defaults to 2; EXAMPLE
# defaults to every folder of examples/ with a scene.rt. Images go to a temporary folder.
set -euo pipefail
cd "$(dirname "$0")/../.."
source docs/bench/args.sh
bench_args 2 "$@"
source docs/bench/host.sh
cargo build --release --quiet -p rtc
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
out=$(mktemp -d)
printf '%-14s %-9s %s\n' example auto "seconds: auto / optimized, alternated"
for e in "${examples[@]}"; do
    times=()
    quick=no
    for _ in $(seq "$runs"); do
        for jit in auto optimized; do
            start=$(date +%s.%N)
            log=$(MESA_SHADER_CACHE_DISABLE=true RTC_PIPELINE_CACHE=off "${runner[@]}" \
                target/release/rtc render "examples/$e/scene.rt" --cpu-jit "$jit" \
                -o "$out/${e}_$jit.png" 2>&1)
            end=$(date +%s.%N)
            times+=("$jit $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')")
            if [[ $jit == auto ]] && grep -q '^host: .*GALLIVM_PERF=nopt' <<<"$log"; then
                quick=quick
            fi
        done
    done
    same=differ
    cmp -s "$out/${e}_auto.png" "$out/${e}_optimized.png" && same=identical
    printf '%-14s %-9s %s (images %s)\n' "$e" "$quick" "$(IFS=,; echo "${times[*]}")" "$same"
done
rm -rf "$out"
