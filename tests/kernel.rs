//! Specialisation of the generated kernel, checked without a GPU: a program, dispatcher or binding
//! the scene does not use is in none of the five emitted outputs and is listed in `manifest.json`'s
//! `left_out`; `LinkOptions { all_programs: true }` (the CLI's `--all-programs`) keeps them.
//!
//! The scenes import several stdlib materials and backgrounds and declare a textured material of
//! their own, then use only some of them. Scenes with a glTF `model` entry link only the model
//! types the file holds (light types, alpha modes): the link step reads the file's metadata.

use rtc_compiler::back::{self, Target};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{self, manifest::manifest_json, CompiledScene, RENDER_ENTRY};
use rtc_compiler::link::LinkOptions;

/// The programs of the imported types; the scenes below use `lambert_shade` and
/// `constant_background` (and `textured_shade` when `textured` is true).
const UNUSED: [&str; 6] = [
    "mirror_rays",
    "mirror_shade",
    "glass_rays",
    "glass_shade",
    "sky_gradient",
    "textured_shade",
];

fn scene(textured: bool) -> String {
    let material = if textured {
        "Textured { tex: solid_texture(vec4f(0.5, 0.25, 1.0, 1.0)) }"
    } else {
        "Lambert { albedo: vec3f(0.5) }"
    };
    format!(
        r#"
import "std/cameras/pinhole.rt";
import "std/materials/lambert.rt";
import "std/materials/mirror.rt";
import "std/materials/glass.rt";
import "std/lights/point.rt";
import "std/miss/constant.rt";
import "std/miss/gradient.rt";

/// A material that samples a texture: the only reader of the `texels` binding.
@material
struct Textured {{
    tex: texture,
}}

@closest_hit
fn textured_shade(m: Textured, ray: Ray, hit: Hit) -> vec3f {{
    return sample(m.tex, hit.uv).xyz;
}}

scene specialised {{
    settings {{ width: 16, height: 16, samples: 1 }}
    camera Pinhole {{}}
    background ConstantBackground {{ color: vec3f(0.1) }}
    object floor {{ geometry: quad_mesh(), material: {material} }}
    object ball {{ geometry: sphere_mesh(1u), material: Lambert {{}}, transform: translate(vec3f(0.0, 1.0, 0.0)) }}
    light PointLight {{ position: vec3f(0.0, 3.0, 0.0) }}
}}
"#
    )
}

fn compile(name: &str, text: &str, all_programs: bool) -> CompiledScene {
    compile_with(name, text, &[], all_programs)
}

