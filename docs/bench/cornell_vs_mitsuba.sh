#!/usr/bin/env bash
# Error against run time: rtc's path-traced Cornell box (examples/cornell_path/scene.rt) against
# Mitsuba 3 rendering the same scene (docs/bench/cornell_mitsuba.py), both measured against one
# converged Mitsuba reference, with the equal-error time ratio (`rtc bench --against`) and a plot.
#
#   bash docs/bench/cornell_vs_mitsuba.sh [--current-lavapipe] [--glass] [SIZE] [SPP_LIST] [REF_SPP] [OUT]
#
# Defaults: 256x256, levels 1,4,16,64, reference 4096 spp, OUT a new temporary folder. RUNS=N in
# the environment renders every level of both renderers N times (in rounds over the levels) and
# compares the median times (default 1: the VMs' speed drifts by 2 to 13 % over minutes). The full
# run of docs/bench/README.md: `bash docs/bench/cornell_vs_mitsuba.sh 512x512 1,4,16,64,256`.
# `--current-lavapipe` runs rtc on the current Mesa release's lavapipe (docs/bench/current_lavapipe.sh).
# `--glass` measures docs/bench/cornell_glass.rt instead (a glass ball for the short box; Mitsuba's
# `dielectric`) and also prints the means over the ball's pixels.
#
# Mitsuba 3.9.1 and numpy are installed with pip into ${XDG_CACHE_HOME:-~/.cache}/rtc/mitsuba-venv
# (python3-venv needed). Its `llvm_ad_rgb` variant needs LLVM's shared library: Debian 12's
# `libllvm19` (`apt-get install libllvm19`), found here or given as DRJIT_LIBLLVM_PATH; without it
# the script says so and falls back to the (much slower) `scalar_rgb` variant. MITSUBA_VARIANT
# overrides the choice.
#
# Prints: Mitsuba's table (spp, seconds, RMSE), rtc's (`rtc bench`: spp, ms, RMSE, ...), the
# equal-error time ratio rtc / Mitsuba at each of rtc's levels and their geometric mean, and the
# per-channel means of the reference, Mitsuba's and rtc's renders at the largest level (the check
# that the two scenes match). Mitsuba renders one more level, 4x the largest, so that the curves
# overlap at rtc's largest level. Files in OUT: reference.exr, mitsuba.csv, rtc.csv, rtc.json,
# cornell_vs_mitsuba.svg, mitsuba_<N>.exr, rtc_<N>.exr.
set -euo pipefail
cd "$(dirname "$0")/../.."
runner=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner=(bash docs/bench/current_lavapipe.sh)
    shift
fi
scene=examples/cornell_path/scene.rt
glass=()
if [[ ${1:-} == --glass ]]; then
    scene=docs/bench/cornell_glass.rt
    glass=(--glass)
    shift
fi
size=${1:-256x256}
levels=${2:-1,4,16,64}
ref_spp=${3:-4096}
out=${4:-$(mktemp -d)}
mkdir -p "$out"
largest=$(tr ',' '\n' <<<"$levels" | sort -g | tail -1)

venv=${XDG_CACHE_HOME:-$HOME/.cache}/rtc/mitsuba-venv
if [[ ! -x $venv/bin/python ]] || ! "$venv/bin/python" -c "import mitsuba" 2>/dev/null; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet mitsuba==3.9.1 numpy
fi
if [[ -z ${MITSUBA_VARIANT:-} ]]; then
    if [[ -z ${DRJIT_LIBLLVM_PATH:-} ]]; then
        for f in /usr/lib/x86_64-linux-gnu/libLLVM.so.19* /usr/lib/x86_64-linux-gnu/libLLVM-19.so \
            /usr/lib/llvm-19/lib/libLLVM.so*; do
            if [[ -e $f ]]; then
                export DRJIT_LIBLLVM_PATH=$f
                break
            fi
        done
    fi
    if [[ -n ${DRJIT_LIBLLVM_PATH:-} ]]; then
        export MITSUBA_VARIANT=llvm_ad_rgb
    else
        echo "no LLVM 19 shared library (apt-get install libllvm19, or set DRJIT_LIBLLVM_PATH):" \
            "Mitsuba runs its scalar_rgb variant" >&2
        export MITSUBA_VARIANT=scalar_rgb
    fi
fi
source docs/bench/host.sh

cargo build --release --quiet -p rtc
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
# Mitsuba also renders 4x the largest level: at equal samples rtc's error is a little lower, so
# without it rtc's largest level would fall outside Mitsuba's curve and get no ratio.
"$venv/bin/python" docs/bench/cornell_mitsuba.py "$out" "${glass[@]}" --size "$size" \
    --spp-list "$levels,$((largest * 4))" \
    --ref-spp "$ref_spp" --keep "$largest" --runs "${RUNS:-1}"
"${runner[@]}" target/release/rtc bench "$scene" --size "$size" \
    --reference "$out/reference.exr" --spp-list "$levels" --runs "${RUNS:-1}" --against "$out/mitsuba.csv" \
    --csv "$out/rtc.csv" --json "$out/rtc.json" --plot "$out/cornell_vs_mitsuba.svg"
"${runner[@]}" target/release/rtc render "$scene" --size "$size" \
    --spp "$largest" -o "$out/rtc_$largest.exr" 2>&1 | grep -E '^adapter|^  render'
"$venv/bin/python" docs/bench/cornell_mitsuba.py "$out" "${glass[@]}" --means "$out/reference.exr" \
    "$out/mitsuba_$largest.exr" "$out/rtc_$largest.exr"
echo "files in $out"
