#!/usr/bin/env bash
# Two settings of one of Mesa's variables for llvmpipe against compile time and frame time: every
# example rendered with VAR=A and VAR=B, alternating. `vector_width.sh` (LP_NATIVE_VECTOR_WIDTH) and
# `cpu_jit.sh` (GALLIVM_PERF, rtc's `--cpu-jit`) are this script with their variable.
#
#   bash docs/bench/driver_ab.sh [--current-lavapipe] VAR LABEL_A=A LABEL_B=B [RUNS] [EXAMPLE...]
#
# An empty value (`optimized=`) sets the variable empty, which rtc counts as set (it then adds
# nothing of its own) and Mesa as unset. For each example and setting: the cold compile
# (`MESA_SHADER_CACHE_DISABLE=true`, `RTC_PIPELINE_CACHE=off`, 64x48 at 1 spp: the "pipelines" time
# of the summary, which is the driver's compile, and the wall time of the whole `rtc render`, that
# is the time to first pixel), then RUNS renders at the example's own size and samples with the
# shader cache on (the median of the "render" times), whether the two settings' images are
# byte-identical, and the break-even: the samples (pixels times spp) of a render at which B's
# compile saving equals its frame cost over A (`inf` when B's frames are not slower, `-` when its
# compile is not shorter). `EXEC=wavefront` measures the wavefront model instead of the megakernel;
# `SIZE=WxH` renders at that size. Prints the CPU (model, AVX2 / AVX-512) and the driver first;
# writes the table as JSON to `LABEL_A-LABEL_B.json` (or `$JSON`) in the working directory.
set -euo pipefail
called_from=$PWD
cd "$(dirname "$0")/../.."
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(bash docs/bench/current_lavapipe.sh)
    shift
fi
if [[ $# -lt 3 || $2 != *=* || $3 != *=* ]]; then
    echo "usage: bash docs/bench/driver_ab.sh [--current-lavapipe] VAR LABEL_A=A LABEL_B=B [RUNS] [EXAMPLE...]" >&2
    exit 2
fi
var=$1
label_a=${2%%=*} value_a=${2#*=}
label_b=${3%%=*} value_b=${3#*=}
shift 3
runs=${1:-3}
shift || true
examples=("$@")
if [[ ${#examples[@]} -eq 0 ]]; then
    for d in examples/*/; do
        [[ -f $d/scene.rt ]] && examples+=("$(basename "$d")")
    done
fi
exec_model=${EXEC:-megakernel}
json_out=${JSON:-$label_a-$label_b.json}
[[ $json_out == /* ]] || json_out=$called_from/$json_out
cargo build --release --quiet -p rtc
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
out=$(mktemp -d)
unset "$var"
declare "$var=$label_a and $label_b, set for each run"
export "${var?}"
source docs/bench/host.sh
unset "$var"
echo "execution model: $exec_model${SIZE:+, every example at $SIZE}"
"${runner[@]}" target/release/rtc render examples/hello/scene.rt --size 8x8 -o "$out/probe.png" 2>&1 |
    grep '^adapter' || true
# cold EXAMPLE VALUE: "PIPELINES_MS WALL_MS" of a cold 64x48 render.
cold() {
    local start end pipes
    start=$(date +%s%N)
    pipes=$(env MESA_SHADER_CACHE_DISABLE=true RTC_PIPELINE_CACHE=off "$var=$2" \
        "${runner[@]}" target/release/rtc render "examples/$1/scene.rt" -o "$out/cold.png" \
        --exec "$exec_model" --size 64x48 --spp 1 2>&1 | awk '$1 == "pipelines" { print $2 }')
    end=$(date +%s%N)
    echo "${pipes:-nan} $(((end - start) / 1000000))"
}
# render EXAMPLE LABEL VALUE: "RENDER_MS SAMPLES" of a render at the example's own settings.
render() {
    env "$var=$3" "${runner[@]}" target/release/rtc render "examples/$1/scene.rt" \
        -o "$out/$1-$2.png" --exec "$exec_model" ${SIZE:+--size "$SIZE"} 2>&1 |
        awk '$1 == "render" { ms = $2 } $1 == "rendered" { split($2, s, "x"); n = s[1] * s[2] * $4 }
             END { print ms, n }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
json="["
printf '%-14s %24s %24s %26s %7s %9s %12s\n' example "cold $label_a: driver/wall" \
    "cold $label_b: driver/wall" "frame $label_a / $label_b (median)" ratio image "break-even"
for ex in "${examples[@]}"; do
    read -r pa wa <<<"$(cold "$ex" "$value_a")"
    read -r pb wb <<<"$(cold "$ex" "$value_b")"
    # One untimed run of each setting fills the driver's cache.
    render "$ex" "$label_a" "$value_a" >/dev/null
    render "$ex" "$label_b" "$value_b" >/dev/null
    fa=()
    fb=()
    for ((i = 0; i < runs; i++)); do
        read -r ms samples <<<"$(render "$ex" "$label_a" "$value_a")"
        fa+=("$ms")
        read -r ms samples <<<"$(render "$ex" "$label_b" "$value_b")"
        fb+=("$ms")
    done
    ma=$(median "${fa[@]}")
    mb=$(median "${fb[@]}")
    ratio=$(awk -v a="$ma" -v b="$mb" 'BEGIN { printf "%.3f", b / a }')
    even=$(awk -v pa="$pa" -v pb="$pb" -v fa="$ma" -v fb="$mb" -v n="$samples" 'BEGIN {
        if (pb >= pa) print "-"; else if (fb <= fa) print "inf"; else printf "%.0f", n * (pa - pb) / (fb - fa) }')
    same=differs
    cmp -s "$out/$ex-$label_a.png" "$out/$ex-$label_b.png" && same=identical
    printf '%-14s %12.0f / %7s ms %12.0f / %7s ms %12.1f / %9.1f ms %7s %9s %12s\n' "$ex" "$pa" "$wa" \
        "$pb" "$wb" "$ma" "$mb" "$ratio" "$same" "$even"
    [[ $even =~ ^[0-9]+$ ]] || even="\"$even\""
    json+="{\"example\":\"$ex\",\"cold_driver_ms_$label_a\":$pa,\"first_pixel_ms_$label_a\":$wa,"
    json+="\"cold_driver_ms_$label_b\":$pb,\"first_pixel_ms_$label_b\":$wb,\"frame_ms_$label_a\":$ma,"
    json+="\"frame_ms_$label_b\":$mb,\"frame_ratio\":$ratio,\"frame_samples\":${samples:-0},"
    json+="\"break_even_samples\":$even,\"images\":\"$same\"},"
done
echo "${json%,}]" >"$json_out"
rm -rf "$out"
