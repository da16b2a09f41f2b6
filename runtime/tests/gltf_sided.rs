//! glTF `doubleSided: false` on opaque materials, on the GPU: a single-sided opaque object is
//! invisible from behind to every viewer, the light included (spec/scenes.md, "Single-sided glTF
//! materials"): camera rays pass through its back faces, and shadow rays, which run against the
//! light's travel, pass through the faces whose back the light sees; under both execution models.
//!
//! The generated file (one `.gltf`, no textures) has a white, rough, double-sided ground at z = 0
//! under the lower half of the view (y in [-1, 0]) and four emissive occluder quads at z = 1 above
//! it, in the upper half (y in [0, 1]), one per column of width 1 (x in [k - 2, k - 1]). An
//! orthographic camera looks down -z from z = 5; a directional light travels along (0, -1, -1),
//! so the shadow of occluder k falls exactly on the ground of column k. Camera and light both look
//! at the occluders' +z side. Occluders:
//! 0. single-sided, facing the ground (-z): the camera sees its back: invisible (black
//!    background); so does the light (a shadow ray from the ground meets its front, against the
//!    light's travel): the ground is lit;
//! 1. single-sided, facing the camera (+z): visible, and the light sees its front: the ground is
//!    in shadow;
//! 2. double-sided, facing the ground: visible, and the ground is in shadow;
//! 3. occluder 0's mesh under a mirroring node (scale x -1): glTF reverses the winding under a
//!    negative determinant, so the mirrored quad still faces the ground, like occluder 0:
//!    invisible, and the ground is lit.
//!
//! Expected values: an invisible occluder's pixels are exactly 0 (nothing else is there); a
//! visible one's are at least its emission, 1 (minus 1e-5); shadowed ground is exactly 0 (no
//! other light, no ambient); lit ground is above 0.05.
//! Only pixels at least 2 pixels from a column or row edge are checked. Both execution models
//! render the same image within 1e-5 per channel.

mod common;

use common::{gpu_or_skip, temp_dir};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene_with, ExecModel, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::image_out::LinearImage;
use rtc_runtime::render::RenderOptions;
use serde_json::{json, Value};

/// Pixels per world unit.
const PX: u32 = 12;

/// Writes `sided.gltf` (see the module docs) into `dir`; with `masked`, the single-sided occluders'
/// material is `alphaMode: MASK` (alpha 1, so every hit counts): culled by its `@any_hit` program
/// instead of by traversal.
fn write_model(dir: &std::path::Path, masked: bool) {
    let mut bin: Vec<u8> = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();
    let mut meshes = Vec::new();
    // (x0, x1, y0, y1, z, facing +z, material)
    let quads = [
        (-2.0f32, 2.0, -1.0, 0.0, 0.0, true, 0),
        (-2.0, -1.0, 0.0, 1.0, 1.0, false, 1),
        (-1.0, 0.0, 0.0, 1.0, 1.0, true, 1),
        (0.0, 1.0, 0.0, 1.0, 1.0, false, 2),
        // Mirrored by its node onto x in [1, 2].
        (-2.0, -1.0, 0.0, 1.0, 1.0, false, 1),
    ];
    for (x0, x1, y0, y1, z, up, material) in quads {
        let positions = [x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z];
        let normal = if up { 1.0f32 } else { -1.0 };
        let normals = [0.0, 0.0, normal].repeat(4);
        // Counter-clockwise seen from +z when facing +z.
        let order: [u16; 6] = if up {
            [0, 1, 2, 0, 2, 3]
        } else {
            [0, 2, 1, 0, 3, 2]
        };
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
                    "min": [x0, y0, z], "max": [x1, y1, z] }),
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
    let occluder = |double: bool| {
        let mode = if masked && !double { "MASK" } else { "OPAQUE" };
        json!({
            "pbrMetallicRoughness": { "baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0 },
            "emissiveFactor": [1.0, 1.0, 1.0],
            "doubleSided": double,
            "alphaMode": mode,
        })
    };
    let doc = json!({
        "asset": { "version": "2.0" },
        "buffers": [{ "uri": "sided.bin", "byteLength": bin.len() }],
        "bufferViews": views,
        "accessors": accessors,
        "materials": [
            { "pbrMetallicRoughness": { "metallicFactor": 0.0, "roughnessFactor": 1.0 }, "doubleSided": true },
            occluder(false),
            occluder(true),
        ],
        "meshes": meshes,
        "nodes": [
            { "mesh": 0 }, { "mesh": 1 }, { "mesh": 2 }, { "mesh": 3 },
            { "mesh": 4, "scale": [-1.0, 1.0, 1.0], "translation": [0.0, 0.0, 0.0] },
        ],
        "scenes": [{ "nodes": [0, 1, 2, 3, 4] }],
        "scene": 0,
    });
    std::fs::write(dir.join("sided.bin"), &bin).unwrap();
    std::fs::write(
        dir.join("sided.gltf"),
        serde_json::to_vec_pretty(&doc).unwrap(),
    )
    .unwrap();
}

