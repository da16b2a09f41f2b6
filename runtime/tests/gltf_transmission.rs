//! glTF `KHR_materials_transmission` and `KHR_materials_ior` on the GPU: a transmissive quad in
//! front of an emissive background shows the background through it, Fresnel-weighted and tinted
//! by the base colour.
//!
//! The generated file has an emissive (1, 1, 1), black, double-sided background quad at z = 0
//! and three transmissive quads at z = 1, side by side (x in [k - 1.5, k - 0.5]), base colour
//! `TINT`, metallic 0, each seen head-on by an orthographic camera looking down -z; no lights, no
//! background colour (a ray that leaves the scene brings 0). At normal incidence the exact
//! Fresnel reflectance is `F = ((ior - 1) / (ior + 1))²`; the reflected ray leaves the scene (0)
//! and the refracted one, undeflected, meets the background (1), so a pixel's expected value is
//! `w (1 - F) TINT` with `w` the transmission (the opaque part, unlit and not emissive, adds 0):
//! 0. transmission 1, ior 1.5: F = 0.04, expected 0.96 TINT;
//! 1. transmission 1, ior 1 (no reflection): exactly TINT on every sample (1e-5);
//! 2. transmission 0.5, ior 1.5: 0.48 TINT.
//!
//! Quads 0 and 2 choose reflection or refraction at random per sample: each sample is 0 or
//! `w TINT`, so the mean over the 8×8 inner pixels × 64 samples (4096 draws) has a standard error
//! of at most `sqrt(0.04 · 0.96 / 4096) ≈ 0.0031` of `w TINT`; the tolerance is 0.02 of it
//! (about 6.5 standard errors).

mod common;

use common::{gpu_or_skip, temp_dir};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene_with, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::render::RenderOptions;
use serde_json::{json, Value};

/// Pixels per world unit.
const PX: u32 = 12;
/// The transmissive quads' base colour (linear).
const TINT: [f64; 3] = [1.0, 0.5, 0.25];
/// (transmission, ior) of each quad.
const QUADS: [(f64, f64); 3] = [(1.0, 1.5), (1.0, 1.0), (0.5, 1.5)];

fn write_model(dir: &std::path::Path) {
    let mut bin: Vec<u8> = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();
    let mut meshes = Vec::new();
    let mut quads = vec![(-1.5f32, 1.5f32, 0.0f32, 0usize)];
    for k in 0..QUADS.len() {
        quads.push((k as f32 - 1.5, k as f32 - 0.5, 1.0, k + 1));
    }
    for (x0, x1, z, material) in quads {
        let positions = [x0, -0.5, z, x1, -0.5, z, x1, 0.5, z, x0, 0.5, z];
        let normals = [0.0f32, 0.0, 1.0].repeat(4);
        let order: [u16; 6] = [0, 1, 2, 0, 2, 3];
        let mut push = |bytes: Vec<u8>, accessor: Value| {
            views.push(json!({ "buffer": 0, "byteOffset": bin.len(), "byteLength": bytes.len() }));
            bin.extend_from_slice(&bytes);
            let mut accessor = accessor;
            accessor["bufferView"] = json!(views.len() - 1);
            accessors.push(accessor);
            accessors.len() - 1
        };
        let floats = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
        let pos = push(
            floats(&positions),
            json!({ "componentType": 5126, "count": 4, "type": "VEC3",
                    "min": [x0, -0.5, z], "max": [x1, 0.5, z] }),
        );
        let nor = push(
            floats(&normals),
            json!({ "componentType": 5126, "count": 4, "type": "VEC3" }),
        );
        let idx = push(
            order.iter().flat_map(|i| i.to_le_bytes()).collect(),
            json!({ "componentType": 5123, "count": 6, "type": "SCALAR" }),
        );
        meshes.push(json!({ "primitives": [{
            "attributes": { "POSITION": pos, "NORMAL": nor }, "indices": idx, "material": material,
        }]}));
    }
    let mut materials = vec![json!({
        "pbrMetallicRoughness": { "baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0 },
        "emissiveFactor": [1.0, 1.0, 1.0],
        "doubleSided": true,
    })];
    for (transmission, ior) in QUADS {
        materials.push(json!({
            "pbrMetallicRoughness": {
                "baseColorFactor": [TINT[0], TINT[1], TINT[2], 1.0],
                "metallicFactor": 0.0, "roughnessFactor": 0.0,
            },
            "extensions": {
                "KHR_materials_transmission": { "transmissionFactor": transmission },
                "KHR_materials_ior": { "ior": ior },
            },
        }));
    }
    let doc = json!({
        "asset": { "version": "2.0" },
        "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior"],
        "buffers": [{ "uri": "glass.bin", "byteLength": bin.len() }],
        "bufferViews": views,
        "accessors": accessors,
        "materials": materials,
        "meshes": meshes,
        "nodes": (0..4).map(|k| json!({ "mesh": k })).collect::<Vec<_>>(),
        "scenes": [{ "nodes": [0, 1, 2, 3] }],
        "scene": 0,
    });
    std::fs::write(dir.join("glass.bin"), &bin).unwrap();
    std::fs::write(
        dir.join("glass.gltf"),
        serde_json::to_vec_pretty(&doc).unwrap(),
    )
    .unwrap();
}

