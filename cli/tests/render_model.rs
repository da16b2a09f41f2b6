//! End-to-end tests of `rtc render model.glb` on lavapipe (skipped, saying so, where no adapter
//! exists): a bare glTF file (the example's model without its camera and lights) renders with the
//! defaults it prints, the model in the middle of the image and the sky at the top; a file with a
//! camera and lights keeps them; the default light rig lights the side the file's camera sees;
//! `--report` lists what was imported; `--frames all` of an animated file covers its animation
//! without BLAS builds; a truncated file and `--scene` are clear errors, never a panic.
//! Also the asset confinement seen from the command line: `--asset-root` must name a folder, and a
//! scene path leading out of the scene's folder is E0903 with a help line naming `--asset-root`.

mod common;

use common::{no_gpu, rtc, s, scratch, text};
use rtc_runtime::image_out::read_image;
use std::path::{Path, PathBuf};
use std::process::Output;

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The example's model.
fn example_glb() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/gltf_scene/model.glb")
}

/// The JSON and binary chunks of a `.glb`.
fn split(glb: &[u8]) -> (serde_json::Value, Vec<u8>) {
    let len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let json = serde_json::from_slice(&glb[20..20 + len]).expect("JSON chunk");
    (json, glb[20 + len..].to_vec())
}

/// A `.glb` of a JSON document and the binary chunk(s) `rest` (already framed).
fn join(doc: &serde_json::Value, rest: &[u8]) -> Vec<u8> {
    let mut json = serde_json::to_vec(doc).unwrap();
    while json.len() % 4 != 0 {
        json.push(b' ');
    }
    let mut body = (json.len() as u32).to_le_bytes().to_vec();
    body.extend_from_slice(b"JSON");
    body.extend_from_slice(&json);
    body.extend_from_slice(rest);
    let mut out = b"glTF".to_vec();
    out.extend_from_slice(&2u32.to_le_bytes());
    out.extend_from_slice(&(12 + body.len() as u32).to_le_bytes());
    out.extend_from_slice(&body);
    out
}

/// The example's model with its camera and lights removed.
fn bare_glb(dir: &Path) -> PathBuf {
    let (mut doc, bin) = split(&std::fs::read(example_glb()).expect("the example's model"));
    let root = doc.as_object_mut().unwrap();
    root.remove("cameras");
    root.remove("extensions");
    root.remove("extensionsUsed");
    for node in root["nodes"].as_array_mut().unwrap() {
        let node = node.as_object_mut().unwrap();
        node.remove("camera");
        node.remove("extensions");
    }
    let path = dir.join("bare.glb");
    std::fs::write(&path, join(&doc, &bin)).unwrap();
    path
}

#[test]
fn a_bare_glb_renders_with_the_defaults_it_prints() {
    let dir = scratch("model-test", "bare");
    let model = bare_glb(&dir);
    let png = dir.join("bare.png");
    let out = rtc(&[
        "render",
        s(&model),
        "-o",
        s(&png),
        "--size",
        "64x48",
        "--spp",
        "1",
    ]);
    if no_gpu(&out) {
        return;
    }
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let printed = stdout(&out);
    for line in [
        "default camera: the file has none; a Pinhole framing the model's bounds",
        "default light: the file has none; a DirectionalLight",
        "default background: a sky gradient",
    ] {
        assert!(printed.contains(line), "missing `{line}` in\n{printed}");
    }
    let image = read_image(&png).expect("the PNG");
    assert_eq!((image.width(), image.height()), (64, 48));
    // The framed model (grey floor, objects) fills the centre; the sky (blue-white, blue above red)
    // the top row. The floor is neutral grey: its blue and red differ by less than 0.05.
    let top = image.get(32, 0).unwrap();
    let centre = image.get(32, 30).unwrap();
    assert!(top[2] > top[0], "the sky is bluish: {top:?}");
    assert!(
        (centre[2] - centre[0]).abs() < 0.05 && centre[0] > 0.02,
        "the lit grey floor is at the centre: {centre:?}"
    );
}

#[test]
fn a_glb_with_camera_and_lights_keeps_them() {
    let dir = scratch("model-test", "full");
    let png = dir.join("full.png");
    let model = example_glb();
    let out = rtc(&[
        "render",
        s(&model),
        "-o",
        s(&png),
        "--size",
        "48x32",
        "--spp",
        "1",
    ]);
    if no_gpu(&out) {
        return;
    }
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let printed = stdout(&out);
    assert!(
        printed.contains("default camera: the file's first perspective camera"),
        "{printed}"
    );
    assert!(
        printed.contains("default lights: the file's 2 KHR_lights_punctual light(s)"),
        "{printed}"
    );
    assert!(
        printed.contains(
            "(6 meshes, 2896 triangles, 7 objects; 6 object BVHs built, 1 scene-level; \
                       6 static objects flattened into 1 world-space BVH)"
        ),
        "{printed}"
    );
}