/// [`compile`] with other files (name, contents) next to the scene.
fn compile_with(
    name: &str,
    text: &str,
    files: &[(&str, Vec<u8>)],
    all_programs: bool,
) -> CompiledScene {
    let dir = std::env::temp_dir().join(format!("rtc-kernel-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join("scene.rt");
    std::fs::write(&path, text).expect("scene file");
    for (file, bytes) in files {
        std::fs::write(dir.join(file), bytes).expect("a file next to the scene");
    }
    let c = kernel::compile_scene(
        std::slice::from_ref(&path),
        None,
        &Options::default(),
        &LinkOptions {
            all_programs,
            ..LinkOptions::default()
        },
    );
    let _ = std::fs::remove_dir_all(&dir);
    match c {
        Ok(c) => c,
        Err(f) => panic!(
            "{name}: compile failed:\n{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        ),
    }
}

/// The five outputs of the render kernel, as text (SPIR-V as its words in hex and its strings).
fn outputs(c: &CompiledScene) -> Vec<(Target, Vec<u8>)> {
    let resources = rtc_compiler::abi::resources(c.bindings.iter().copied());
    Target::ALL
        .into_iter()
        .map(|t| {
            let bytes = back::write(&c.render, t, RENDER_ENTRY, &resources)
                .unwrap_or_else(|e| panic!("{}: {e}", t.name()));
            (t, bytes)
        })
        .collect()
}

fn contains(haystack: &[u8], needle: &str) -> bool {
    haystack
        .windows(needle.len())
        .any(|w| w == needle.as_bytes())
}

fn function_names(c: &CompiledScene) -> Vec<String> {
    c.render
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.clone())
        .collect()
}

fn global_names(c: &CompiledScene) -> Vec<String> {
    c.render
        .global_variables
        .iter()
        .filter_map(|(_, g)| g.name.clone())
        .collect()
}

/// The `left_out` part of the manifest (it is the last member); a program there is named
/// `"@<kind> <function>"`.
fn left_out(manifest: &str) -> &str {
    let at = manifest
        .find("\"left_out\"")
        .expect("manifest has left_out");
    &manifest[at..]
}

/// The manifest without its `left_out` part: what the kernels declare.
fn declared(manifest: &str) -> &str {
    let at = manifest
        .find("\"left_out\"")
        .expect("manifest has left_out");
    &manifest[..at]
}

#[test]
fn unused_programs_are_in_no_output_and_listed_as_left_out() {
    let c = compile("lambert", &scene(false), false);
    let names = function_names(&c);
    assert!(
        names.iter().any(|n| n.contains("lambert_shade")),
        "the used program is emitted: {names:?}"
    );
    for (t, bytes) in outputs(&c) {
        for f in UNUSED {
            assert!(!contains(&bytes, f), "{f} is in the {} output", t.name());
        }
    }
    for f in UNUSED {
        assert!(
            !names.iter().any(|n| n.contains(f)),
            "{f} is a function of the module"
        );
    }
    let manifest = manifest_json(&c);
    let left = left_out(&manifest);
    for f in UNUSED {
        assert!(
            contains(left.as_bytes(), &format!(" {f}\"")),
            "{f} is not in the manifest's left_out:\n{left}"
        );
        assert!(
            !contains(declared(&manifest).as_bytes(), f),
            "{f} is in the manifest's kernels or programs"
        );
    }
}

#[test]
fn a_scene_without_textures_has_no_texels_binding() {
    let c = compile("no-textures", &scene(false), false);
    assert!(!c.bindings.iter().any(|b| b.name == "texels"));
    assert!(
        !global_names(&c).iter().any(|g| g.contains("texels")),
        "{:?}",
        global_names(&c)
    );
    let manifest = manifest_json(&c);
    assert!(!contains(declared(&manifest).as_bytes(), "\"texels\""));
    assert!(contains(left_out(&manifest).as_bytes(), "\"texels\""));
    for (t, bytes) in outputs(&c) {
        assert!(
            !contains(&bytes, "texels"),
            "texels in the {} output",
            t.name()
        );
    }

    // The same scene with the textured material in use has the binding.
    let t = compile("textures", &scene(true), false);
    assert!(t.bindings.iter().any(|b| b.name == "texels"));
    assert!(global_names(&t).iter().any(|g| g.contains("texels")));
    let manifest = manifest_json(&t);
    assert!(contains(declared(&manifest).as_bytes(), "\"texels\""));
    assert!(!contains(left_out(&manifest).as_bytes(), "\"texels\""));
}

#[test]
fn all_programs_keeps_every_program_and_binding() {
    let specialised = compile("specialised", &scene(false), false);
    let all = compile("all-programs", &scene(false), true);
    let names = function_names(&all);
    for f in UNUSED {
        assert!(
            names.iter().any(|n| n.contains(f)),
            "{f} is not a function of the --all-programs module: {names:?}"
        );
    }
    assert!(all.bindings.iter().any(|b| b.name == "texels"));
    assert!(global_names(&all).iter().any(|g| g.contains("texels")));
    let manifest = manifest_json(&all);
    for f in UNUSED {
        assert!(
            contains(declared(&manifest).as_bytes(), &format!("\"{f}\"")),
            "{f} is not among the --all-programs manifest's programs"
        );
    }
    assert!(contains(declared(&manifest).as_bytes(), "\"texels\""));
    // Every output of the unspecialised kernel is larger.
    for ((t, s), (_, a)) in outputs(&specialised).into_iter().zip(outputs(&all)) {
        assert!(
            a.len() > s.len(),
            "{}: {} bytes specialised, {} with --all-programs",
            t.name(),
            s.len(),
            a.len()
        );
        if t != Target::SpirV {
            for f in UNUSED {
                assert!(contains(&a, f), "{f} is not in the {} output", t.name());
            }
        }
    }
}

/// A `.gltf` file (with its `model.bin`) holding one triangle whose material has `alpha_mode`, and
/// one light of each type in `lights` on its own node.
fn model_files(lights: &[&str], alpha_mode: &str) -> Vec<(&'static str, Vec<u8>)> {
    let bin: Vec<u8> = [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let light_list: Vec<String> = lights
        .iter()
        .map(|t| match *t {
            "spot" => r#"{"type": "spot", "spot": {}}"#.to_owned(),
            t => format!(r#"{{"type": "{t}"}}"#),
        })
        .collect();
    let mut nodes = vec![r#"{"mesh": 0}"#.to_owned()];
    nodes.extend((0..lights.len()).map(|i| {
        format!(r#"{{"translation": [0, 2, 0], "extensions": {{"KHR_lights_punctual": {{"light": {i}}}}}}}"#)
    }));
    let gltf = format!(
        r#"{{
  "asset": {{"version": "2.0"}},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {{"KHR_lights_punctual": {{"lights": [{lights}]}}}},
  "buffers": [{{"uri": "model.bin", "byteLength": 36}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                  "min": [0, 0, 0], "max": [1, 1, 0]}}],
  "materials": [{{"alphaMode": "{alpha_mode}"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}, "material": 0}}]}}],
  "nodes": [{nodes}],
  "scenes": [{{"nodes": [{indices}]}}],
  "scene": 0
}}"#,
        lights = light_list.join(", "),
        nodes = nodes.join(", "),
        indices = (0..nodes.len())
            .map(|i| i.to_string())
            .collect::<Vec<_>>()
            .join(", "),
    );
    vec![("model.gltf", gltf.into_bytes()), ("model.bin", bin)]
}