/// Mean of channel 0 over the inner pixels of column `k` (0..4), row `row` (0: top, occluders;
/// 1: bottom, ground), with the smallest and largest value.
fn cell(image: &LinearImage, k: u32, row: u32) -> (f64, f64, f64) {
    let (mut sum, mut lo, mut hi, mut n) = (0.0f64, f64::INFINITY, f64::NEG_INFINITY, 0.0);
    for y in row * PX + 2..(row + 1) * PX - 2 {
        for x in k * PX + 2..(k + 1) * PX - 2 {
            let v = f64::from(image.get(x, y).unwrap()[0]);
            sum += v;
            lo = lo.min(v);
            hi = hi.max(v);
            n += 1.0;
        }
    }
    (sum / n, lo, hi)
}

#[test]
fn single_sided_opaque_objects_are_invisible_from_behind_to_camera_and_light() {
    check_sides(false);
}

/// The same scene with the single-sided occluders `MASK`ed: their any-hit program applies the same
/// rule as traversal's culling.
#[test]
fn single_sided_masked_objects_are_invisible_from_behind_to_camera_and_light() {
    check_sides(true);
}

/// Renders the scene of the module docs under both execution models and checks every cell.
fn check_sides(masked: bool) {
    let label = if masked { "masked" } else { "opaque" };
    let Some(gpu) = gpu_or_skip(&format!("single_sided_{label}_objects")) else {
        return;
    };
    let dir = temp_dir("gltf_sided", label);
    write_model(&dir, masked);
    let scene = format!(
        "import \"std/cameras/orthographic.rt\";\n\
         import \"std/lights/directional.rt\";\n\
         scene sided {{\n\
             settings {{ width: {w}, height: {h}, samples: 1 }}\n\
             camera Orthographic {{ position: vec3f(0.0, 0.0, 5.0), height: 2.0 }}\n\
             light DirectionalLight {{ direction: vec3f(0.0, -1.0, -1.0), intensity: 3.0 }}\n\
             model \"sided.gltf\" {{}}\n\
         }}\n",
        w = 4 * PX,
        h = 2 * PX
    );
    let path = dir.join("scene.rt");
    std::fs::write(&path, scene).unwrap();
    let compiled = match compile_scene_with(
        std::slice::from_ref(&path),
        None,
        &Options::default(),
        &LinkOptions::default(),
        &KernelOptions {
            exec: Some(ExecModel::Wavefront),
            ..KernelOptions::default()
        },
    ) {
        Ok(c) => c,
        Err(f) => panic!(
            "the test scene does not compile:\n{}",
            rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
        ),
    };
    // Traversal culls only for opaque single-sided materials; masked ones cull in any-hit.
    assert_eq!(compiled.linked.config.cull_back_faces, !masked);
    let options = |exec| RenderOptions {
        exec: Some(exec),
        ..RenderOptions::default()
    };
    let (mega, _) = common::scene::render(&gpu, &compiled, options(ExecModel::Megakernel), "mega");
    let (wave, stats) =
        common::scene::render(&gpu, &compiled, options(ExecModel::Wavefront), "wavefront");
    assert_eq!(stats.exec, ExecModel::Wavefront);
    for (name, image) in [("megakernel", &mega), ("wavefront", &wave)] {
        let top: Vec<_> = (0..4).map(|k| cell(image, k, 0)).collect();
        let ground: Vec<_> = (0..4).map(|k| cell(image, k, 1)).collect();
        eprintln!("{label} {name}: occluders {top:?}\n  ground {ground:?}");
        assert_eq!(
            top[0].2, 0.0,
            "{name}: a back face is invisible to the camera"
        );
        for (k, cell) in top.iter().enumerate().take(3).skip(1) {
            assert!(
                cell.1 >= 1.0 - 1e-5,
                "{name}: occluder {k} visible: {cell:?}"
            );
        }
        assert!(
            ground[0].1 > 0.05,
            "{name}: a surface whose back the light sees casts no shadow: {:?}",
            ground[0]
        );
        assert_eq!(
            ground[1].2, 0.0,
            "{name}: a surface whose front the light sees shadows"
        );
        assert_eq!(ground[2].2, 0.0, "{name}: a double-sided occluder shadows");
        assert!(
            top[3].2 == 0.0 && ground[3].1 > 0.05 && (ground[3].0 - ground[0].0).abs() < 1e-5,
            "{name}: the mirrored occluder keeps its front to the ground: {:?} {:?}",
            top[3],
            ground[3]
        );
    }
    let mut worst = 0.0f32;
    for y in 0..2 * PX {
        for x in 0..4 * PX {
            let (a, b) = (mega.get(x, y).unwrap(), wave.get(x, y).unwrap());
            for c in 0..3 {
                worst = worst.max((a[c] - b[c]).abs());
            }
        }
    }
    assert!(worst <= 1e-5, "the execution models differ by {worst}");
}
