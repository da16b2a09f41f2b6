#!/usr/bin/env bash
# docs/bench/web_frames.sh: frames per second of the renderer in WebAssembly on Dawn (Node, npm
# `webgpu`) against native `rtc render` on the same adapter (lavapipe), for examples/hello and
# examples/cornell_box at their own sizes (docs/bench/web_frames.mjs says what is timed).
#
#   bash docs/bench/web_frames.sh [PASSES [SCENE…]]      (default 32 passes)
#
# Builds web/pkg (with the renderer), web/node_modules and target/release/rtc when missing.
# Figures and the CPU are printed; docs/bench/README.md keeps the last ones.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
[ -f web/pkg/node/rtc_web.js ] && grep -q initGpu web/pkg/node/rtc_web.js || bash web/build.sh --renderer
[ -d web/node_modules/webgpu ] || (cd web && npm ci --no-audit --no-fund --loglevel=error)
[ -x target/release/rtc ] || cargo build --release -p rtc
source docs/bench/host.sh
node docs/bench/web_frames.mjs "$@"
