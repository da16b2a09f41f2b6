#!/usr/bin/env bash
# Frame time of the two execution models, megakernel and wavefront, on every example: each
# example rendered at its own size and samples with `--exec megakernel` and `--exec wavefront`,
# alternating, RUNS times each; the median "render" time of each and their ratio (wavefront over
# megakernel; above 1 the wavefront model is slower). The Mesa shader cache is left on, so only
# the first run of each model compiles.
#
#   bash docs/bench/exec_models.sh [--current-lavapipe] [RUNS] [EXAMPLE...]
#
# `SIZE=WxH` renders every example at that size instead of its own (for the long path-traced ones).
# Prints the CPU (model, AVX2 / AVX-512), the adapter and driver, then one line per example, and
# writes the table as JSON to `exec_models.json` in the working directory. `RTC_PREBUILT=1` uses
# target/release/rtc as it is, without building it (docs/bench/gpu.sh, on a machine without Rust).
set -euo pipefail
cd "$(dirname "$0")/../.."
source docs/bench/args.sh
bench_args 5 "$@"
[[ -n ${RTC_PREBUILT:-} ]] || cargo build --release --quiet -p rtc
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
out=$(mktemp -d)
source docs/bench/host.sh
if [[ -n ${SIZE:-} ]]; then echo "every example at $SIZE"; fi
"${runner[@]}" target/release/rtc render examples/hello/scene.rt --size 8x8 -o "$out/probe.png" 2>&1 |
    grep '^adapter' || true
render_ms() {
    "${runner[@]}" target/release/rtc render "examples/$1/scene.rt" -o "$out/$1-$2.png" --exec "$2" \
        ${SIZE:+--size "$SIZE"} 2>&1 |
        awk '$1 == "render" { print $2 }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
json="["
printf '%-14s %12s %12s %8s %s\n' example megakernel wavefront ratio image
for ex in "${examples[@]}"; do
    # One untimed run of each compiles (or loads from the driver's cache) its kernels.
    render_ms "$ex" megakernel > /dev/null
    render_ms "$ex" wavefront > /dev/null
    mega=()
    wave=()
    for ((i = 0; i < runs; i++)); do
        mega+=("$(render_ms "$ex" megakernel)")
        wave+=("$(render_ms "$ex" wavefront)")
    done
    m=$(median "${mega[@]}")
    w=$(median "${wave[@]}")
    ratio=$(awk -v m="$m" -v w="$w" 'BEGIN { printf "%.3f", w / m }')
    same=differs
    cmp -s "$out/$ex-megakernel.png" "$out/$ex-wavefront.png" && same=identical
    printf '%-14s %9.1f ms %9.1f ms %8s %s\n' "$ex" "$m" "$w" "$ratio" "$same"
    json+="{\"example\":\"$ex\",\"megakernel_ms\":$m,\"wavefront_ms\":$w,\"ratio\":$ratio,\"images\":\"$same\"},"
done
json="${json%,}]"
echo "{\"cpu\":\"$cpu ($features)\",\"runs\":$runs,\"examples\":$json}" > exec_models.json
