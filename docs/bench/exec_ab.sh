#!/usr/bin/env bash
# The wavefront frame of this checkout against another build of rtc (OTHER, e.g. a worktree of an
# earlier commit built with `cargo build --release -p rtc`), with this checkout's megakernel as the
# anchor of both: every example rendered at its own size and samples, the three alternating
# (megakernel, OTHER's wavefront, this wavefront) RUNS times each after one untimed run of each
# (which compiles, or loads from the driver's cache); the median "render" time of each, and the
# ratios this/OTHER and each wavefront over the megakernel (above 1 the wavefront is slower).
#
#   bash docs/bench/exec_ab.sh [--current-lavapipe] OTHER_RTC [RUNS] [EXAMPLE...]
#
# OTHER reads its own stdlib (the one of the checkout it was built in). Prints the CPU (model,
# AVX2 / AVX-512), the adapter and driver, then one line per example, and writes the table as
# JSON to `exec_ab.json` in the working directory.
set -euo pipefail
cd "$(dirname "$0")/../.."
runner_flag=()
if [[ ${1:-} == --current-lavapipe ]]; then
    runner_flag=(--current-lavapipe)
    shift
fi
other=${1:?usage: exec_ab.sh [--current-lavapipe] OTHER_RTC [RUNS] [EXAMPLE...]}
shift
[[ -x $other ]] || { echo "exec_ab.sh: $other is not an executable" >&2; exit 2; }
source docs/bench/args.sh
bench_args 3 "${runner_flag[@]}" "$@"
cargo build --release --quiet -p rtc
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
out=$(mktemp -d)
source docs/bench/host.sh
"${runner[@]}" target/release/rtc render examples/hello/scene.rt --size 8x8 -o "$out/probe.png" 2>&1 |
    grep '^adapter' || true
# render_ms BINARY EXAMPLE EXEC TAG
render_ms() {
    "${runner[@]}" "$1" render "examples/$2/scene.rt" -o "$out/$2-$4.png" --exec "$3" 2>&1 |
        awk '$1 == "render" { print $2 }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
this=target/release/rtc
json="["
printf '%-14s %11s %11s %11s %9s %9s %9s %s\n' example megakernel other this this/other other/mega this/mega image
for ex in "${examples[@]}"; do
    render_ms "$this" "$ex" megakernel mega > /dev/null
    render_ms "$other" "$ex" wavefront other > /dev/null
    render_ms "$this" "$ex" wavefront this > /dev/null
    m=() o=() t=()
    for ((i = 0; i < runs; i++)); do
        m+=("$(render_ms "$this" "$ex" megakernel mega)")
        o+=("$(render_ms "$other" "$ex" wavefront other)")
        t+=("$(render_ms "$this" "$ex" wavefront this)")
    done
    mm=$(median "${m[@]}")
    om=$(median "${o[@]}")
    tm=$(median "${t[@]}")
    ratios=$(awk -v m="$mm" -v o="$om" -v t="$tm" 'BEGIN { printf "%.3f %.3f %.3f", t / o, o / m, t / m }')
    read -r r_to r_om r_tm <<< "$ratios"
    same=differs
    cmp -s "$out/$ex-mega.png" "$out/$ex-this.png" && same=identical
    printf '%-14s %8.1f ms %8.1f ms %8.1f ms %9s %9s %9s %s\n' "$ex" "$mm" "$om" "$tm" "$r_to" "$r_om" "$r_tm" "$same"
    json+="{\"example\":\"$ex\",\"megakernel_ms\":$mm,\"other_wavefront_ms\":$om,\"wavefront_ms\":$tm,\"wavefront_over_other\":$r_to,\"other_over_megakernel\":$r_om,\"wavefront_over_megakernel\":$r_tm,\"images\":\"$same\"},"
done
json="${json%,}]"
echo "{\"cpu\":\"$cpu ($features)\",\"other\":\"$other\",\"runs\":$runs,\"examples\":$json}" > exec_ab.json
