#!/usr/bin/env bash
# web/build.sh: builds the compiler in WebAssembly (rtc-web) into web/pkg/: pkg/web/ for browsers
# (`--target web`, an ES module with an async init) and pkg/node/ for Node (`--target nodejs`,
# what web/tests/*.mjs load), plus pkg/examples/ and pkg/examples.json, the examples the
# playground (web/playground/, web/README.md) offers.
#
#   bash web/build.sh              the compiler
#   bash web/build.sh --renderer   the compiler and the renderer (feature `renderer`: rtc-runtime
#                                  on wgpu's WebGPU backend; web/tests/render.mjs needs it)
#
# Needs the wasm32-unknown-unknown target (added with rustup if missing) and wasm-bindgen-cli of
# exactly the version of the `wasm-bindgen` crate in Cargo.lock; that one is installed once into
# ${RTC_CACHE:-~/.cache/rtc}/wasm-bindgen-VERSION (a few minutes of compiling; CI keeps the folder).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
[ -n "$version" ] || { echo "error: no wasm-bindgen in Cargo.lock" >&2; exit 1; }
cache="${RTC_CACHE:-$HOME/.cache/rtc}"
bindgen="$cache/wasm-bindgen-$version/bin/wasm-bindgen"
if [ ! -x "$bindgen" ]; then
    echo "installing wasm-bindgen-cli $version into $cache/wasm-bindgen-$version"
    # Not --locked: the CLI's lock file names a webpki-roots release some registry mirrors lack.
    cargo install wasm-bindgen-cli --version "$version" --root "$cache/wasm-bindgen-$version"
fi
if command -v rustup >/dev/null 2>&1 && ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    rustup target add wasm32-unknown-unknown
fi

start=$SECONDS
features=()
[ "${1:-}" = "--renderer" ] && features=(--features renderer)
cargo build -p rtc-web --target wasm32-unknown-unknown --release "${features[@]}"
wasm=target/wasm32-unknown-unknown/release/rtc_web.wasm
rm -rf web/pkg
"$bindgen" --target web --out-dir web/pkg/web "$wasm"
"$bindgen" --target nodejs --out-dir web/pkg/node "$wasm"
bash web/playground/examples.sh web/pkg
echo "built web/pkg/web and web/pkg/node in $((SECONDS - start)) s ($(du -k web/pkg/web/rtc_web_bg.wasm | cut -f1) KiB of wasm)"
