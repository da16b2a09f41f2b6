//! The import report (`model/report.rs`, `rtc render model.glb --report`) of a generated file
//! holding one of each kind of thing rtc imports (meshes instanced twice, a textured material and
//! glTF's default one, a point and a spot light, a perspective and an orthographic camera, an
//! animation) and several it does not (a skin, morph targets, an extension it does not know, a
//! second animation, a `weights` channel), compared with the golden file
//! `golden/gltf_report.txt`. `RTC_BLESS=1` writes the golden file anew.

use std::path::PathBuf;

use serde_json::json;

use super::gltf_builder::{small_png, triangle};
use super::TempDir;
use crate::assets::load_gltf;
use crate::assets::model::report;

fn golden_path() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src/assets/tests/golden/gltf_report.txt")
}

#[test]
fn report_of_a_generated_file_matches_its_golden_file() {
    let dir = TempDir::new("report");
    dir.write("albedo.png", small_png());
    let (mut b, pos, idx) = triangle();
    let uv = b.vec2(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    let bytes: Vec<u8> = [0.0f32, 1.0].iter().flat_map(|x| x.to_le_bytes()).collect();
    let view = b.view(&bytes, None);
    let t = b.accessor(json!({
        "bufferView": view, "componentType": 5126, "count": 2, "type": "SCALAR",
        "min": [0.0], "max": [1.0],
    }));
    let moves = b.vec3(&[[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let path = b.write_gltf(
        &dir,
        "report",
        json!({
            "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_clearcoat", "EXT_unused"],
            "extensions": { "KHR_lights_punctual": { "lights": [
                { "type": "point", "name": "bulb", "color": [1.0, 0.5, 0.25], "intensity": 20.0 },
                { "type": "spot", "spot": { "innerConeAngle": 0.2, "outerConeAngle": 0.5 } },
            ] } },
            "meshes": [
                { "name": "leaf", "primitives": [
                    { "attributes": { "POSITION": pos, "TEXCOORD_0": uv }, "indices": idx, "material": 0 },
                    { "attributes": { "POSITION": pos }, "indices": idx },
                ] },
                { "name": "blob", "primitives": [
                    { "attributes": { "POSITION": pos }, "indices": idx,
                      "targets": [{ "POSITION": pos }] },
                ] },
            ],
            "materials": [{
                "name": "painted",
                "pbrMetallicRoughness": {
                    "baseColorFactor": [0.5, 0.6, 0.7, 1.0],
                    "baseColorTexture": { "index": 0 },
                    "metallicFactor": 0.0,
                    "roughnessFactor": 0.5,
                },
                "doubleSided": true,
                "extensions": { "KHR_materials_clearcoat": { "clearcoatFactor": 1.0 } },
            }],
            "textures": [{ "source": 0 }],
            "images": [{ "uri": "albedo.png" }],
            "cameras": [
                { "type": "perspective", "name": "main", "perspective": { "yfov": 0.8, "znear": 0.1 } },
                { "type": "orthographic", "orthographic": { "xmag": 2.0, "ymag": 1.0, "znear": 0.01, "zfar": 100.0 } },
            ],
            "skins": [{ "name": "rig", "joints": [3] }],
            "nodes": [
                { "name": "root", "mesh": 0, "children": [1] },
                { "mesh": 0, "translation": [2.0, 0.0, 0.0] },
                { "mesh": 1, "skin": 0 },
                { "name": "bone", "translation": [0.0, 1.0, 0.0] },
                { "camera": 0, "translation": [0.0, 1.0, 5.0] },
                { "camera": 1 },
                { "extensions": { "KHR_lights_punctual": { "light": 0 } }, "translation": [1.0, 2.0, 3.0] },
                { "extensions": { "KHR_lights_punctual": { "light": 1 } }, "translation": [0.0, 4.0, 0.0] },
            ],
            "scenes": [{ "nodes": [0, 2, 3, 4, 5, 6, 7] }],
            "animations": [
                { "name": "bob",
                  "samplers": [{ "input": t, "output": moves }],
                  "channels": [
                      { "sampler": 0, "target": { "node": 0, "path": "translation" } },
                      { "sampler": 0, "target": { "node": 2, "path": "weights" } },
                  ] },
                { "name": "wave",
                  "samplers": [{ "input": t, "output": moves }],
                  "channels": [{ "sampler": 0, "target": { "node": 1, "path": "translation" } }] },
            ],
        }),
    );
    let scene = load_gltf(&path).expect("the file loads");
    let got = report("report.gltf", &scene);
    let golden = golden_path();
    if std::env::var("RTC_BLESS").is_ok_and(|v| !v.is_empty() && v != "0") {
        std::fs::write(&golden, &got).expect("write the golden file");
    }
    let want = std::fs::read_to_string(&golden).unwrap_or_default();
    assert_eq!(
        got,
        want,
        "the report differs from {} (run with RTC_BLESS=1 to accept it)",
        golden.display()
    );
}
