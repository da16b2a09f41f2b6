#!/usr/bin/env bash
# web/playground/examples.sh OUT: copies the examples the playground offers into OUT/examples/
# and writes OUT/examples.json, the index the page fetches (web/build.sh runs it with OUT=web/pkg,
# which is not committed).
#
# Per example folder (examples/NAME with at least one `.rt` file): every `.rt` file and
# `rtc.registry.json` are copied (the page gives them to the compiler as examples/NAME/FILE, the
# paths `rtc` run at the repository's root uses). The index lists, per example, its files, its
# scene files (`entries`: FILE and the scene it declares) and the asset files its sources load
# (`load_mesh("…")`, `load_image("…")`, `model "…"`), which are copied beside them: the page does
# not give those to the renderer up front, its `loadRenderer` asks for them and the page fetches
# them from OUT/examples/NAME/ as a page fetches its assets from URLs. `noRender` names the
# examples that cannot render in the page, with the reason (verified by web/tests/playground.mjs,
# which renders every other one).
# Names are [A-Za-z0-9_.-] only, so the JSON needs no escaping; anything else is skipped.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
out="${1:?usage: examples.sh OUT_DIR}"

# Examples that cannot render in the page, with the reason (none now: custom geometry's bounds
# are read back by the awaiting setup, `loadRenderer`). An example whose scene asks for the
# wavefront model (`exec: wavefront`) would go here: its rounds read back mid-frame.
declare -A no_render=()

safe() { [[ "$1" =~ ^[A-Za-z0-9_.-]+$ ]]; }
join() { local IFS=,; echo "$*"; }

rm -rf "$out/examples" "$out/examples.json"
mkdir -p "$out/examples"
json="["
first=1
for dir in examples/*/; do
    name=$(basename "$dir")
    safe "$name" || continue
    shopt -s nullglob
    sources=("$dir"*.rt)
    shopt -u nullglob
    [ ${#sources[@]} -gt 0 ] || continue
    mkdir -p "$out/examples/$name"
    files=()
    entries=()
    assets=()
    for f in "${sources[@]}" "$dir"rtc.registry.json; do
        [ -f "$f" ] || continue
        base=$(basename "$f")
        safe "$base" || continue
        cp "$f" "$out/examples/$name/$base"
        files+=("\"$base\"")
        [[ "$base" == *.rt ]] || continue
        while read -r scene; do
            safe "$scene" && entries+=("{\"file\":\"$base\",\"scene\":\"$scene\"}")
        done < <(sed -nE 's/^scene[[:space:]]+([A-Za-z_][A-Za-z0-9_]*).*/\1/p' "$f")
        while read -r asset; do
            if safe "$asset" && [[ " ${assets[*]} " != *" \"$asset\" "* ]]; then
                assets+=("\"$asset\"")
                if [ -f "$dir$asset" ]; then cp "$dir$asset" "$out/examples/$name/$asset"; fi
            fi
        done < <(grep -oE '(load_mesh|load_image)\("[^"]+"\)|model "[^"]+"' "$f" | sed -E 's/.*"([^"]+)".*/\1/')
    done
    [ ${#entries[@]} -gt 0 ] || continue
    reason="${no_render[$name]:-}"
    [ $first -eq 1 ] || json+=","
    first=0
    json+=$'\n'"  {\"name\":\"$name\",\"files\":[$(join "${files[@]}")],\"entries\":[$(join "${entries[@]}")],\"assets\":[$(join "${assets[@]}")]"
    [ -z "$reason" ] || json+=",\"noRender\":\"$reason\""
    json+="}"
done
json+=$'\n'"]"
printf '%s\n' "$json" >"$out/examples.json"
echo "wrote $out/examples.json ($(grep -c '"name"' "$out/examples.json") examples)"
