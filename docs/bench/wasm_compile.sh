#!/usr/bin/env bash
# docs/bench/wasm_compile.sh: edit → WGSL latency of examples/hello, the compiler in WebAssembly
# under Node against the same compiler native (both in memory, same code: rtc-web's Compiler), and
# the wall time of a native `rtc compile --target wgsl` process when target/release/rtc exists.
#
#   bash docs/bench/wasm_compile.sh [ITERATIONS]     (default 20; builds web/pkg and the native bench)
#
# Figures (and the CPU) are printed; docs/bench/README.md keeps the last ones.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
n="${1:-20}"
[ -f web/pkg/node/rtc_web.js ] || bash web/build.sh
cargo build --release -p rtc-web --example bench -q
echo "cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //') ($(nproc) cores)"
echo "node $(node --version): wasm   $(node docs/bench/wasm_compile.mjs "$n")"
echo "native (in memory):   $(target/release/examples/bench "$n")"
if [ -x target/release/rtc ]; then
    out=$(mktemp -d)
    times=()
    for _ in $(seq "$n"); do
        s=$(date +%s%N)
        target/release/rtc compile examples/hello/scene.rt --target wgsl --out "$out" 2>/dev/null
        times+=($((($(date +%s%N) - s) / 1000)))
    done
    rm -rf "$out"
    median=$(printf '%s\n' "${times[@]}" | sort -n | sed -n "$((n / 2 + 1))p")
    echo "native rtc compile process (wall, median of $n): $((median / 1000)).$(printf '%03d' $((median % 1000))) ms"
fi