#[test]
fn broken_models_are_clear_errors() {
    let dir = scratch("model-test", "broken");
    let glb = std::fs::read(example_glb()).unwrap();
    let cut = dir.join("cut.glb");
    std::fs::write(&cut, &glb[..glb.len() / 3]).unwrap();
    let out = rtc(&["render", s(&cut), "-o", s(&dir.join("x.png"))]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let t = text(&out);
    assert!(
        t.contains("cut.glb") && t.contains("bad .glb file") && t.contains("truncated"),
        "{t}"
    );

    let missing = dir.join("nothing.gltf");
    let out = rtc(&["render", s(&missing), "-o", s(&dir.join("x.png"))]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        text(&out).contains("nothing.gltf: cannot read the file"),
        "{}",
        text(&out)
    );

    let out = rtc(&[
        "render",
        s(&example_glb()),
        "-o",
        s(&dir.join("x.png")),
        "--scene",
        "a",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("--scene"), "{}", text(&out));
}

#[test]
fn asset_roots_must_be_folders() {
    let dir = scratch("model-test", "roots");
    let scene = dir.join("scene.rt");
    std::fs::write(&scene, "scene s {}\n").unwrap();
    for command in ["render", "bvh"] {
        let out = rtc(&[
            command,
            s(&scene),
            "-o",
            s(&dir.join("x.png")),
            "--asset-root",
            s(&dir.join("no-such-folder")),
        ]);
        assert_eq!(out.status.code(), Some(2), "{command}: {}", text(&out));
        assert!(
            text(&out).contains("--asset-root") && text(&out).contains("no such folder"),
            "{command}: {}",
            text(&out)
        );
    }
}

#[test]
fn a_scene_path_leaving_its_folder_is_e0903() {
    let dir = scratch("model-test", "escape");
    std::fs::create_dir_all(dir.join("scene")).unwrap();
    std::fs::write(
        dir.join("secret.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let scene = dir.join("scene/scene.rt");
    std::fs::write(
        &scene,
        "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/lambert.rt\";\n\
         scene s {\n    camera Pinhole {}\n    \
         object o { geometry: load_mesh(\"../secret.obj\"), material: Lambert {} }\n}\n",
    )
    .unwrap();
    let out = rtc(&["render", s(&scene), "-o", s(&dir.join("x.png"))]);
    if no_gpu(&out) {
        return;
    }
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(t.contains("E0903"), "{t}");
    assert!(t.contains("../secret.obj"), "{t}");
    assert!(t.contains("--asset-root"), "{t}");
    assert!(!dir.join("x.png").exists());
}

#[test]
fn report_lists_what_the_model_brought() {
    let dir = scratch("model-test", "report");
    let out = rtc(&[
        "render",
        s(&example_glb()),
        "-o",
        s(&dir.join("r.png")),
        "--size",
        "16x12",
        "--spp",
        "1",
        "--report",
    ]);
    if no_gpu(&out) {
        return;
    }
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let printed = stdout(&out);
    for line in [
        "import report of model.glb\n",
        "  meshes: 6 triangle mesh(es), 2896 triangle(s), placed 7 time(s)\n",
        "  lights: 2\n",
        "  cameras: 1\n",
        "  animation: none\n",
    ] {
        assert!(printed.contains(line), "missing `{line}` in\n{printed}");
    }
}

/// A glTF quad whose node a LINEAR translation channel moves from x = -1 at 0 s to +1 at 1 s
/// (`anim.gltf` and `anim.bin` in `dir`).
fn animated_gltf(dir: &Path) -> PathBuf {
    let mut bin: Vec<u8> = Vec::new();
    let floats = [
        -0.5f32, -0.5, 0.0, 0.5, -0.5, 0.0, 0.5, 0.5, 0.0, -0.5, 0.5, 0.0,
    ];
    bin.extend(floats.iter().flat_map(|x| x.to_le_bytes()));
    bin.extend([0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    bin.extend([0.0f32, 1.0].iter().flat_map(|x| x.to_le_bytes()));
    bin.extend(
        [-1.0f32, 0.0, 0.0, 1.0, 0.0, 0.0]
            .iter()
            .flat_map(|x| x.to_le_bytes()),
    );
    std::fs::write(dir.join("anim.bin"), &bin).unwrap();
    let gltf = serde_json::json!({
        "asset": {"version": "2.0"},
        "buffers": [{"uri": "anim.bin", "byteLength": 92}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48},
            {"buffer": 0, "byteOffset": 48, "byteLength": 12},
            {"buffer": 0, "byteOffset": 60, "byteLength": 8},
            {"buffer": 0, "byteOffset": 68, "byteLength": 24}
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-0.5, -0.5, 0.0], "max": [0.5, 0.5, 0.0]},
            {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR",
             "min": [0.0], "max": [1.0]},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"}
        ],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}],
        "animations": [{
            "samplers": [{"input": 2, "output": 3}],
            "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]
        }]
    });
    let path = dir.join("anim.gltf");
    std::fs::write(&path, serde_json::to_vec(&gltf).unwrap()).unwrap();
    path
}

#[test]
fn frames_all_of_an_animated_gltf_cover_its_animation_without_blas_builds() {
    let dir = scratch("model-test", "animated");
    let model = animated_gltf(&dir);
    let out = rtc(&[
        "render",
        s(&model),
        "-o",
        s(&dir.join("f_%d.png")),
        "--size",
        "16x12",
        "--spp",
        "1",
        "--frames",
        "all",
        "--fps",
        "2",
    ]);
    if no_gpu(&out) {
        return;
    }
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let printed = stdout(&out);
    assert!(
        printed.contains("frames: 3 of 0..3"),
        "1 s at 2 fps, the last key's frame included:\n{printed}"
    );
    assert!(
        printed.contains("1 BLAS builds at setup, 0 over the frames after it"),
        "{printed}"
    );
    assert!(
        !text(&out).contains("every frame is the same image"),
        "{}",
        text(&out)
    );
    for f in 0..3 {
        assert!(dir.join(format!("f_{f}.png")).is_file(), "frame {f}");
    }
}

/// A grey quad (`back.gltf`) facing -z, seen by the file's camera from (0, 0, -3) looking along
/// +z: the side the old default light (from above, on the +z side) left black.
fn back_lit_gltf(dir: &Path) -> PathBuf {
    let mut bin: Vec<u8> = Vec::new();
    // Positions wound counter-clockwise seen from -z, then normals (0, 0, -1).
    let positions = [
        1.0f32, -1.0, 0.0, -1.0, -1.0, 0.0, -1.0, 1.0, 0.0, 1.0, 1.0, 0.0,
    ];
    bin.extend(positions.iter().flat_map(|x| x.to_le_bytes()));
    let normals = [0.0f32, 0.0, -1.0].repeat(4);
    bin.extend(normals.iter().flat_map(|x| x.to_le_bytes()));
    bin.extend([0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()));
    std::fs::write(dir.join("back.bin"), &bin).unwrap();
    let gltf = serde_json::json!({
        "asset": {"version": "2.0"},
        "buffers": [{"uri": "back.bin", "byteLength": 108}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48},
            {"buffer": 0, "byteOffset": 48, "byteLength": 48},
            {"buffer": 0, "byteOffset": 96, "byteLength": 12}
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-1.0, -1.0, 0.0], "max": [1.0, 1.0, 0.0]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}
        ],
        "materials": [{"pbrMetallicRoughness": {
            "baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1}}],
        "nodes": [
            {"mesh": 0},
            {"camera": 0, "translation": [0.0, 0.0, -3.0], "rotation": [0.0, 1.0, 0.0, 0.0]}
        ],
        "scenes": [{"nodes": [0, 1]}]
    });
    let path = dir.join("back.gltf");
    std::fs::write(&path, serde_json::to_vec(&gltf).unwrap()).unwrap();
    path
}

/// The mean Rec. 709 luminance of the linear image's central quarter.
fn centre_luminance(png: &Path) -> f64 {
    let image = read_image(png).expect("the image");
    let (w, h) = (image.width(), image.height());
    let (mut sum, mut n) = (0.0f64, 0.0f64);
    for y in h / 4..3 * h / 4 {
        for x in w / 4..3 * w / 4 {
            let p = image.get(x, y).unwrap();
            sum += 0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2]);
            n += 1.0;
        }
    }
    sum / n
}

#[test]
fn the_default_light_lights_what_the_files_camera_sees() {
    let dir = scratch("model-test", "headlight");
    let model = back_lit_gltf(&dir);
    let exr = dir.join("back.exr");
    let out = rtc(&[
        "render",
        s(&model),
        "-o",
        s(&exr),
        "--size",
        "32x24",
        "--spp",
        "1",
    ]);
    if no_gpu(&out) {
        return;
    }
    assert_eq!(out.status.code(), Some(0), "{}", text(&out));
    let lum = centre_luminance(&exr);
    eprintln!("centre luminance {lum}");
    // The quad fills the centre. Under the headlight (intensity π, at cos ≈ 0.889 to the quad)
    // a diffuse albedo of 0.8 gives 0.8 × 0.889 ≈ 0.71, plus a little specular; the sky fill
    // grazes the vertical quad. The old rig (one light from the +z side) gave exactly 0 here.
    assert!(
        lum > 0.5 && lum < 1.0,
        "the side the camera sees is not lit as the rig says: {lum}"
    );
}
