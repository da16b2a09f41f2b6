#!/usr/bin/env bash
# Scaling of `rtc check` and `rtc compile` with the size of the input (issue 21, item 3).
#
# Generates, for each size N, a scene file whose one function `big` has N `let` statements (a chain:
# each `let` reads the one before, so no unused-variable warnings), a function of N unused `let`s
# on one line (N W0001 warnings, each quoting that line: the case of issue 21), and a file of N/10
# small functions of ten statements each (the shape of tests/fuzz.rs's 10 MB valid file). Runs
# `rtc check` on each, and `rtc compile` (all five targets) on the one-function scene, under
# `/usr/bin/time -v`, and prints a Markdown table of wall time and peak memory (max RSS).
#
# Usage: docs/bench/checker_scaling.sh [RTC_BINARY] [SIZES] [COMPILE_SIZES]
#   RTC_BINARY     default target/release/rtc if it exists, else target/debug/rtc
#   SIZES          default "10000 100000 1000000"
#   COMPILE_SIZES  default "10000 100000" (the sizes also compiled; "" for none)
# Environment: RTC_BENCH_TIMEOUT (seconds per run, default 180): a run that takes longer is stopped
# and shown as `>TIMEOUT`. RTC_BENCH_DIR: keep the generated files and outputs in this folder.
set -euo pipefail

root="$(cd "$(dirname "$0")/../.." && pwd)"
rtc="${1:-}"
if [[ -z "$rtc" ]]; then
    if [[ -x "$root/target/release/rtc" ]]; then rtc="$root/target/release/rtc"; else rtc="$root/target/debug/rtc"; fi
fi
sizes="${2:-10000 100000 1000000}"
compile_sizes="${3-10000 100000}"
limit="${RTC_BENCH_TIMEOUT:-180}"
if [[ -n "${RTC_BENCH_DIR:-}" ]]; then
    work="$RTC_BENCH_DIR"
    mkdir -p "$work"
else
    work="$(mktemp -d)"
    trap 'rm -rf "$work"' EXIT
fi

# One function of $1 chained `let`s, reached from a material's closest-hit program.
gen_chain() {
    local n="$1" out="$2"
    {
        cat <<'EOF'
import "std/cameras/pinhole.rt";
import "std/lights/point.rt";
import "std/miss/gradient.rt";

fn big(x: f32) -> f32 {
    let v0 = x * 0.5 + 1.0;
EOF
        awk -v n="$n" 'BEGIN { for (i = 1; i < n; i++) printf "    let v%d = v%d * 0.5 + 1.0;\n", i, i - 1 }'
        printf '    return v%d;\n}\n' "$((n - 1))"
        cat <<'EOF'

@material
struct Big {
    k: f32 = 1.0,
}

@closest_hit
fn big_shade(m: Big, ray: Ray, hit: Hit) -> vec3f {
    return vec3f(big(m.k));
}

scene bench {
    settings { width: 16, height: 16, samples: 1, max_depth: 1 }
    camera Pinhole { position: vec3f(0.0, 1.5, 5.0), look_at: vec3f(0.0, 0.5, 0.0), fov: 40.0 }
    background SkyGradient {}
    object floor { geometry: quad_mesh(), material: Big {} }
    light key PointLight { position: vec3f(2.0, 4.0, 3.0), color: vec3f(1.0), intensity: 30.0 }
}
EOF
    } >"$out"
}

# One function of $1 unused `let`s, all on one line (each is a W0001 warning that quotes the line).
gen_oneline() {
    local n="$1" out="$2"
    {
        printf 'fn big(x: f32) -> f32 {'
        awk -v n="$n" 'BEGIN { for (i = 0; i < n; i++) printf " let v%d = 1.0;", i }'
        printf ' return x; }\n'
    } >"$out"
}

# $1/10 functions of ten statements each (as tests/src/fuzzgen.rs's `big_valid`).
gen_many() {
    local n="$1" out="$2"
    awk -v n="$((n / 10))" 'BEGIN {
        for (i = 0; i < n; i++) {
            printf "/// Function number %d.\nfn f_%d(x: f32, v: vec3f) -> f32 {\n", i, i
            printf "    let y = x * 2.0 + 1.0;\n    var acc = dot(v, vec3f(y));\n"
            printf "    for k in 0u..4u {\n        acc += f32(k) * y;\n    }\n"
            printf "    if acc > 10.0 {\n        return acc;\n    }\n    return max(acc, 0.5);\n}\n\n"
        }
    }' >"$out"
}

# Runs "$@" under /usr/bin/time -v with the time limit; prints "seconds|max RSS MiB|exit".
measure() {
    local log="$work/time.log"
    local rc=0
    /usr/bin/time -v -o "$log" timeout "$limit" "$@" >/dev/null 2>"$work/err.log" || rc=$?
    local wall rss
    wall=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; printf "%.2f", s }' "$log")
    rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.0f", $2 / 1024 }' "$log")
    if [[ $rc -eq 124 ]]; then wall=">$limit"; fi
    if [[ $rc -ne 0 && $rc -ne 124 ]]; then head -c 600 "$work/err.log" >&2; fi
    echo "$wall|$rss|$rc"
}

(cd "$root" && source docs/bench/host.sh)
echo "binary: $rtc"
echo "time limit per run: ${limit}s"
echo
echo "| input | statements | file MB | command | seconds | max RSS MiB | exit |"
echo "|---|---:|---:|---|---:|---:|---:|"
for n in $sizes; do
    f="$work/chain_$n.rt"
    gen_chain "$n" "$f"
    mb=$(awk -v b="$(stat -c %s "$f")" 'BEGIN { printf "%.1f", b / 1048576 }')
    IFS='|' read -r s m rc <<<"$(measure "$rtc" check "$f")"
    echo "| one function | $n | $mb | check | $s | $m | $rc |"
    if [[ " $compile_sizes " == *" $n "* ]]; then
        IFS='|' read -r s m rc <<<"$(measure "$rtc" compile "$f" --out "$work/out_$n")"
        echo "| one function | $n | $mb | compile (5 targets) | $s | $m | $rc |"
    fi
    o="$work/oneline_$n.rt"
    gen_oneline "$n" "$o"
    mb=$(awk -v b="$(stat -c %s "$o")" 'BEGIN { printf "%.1f", b / 1048576 }')
    IFS='|' read -r s m rc <<<"$(measure "$rtc" check "$o")"
    echo "| one line, every \`let\` unused (n warnings) | $n | $mb | check | $s | $m | $rc |"
    g="$work/many_$n.rt"
    gen_many "$n" "$g"
    mb=$(awk -v b="$(stat -c %s "$g")" 'BEGIN { printf "%.1f", b / 1048576 }')
    IFS='|' read -r s m rc <<<"$(measure "$rtc" check "$g")"
    echo "| $((n / 10)) functions of 10 | $n | $mb | check | $s | $m | $rc |"
done
