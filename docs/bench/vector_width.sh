#!/usr/bin/env bash
# llvmpipe's SIMD width against compile time and frame time: every example rendered with
# `LP_NATIVE_VECTOR_WIDTH=256` (Mesa's default on AVX2 and AVX-512 CPUs: 8 invocations a batch) and
# `=128` (4 a batch; what `rtc` sets for itself on lavapipe before Mesa 26 unless the variable is set, see
# `runtime/src/gpu/cpu.rs`), alternating.
#
#   bash docs/bench/vector_width.sh [--current-lavapipe] [RUNS] [EXAMPLE...]
#
# For each example and width: the cold compile (`MESA_SHADER_CACHE_DISABLE=true`,
# `RTC_PIPELINE_CACHE=off`, 64x48 at 1 spp: the "pipelines" time of the summary, which is the
# driver's compile, and the wall time of the whole `rtc render`, that is the time to first pixel),
# then RUNS renders at the example's own size and samples with the shader cache on (the median of
# the "render" times), and whether the two widths' images are byte-identical. `EXEC=wavefront`
# measures the wavefront model instead of the megakernel; `SIZE=WxH` renders at that size.
# Prints the CPU (model, AVX2 / AVX-512) and the driver first; writes the table as JSON to
# `vector_width.json` in the working directory.
set -euo pipefail
cd "$(dirname "$0")/../.."
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(bash docs/bench/current_lavapipe.sh)
    shift
fi
runs=${1:-3}
shift || true
examples=("$@")
if [[ ${#examples[@]} -eq 0 ]]; then
    for d in examples/*/; do
        [[ -f $d/scene.rt ]] && examples+=("$(basename "$d")")
    done
fi
exec_model=${EXEC:-megakernel}
cargo build --release --quiet -p rtc
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
out=$(mktemp -d)
unset LP_NATIVE_VECTOR_WIDTH
LP_NATIVE_VECTOR_WIDTH="256 and 128, set for each run"
source docs/bench/host.sh
unset LP_NATIVE_VECTOR_WIDTH
echo "execution model: $exec_model${SIZE:+, every example at $SIZE}"
"${runner[@]}" target/release/rtc render examples/hello/scene.rt --size 8x8 -o "$out/probe.png" 2>&1 |
    grep '^adapter' || true
# cold EXAMPLE WIDTH: "PIPELINES_MS WALL_MS" of a cold 64x48 render.
cold() {
    local start end pipes
    start=$(date +%s%N)
    pipes=$(env MESA_SHADER_CACHE_DISABLE=true RTC_PIPELINE_CACHE=off LP_NATIVE_VECTOR_WIDTH="$2" \
        "${runner[@]}" target/release/rtc render "examples/$1/scene.rt" -o "$out/cold.png" \
        --exec "$exec_model" --size 64x48 --spp 1 2>&1 | awk '$1 == "pipelines" { print $2 }')
    end=$(date +%s%N)
    echo "${pipes:-nan} $(((end - start) / 1000000))"
}
# render_ms EXAMPLE WIDTH: the "render" milliseconds of a render at the example's own settings.
render_ms() {
    LP_NATIVE_VECTOR_WIDTH="$2" "${runner[@]}" target/release/rtc render "examples/$1/scene.rt" \
        -o "$out/$1-$2.png" --exec "$exec_model" ${SIZE:+--size "$SIZE"} 2>&1 |
        awk '$1 == "render" { print $2 }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
json="["
printf '%-14s %22s %22s %24s %7s %s\n' example "cold 256: driver/wall" "cold 128: driver/wall" \
    "frame 256 / 128 (median)" ratio image
for ex in "${examples[@]}"; do
    read -r p256 w256 <<<"$(cold "$ex" 256)"
    read -r p128 w128 <<<"$(cold "$ex" 128)"
    # One untimed run of each width fills the driver's cache.
    render_ms "$ex" 256 >/dev/null
    render_ms "$ex" 128 >/dev/null
    f256=()
    f128=()
    for ((i = 0; i < runs; i++)); do
        f256+=("$(render_ms "$ex" 256)")
        f128+=("$(render_ms "$ex" 128)")
    done
    m256=$(median "${f256[@]}")
    m128=$(median "${f128[@]}")
    ratio=$(awk -v a="$m256" -v b="$m128" 'BEGIN { printf "%.3f", b / a }')
    same=differs
    cmp -s "$out/$ex-256.png" "$out/$ex-128.png" && same=identical
    printf '%-14s %10.0f / %7s ms %10.0f / %7s ms %10.1f / %8.1f ms %7s %s\n' "$ex" "$p256" "$w256" \
        "$p128" "$w128" "$m256" "$m128" "$ratio" "$same"
    json+="{\"example\":\"$ex\",\"cold_driver_ms_256\":$p256,\"first_pixel_ms_256\":$w256,"
    json+="\"cold_driver_ms_128\":$p128,\"first_pixel_ms_128\":$w128,\"frame_ms_256\":$m256,"
    json+="\"frame_ms_128\":$m128,\"frame_ratio\":$ratio,\"images\":\"$same\"},"
done
echo "${json%,}]" >vector_width.json
rm -rf "$out"