#[test]
fn a_transmissive_quad_shows_the_background_fresnel_weighted_and_tinted() {
    let Some(gpu) = gpu_or_skip("a_transmissive_quad_shows_the_background") else {
        return;
    };
    let dir = temp_dir("gltf_transmission", "quads");
    write_model(&dir);
    let scene = format!(
        "import \"std/cameras/orthographic.rt\";\n\
         scene glass {{\n\
             settings {{ width: {w}, height: {PX}, samples: 64 }}\n\
             camera Orthographic {{ position: vec3f(0.0, 0.0, 5.0), height: 1.0 }}\n\
             model \"glass.gltf\" {{}}\n\
         }}\n",
        w = 3 * PX
    );
    let path = dir.join("scene.rt");
    std::fs::write(&path, scene).unwrap();
    let compiled = match compile_scene_with(
        std::slice::from_ref(&path),
        None,
        &Options::default(),
        &LinkOptions::default(),
        &KernelOptions::default(),
    ) {
        Ok(c) => c,
        Err(f) => panic!(
            "the test scene does not compile:\n{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        ),
    };
    assert!(
        !compiled.linked.config.cull_back_faces,
        "transmissive materials are not culled"
    );
    let (image, _) =
        common::scene::render(&gpu, &compiled, RenderOptions::default(), "transmission");
    for (k, &(w, ior)) in QUADS.iter().enumerate() {
        let f = ((ior - 1.0) / (ior + 1.0)).powi(2);
        let (mut sum, mut n) = ([0.0f64; 3], 0.0);
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for y in 2..PX - 2 {
            for x in k as u32 * PX + 2..(k as u32 + 1) * PX - 2 {
                let p = image.get(x, y).unwrap();
                for c in 0..3 {
                    let v = f64::from(p[c]);
                    sum[c] += v;
                    lo[c] = lo[c].min(v);
                    hi[c] = hi[c].max(v);
                }
                n += 1.0;
            }
        }
        for c in 0..3 {
            let want = w * (1.0 - f) * TINT[c];
            let mean = sum[c] / n;
            eprintln!("quad {k} channel {c}: mean {mean:.5}, want {want:.5}");
            if f == 0.0 {
                assert!(
                    (lo[c] - want).abs() < 1e-5 && (hi[c] - want).abs() < 1e-5,
                    "quad {k} (ior 1) channel {c}: {}..{} want {want}",
                    lo[c],
                    hi[c]
                );
            } else {
                assert!(
                    (mean - want).abs() <= 0.02 * w * TINT[c],
                    "quad {k} channel {c}: mean {mean} want {want}"
                );
            }
        }
    }
}
