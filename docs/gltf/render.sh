#!/usr/bin/env bash
# docs/gltf/render.sh MODELS [OUT]: renders Khronos's glTF sample models with `rtc render` as a new
# user would (the bare file: rtc's framing camera, or the file's own, and its default light rig),
# for the comparison with the glTF Sample Viewer's screenshots in docs/gltf/README.md.
#
# MODELS is a folder laid out like the glTF-Sample-Models repository's `2.0/` folder: MODEL/glTF/
# MODEL.gltf with its .bin and textures (the repository is about 1 GB; the five models used here
# are 13 MB, see README.md for where they come from). The models are not part of rtc.
# OUT (default docs/gltf) receives MODEL.png for each model, and MODEL.txt with rtc's summary and
# import report; and DamagedHelmet_matched.png, the helmet through docs/gltf/damaged_helmet.rt
# (the Sample Viewer screenshot's view, the bare file's light rig). RTC_BIN=path uses that rtc instead of building a release one; RTC_GLTF_SIZE and
# RTC_GLTF_SPP set the size (320x320) and samples per pixel (64).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."

models="${1:?usage: docs/gltf/render.sh MODELS [OUT]}"
out="${2:-docs/gltf}"
size="${RTC_GLTF_SIZE:-320x320}"
spp="${RTC_GLTF_SPP:-64}"
mkdir -p "$out"
source docs/bench/host.sh
rtc="${RTC_BIN:-}"
if [ -z "$rtc" ]; then
    cargo build --release -q -p rtc
    rtc=target/release/rtc
fi
for m in DamagedHelmet WaterBottle BoxVertexColors TextureSettingsTest Duck; do
    file="$models/$m/glTF/$m.gltf"
    if [ ! -f "$file" ]; then
        echo "skipped $m: no $file"
        continue
    fi
    echo "+ rtc render $file --size $size --spp $spp --report -o $out/$m.png"
    "$rtc" render "$file" --size "$size" --spp "$spp" --report -o "$out/$m.png" \
        >"$out/$m.txt" 2>&1 || { cat "$out/$m.txt"; exit 1; }
    tail -n 4 "$out/$m.txt"
done
if [ -f "$models/DamagedHelmet/glTF/DamagedHelmet.gltf" ]; then
    echo "+ rtc render docs/gltf/damaged_helmet.rt --asset-root $models --size $size --spp $spp -o $out/DamagedHelmet_matched.png"
    "$rtc" render docs/gltf/damaged_helmet.rt --asset-root "$models" --size "$size" --spp "$spp" \
        -o "$out/DamagedHelmet_matched.png" >"$out/DamagedHelmet_matched.txt" 2>&1 ||
        { cat "$out/DamagedHelmet_matched.txt"; exit 1; }
    tail -n 4 "$out/DamagedHelmet_matched.txt"
fi