const MODEL_SCENE: &str = r#"
import "std/cameras/pinhole.rt";

scene with_model {
    settings { width: 16, height: 16, samples: 1 }
    camera Pinhole {}
    model "model.gltf" {}
}
"#;

/// The manifest as JSON.
fn manifest_value(c: &CompiledScene) -> serde_json::Value {
    serde_json::from_str(&manifest_json(c)).expect("manifest.json is JSON")
}

#[test]
fn a_model_with_only_a_point_light_links_no_other_light_and_no_any_hit() {
    let c = compile_with(
        "gltf-point",
        MODEL_SCENE,
        &model_files(&["point"], "OPAQUE"),
        false,
    );
    let names = function_names(&c);
    assert!(names.iter().any(|n| n == "point_light"), "{names:?}");
    assert!(names.iter().any(|n| n == "gltf_shade"), "{names:?}");
    let absent = [
        "spot_light",
        "directional_light",
        "gltf_masked_any_hit",
        "gltf_masked_shade",
        "dispatch_any_hit",
    ];
    for f in absent {
        assert!(
            !names.iter().any(|n| n == f),
            "{f} is a function: {names:?}"
        );
    }
    for (t, bytes) in outputs(&c) {
        for f in absent {
            assert!(!contains(&bytes, f), "{f} is in the {} output", t.name());
        }
    }
    assert!(!c.linked.config.has_any_hit);

    let m = manifest_value(&c);
    assert_eq!(
        m["models"],
        serde_json::json!({
            "entries": [{
                "path": "model.gltf",
                "read": true,
                // glTF's default `doubleSided` is false: the file's material is single-sided, which
                // switches traversal-side culling on (no type, no any-hit).
                "holds": ["opaque material", "point light", "single-sided opaque material"],
            }],
            "linked": ["GltfMaterial", "PointLight"],
        })
    );
    assert_eq!(m["constants"]["has_any_hit"], false);
    let left = m["left_out"].as_array().expect("left_out");
    for (program, part) in [
        ("@light spot_light", "spot light"),
        ("@light directional_light", "directional light"),
        (
            "@any_hit gltf_masked_any_hit",
            "alpha-masked or blended material",
        ),
    ] {
        let entry = left
            .iter()
            .find(|e| e["name"] == program)
            .unwrap_or_else(|| panic!("{program} not left out: {left:?}"));
        assert_eq!(
            entry["reason"],
            format!("no model file of the scene holds a {part}")
        );
    }
}

