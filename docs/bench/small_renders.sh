#!/usr/bin/env bash
# Time to first pixel of a small still render (a preview): every example rendered at SIZE and 1 spp
# (default 128x128, 16,384 samples: the most `WAVEFRONT_PREVIEW_MAX_SAMPLES` gives the automatic
# choice), cold, with the execution model `rtc render` chooses for a scene left at `EXEC_AUTO`
# against `--exec wavefront` and `--exec megakernel`, alternated: wall time of the whole command,
# the model the automatic choice ran, and whether the images are byte-identical.
#
#   bash docs/bench/small_renders.sh [--current-lavapipe] [RUNS] [EXAMPLE...]
#
# Cold: `MESA_SHADER_CACHE_DISABLE=true RTC_PIPELINE_CACHE=off`. RUNS defaults to 2 (the median
# is printed, then every run); EXAMPLE defaults to every folder of examples/ with a scene.rt.
# `SIZE=WxH` renders at that size. docs/bench/compile.md, "Which model compiles faster, with
# uniform tables (2026-12-04)", has what decides the choice.
set -euo pipefail
cd "$(dirname "$0")/../.."
source docs/bench/args.sh
bench_args 2 "$@"
size=${SIZE:-128x128}
source docs/bench/host.sh
cargo build --release --quiet -p rtc
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
out=$(mktemp -d)
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
echo "every example at $size, 1 spp, cold; seconds of the whole rtc render, medians of $runs"
printf '%-14s %-11s %8s %10s %11s  %s\n' example "auto runs" auto wavefront megakernel images
for e in "${examples[@]}"; do
    declare -A times=([auto]="" [wavefront]="" [megakernel]="")
    chose=megakernel
    for _ in $(seq "$runs"); do
        for exec in auto wavefront megakernel; do
            flag=()
            [[ $exec == auto ]] || flag=(--exec "$exec")
            start=$(date +%s.%N)
            log=$(MESA_SHADER_CACHE_DISABLE=true RTC_PIPELINE_CACHE=off "${runner[@]}" \
                target/release/rtc render "examples/$e/scene.rt" --size "$size" --spp 1 \
                "${flag[@]}" -o "$out/${e}_$exec.png" 2>&1)
            end=$(date +%s.%N)
            times[$exec]+=" $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')"
            if [[ $exec == auto ]] && grep -q '^exec: wavefront' <<<"$log"; then
                chose=wavefront
            fi
        done
    done
    same=differ
    cmp -s "$out/${e}_auto.png" "$out/${e}_wavefront.png" &&
        cmp -s "$out/${e}_auto.png" "$out/${e}_megakernel.png" && same=identical
    # shellcheck disable=SC2086
    printf '%-14s %-11s %8.2f %10.2f %11.2f  %s (auto:%s; wavefront:%s; megakernel:%s)\n' "$e" \
        "$chose" "$(median ${times[auto]})" "$(median ${times[wavefront]})" \
        "$(median ${times[megakernel]})" "$same" "${times[auto]}" "${times[wavefront]}" \
        "${times[megakernel]}"
    unset times
done
rm -rf "$out"
