# Sourced by the scripts in docs/bench that take `[--current-lavapipe] [RUNS] [EXAMPLE...]`:
# defines `bench_args`, which reads those arguments the same way for every script.
#
#   bench_args DEFAULT_RUNS "$@"
#
# Sets `runner` (an array: empty, or `bash docs/bench/current_lavapipe.sh` after
# `--current-lavapipe`), `runs` (RUNS, else DEFAULT_RUNS) and `examples` (an array: the EXAMPLE
# arguments, else every folder of examples/ with a scene.rt, in name order). Must be called from
# the repository's root.
bench_args() {
    runs=$1
    shift
    runner=()
    if [[ ${1:-} == --current-lavapipe ]]; then
        runner=(bash docs/bench/current_lavapipe.sh)
        shift
    fi
    if [[ $# -gt 0 ]]; then
        runs=${1:-$runs}
        shift
    fi
    examples=("$@")
    if [[ ${#examples[@]} -eq 0 ]]; then
        local f
        for f in examples/*/scene.rt; do
            examples+=("$(basename "$(dirname "$f")")")
        done
    fi
}