#[test]
fn a_masked_material_brings_the_any_hit_path_and_each_light_type_its_program() {
    let c = compile_with(
        "gltf-mask",
        MODEL_SCENE,
        &model_files(&["spot", "directional"], "MASK"),
        false,
    );
    let names = function_names(&c);
    for f in [
        "gltf_masked_any_hit",
        "dispatch_any_hit",
        "spot_light",
        "directional_light",
    ] {
        assert!(names.iter().any(|n| n == f), "{f} missing: {names:?}");
    }
    for f in ["point_light", "gltf_shade"] {
        assert!(
            !names.iter().any(|n| n == f),
            "{f} is a function: {names:?}"
        );
    }
    assert!(c.linked.config.has_any_hit);
    let m = manifest_value(&c);
    assert_eq!(
        m["models"]["linked"],
        serde_json::json!(["GltfMaskedMaterial", "DirectionalLight", "SpotLight"])
    );
}

#[test]
fn a_model_the_compiler_cannot_read_links_every_model_type_and_says_why() {
    let c = compile_with("gltf-missing", MODEL_SCENE, &[], false);
    let names = function_names(&c);
    for f in [
        "point_light",
        "spot_light",
        "directional_light",
        "gltf_masked_any_hit",
    ] {
        assert!(names.iter().any(|n| n == f), "{f} missing: {names:?}");
    }
    let m = manifest_value(&c);
    let entry = &m["models"]["entries"][0];
    assert_eq!(entry["read"], false);
    let why = entry["not_read"].as_str().expect("a reason");
    assert!(
        why.contains("model.gltf") && why.contains("cannot be read"),
        "{why}"
    );
    // The scene has a camera entry, so the model camera type is not linked even then.
    assert_eq!(
        m["models"]["linked"],
        serde_json::json!([
            "GltfMaterial",
            "GltfMappedMaterial",
            "GltfMaskedMaterial",
            "GltfMaskedMappedMaterial",
            "GltfDetailMaterial",
            "GltfMaskedDetailMaterial",
            "GltfTransmissiveMaterial",
            "PointLight",
            "DirectionalLight",
            "SpotLight"
        ])
    );
}

#[test]
fn a_model_without_lights_links_no_light_type() {
    let c = compile_with("gltf-dark", MODEL_SCENE, &model_files(&[], "OPAQUE"), false);
    let names = function_names(&c);
    for f in ["point_light", "spot_light", "directional_light"] {
        assert!(
            !names.iter().any(|n| n == f),
            "{f} is a function: {names:?}"
        );
    }
    assert!(!c
        .linked
        .types
        .contains_key(&rtc_compiler::sema::hir::Role::Light));
    assert_eq!(
        manifest_value(&c)["models"]["linked"],
        serde_json::json!(["GltfMaterial"])
    );
}

#[test]
fn light_programs_shadows_are_deferred_only_with_more_than_one_light_type() {
    // One light type: its `shadow` traversal is one copy per material either way, so the kernel
    // keeps the light program tracing in place (and the smaller scratch array).
    let one = compile("one_light_type", &scene(false), false);
    let names = function_names(&one);
    assert!(
        !names.iter().any(|n| n == "sample_light_deferred"),
        "{names:?}"
    );
    assert!(!names.iter().any(|n| n == "shadow_deferred"), "{names:?}");
    // Two: `sample_light` traces every light program's queries at its one call site.
    let two = scene(false).replace(
        "    light PointLight {",
        "    light DirectionalLight { direction: vec3f(0.0, -1.0, 0.0) }\n    light PointLight {",
    );
    let two = two.replace(
        "import \"std/lights/point.rt\";",
        "import \"std/lights/point.rt\";\nimport \"std/lights/directional.rt\";",
    );
    let two = compile("two_light_types", &two, false);
    let names = function_names(&two);
    for f in ["sample_light_deferred", "shadow_deferred"] {
        assert!(names.iter().any(|n| n == f), "{f} missing: {names:?}");
    }
}
