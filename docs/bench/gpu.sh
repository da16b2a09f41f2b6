#!/usr/bin/env bash
# The figures the open issues ask of a real GPU, in one run short enough for a lent machine's
# 15 minutes (about 3 minutes on lavapipe on this project's 2-core VM; not yet run on a GPU):
# the thesis frame with both execution models (issues 18 and 23), every example's cold compile
# and the material edit (`rtc bench --compile`, issue 18), every example's frame with both models
# (exec_models.sh, issue 18), the live session against rebuilding (session_bench at 960x540 and
# 1920x1080, issue 17) and the embedding example's frame pacing (issue 17).
#
#   bash docs/bench/gpu.sh prepare   # here: builds, strips and packs the binaries into .device/,
#                                    # and fetches the Vulkan loader's packages into .gl/
#   bash docs/bench/gpu.sh run       # there, in the repository's root, with `.device` and `.gl`
#                                    # carried: everything above, the log and JSON under $OUT
#
# The machine there has no Rust toolchain: `run` takes the release binaries `prepare` built here
# (`rtc`, and the runtime's examples `session_bench` and `embed`; stripped and xz-packed to fit
# the working tree's 64 MiB), unpacks them into target/release, and tells the bench scripts not to
# build (`RTC_PREBUILT=1`). It brings the loader only where the system has no libvulkan. Cold
# compiles there disable NVIDIA's shader disk cache as well as Mesa's (`rtc bench --compile` sets
# both for its children). Writes `$OUT/gpu.log` (everything printed), `$OUT/compile_gpu.json`,
# `$OUT/exec_models_gpu.json`, and the session's JSON lines in the log; `OUT` defaults to
# `gpu_out` here, for trying the script on lavapipe.
set -euo pipefail
cd "$(dirname "$0")/../.."
mode=${1:-run}

if [[ $mode == prepare ]]; then
    cargo build --release --quiet -p rtc
    cargo build --release --quiet -p rtc-runtime --example session_bench --example embed
    rm -rf .device
    mkdir -p .device/bin
    cp target/release/rtc target/release/examples/session_bench target/release/examples/embed \
        .device/bin/
    strip .device/bin/*
    tar -C .device -cJf .device/bin.tar.xz bin
    rm -r .device/bin
    # The machine there gets no .git: the commit the binaries were built from travels with them.
    git rev-parse --short HEAD > .device/commit
    if [[ ! -d .gl ]]; then
        mkdir -p .gl /tmp/amd64/partial
        o=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64)
        apt-get "${o[@]}" update -qq
        (cd .gl && apt-get "${o[@]}" download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
    fi
    du -sh .device .gl
    echo "now: run(command='bash docs/bench/gpu.sh run', carry=['.device', '.gl'], timeout_s=540)"
    exit 0
fi
if [[ $mode != run ]]; then
    echo "usage: bash docs/bench/gpu.sh prepare|run" >&2
    exit 2
fi

OUT=${OUT:-gpu_out}
mkdir -p "$OUT"
exec > >(tee "$OUT/gpu.log") 2>&1
if [[ -f .device/bin.tar.xz ]]; then
    mkdir -p target/release/examples
    tar -C .device -xJf .device/bin.tar.xz
    mv .device/bin/rtc target/release/rtc
    mv .device/bin/session_bench .device/bin/embed target/release/examples/
fi
for b in target/release/rtc target/release/examples/session_bench target/release/examples/embed; do
    [[ -x $b ]] || { echo "error: $b is missing: run 'bash docs/bench/gpu.sh prepare' here first" >&2; exit 1; }
done
# (`grep` without `-q` reads all of ldconfig's output: no broken pipe for `pipefail` to report.)
if ! ldconfig -p | grep 'libvulkan\.so\.1' > /dev/null; then
    for f in .gl/*.deb; do dpkg -x "$f" /; done
    ldconfig
fi
icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [[ -f $icd && -z ${VK_DRIVER_FILES:-} ]]; then
    export VK_DRIVER_FILES=$icd
fi
export RTC_PREBUILT=1 RTC_STDLIB=$PWD/stdlib XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$(mktemp -d)}
# From here on a failing step is reported and the next one runs: one run of the script is all a
# lent machine's time allows.
set +e
[[ -f .device/commit ]] && echo "binaries built from commit $(cat .device/commit)"
command -v nvidia-smi > /dev/null && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv
source docs/bench/host.sh
rtc=target/release/rtc
tmp=$(mktemp -d)

section() { printf '\n== %s (%s)\n' "$1" "$(date -u +%H:%M:%S)"; }

section "the thesis frame, 1920x1080, 1 spp: one warm-up of each model, then 5 of each alternated"
for exec in megakernel wavefront; do
    "$rtc" render examples/thesis_scene/scene.rt -o "$tmp/t-$exec.png" --exec "$exec" 2>&1 |
        grep -E '^(adapter|host)'
done
for i in 1 2 3 4 5; do
    for exec in megakernel wavefront; do
        printf '%-10s ' "$exec"
        "$rtc" render examples/thesis_scene/scene.rt -o "$tmp/t-$exec.png" --exec "$exec" 2>&1 |
            awk '$1 == "render" { print }'
    done
done
cmp -s "$tmp/t-megakernel.png" "$tmp/t-wavefront.png" && echo "images: identical" || echo "images: differ"

section "cold compile and the material edit (rtc bench --compile)"
"$rtc" bench --compile examples --json "$OUT/compile_gpu.json"

section "every example's frame, both models (exec_models.sh, 3 runs)"
bash docs/bench/exec_models.sh 3
mv exec_models.json "$OUT/exec_models_gpu.json"

section "the live session against rebuilding, 960x540 (session_bench, 5 runs)"
target/release/examples/session_bench --runs 5
section "the live session against rebuilding, 1920x1080 (session_bench, 5 runs)"
target/release/examples/session_bench --runs 5 --size 1920x1080

section "the embedding example's frame pacing (embed --headless, 120 frames)"
target/release/examples/embed --headless --frames 120 examples/thesis_scene/scene.rt

section "done"
