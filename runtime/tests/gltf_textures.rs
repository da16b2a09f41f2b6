//! glTF textures on the GPU: samplers (wrap modes per axis, nearest and linear filtering) and the
//! emissive texture, rendered from generated glTF files on whatever adapter exists (lavapipe on
//! CI); a test skips only when there is no adapter at all, and says so.
//!
//! The file follows the layout of Khronos's TextureSettingsTest: one quad per sampler, side by
//! side, each with the same small texture and uvs running from -1 to 2 across it (three periods),
//! so the wrap modes show. Each quad's material is black, non-metallic and emissive with
//! `emissiveFactor` 1 × the texture; the scene has no lights, so a pixel is exactly the texture
//! value at its uv (glTF's emissive texture is sRGB: the kernel decodes it). An orthographic
//! camera shoots one ray through each pixel centre, and no pixel centre lies on a texel edge, so
//! nearest lookups are exact and the expected values are computed independently here (the test's
//! own wrap functions, sRGB decoding in f64); tolerance 1e-4 (f32 arithmetic; sRGB decoding).

mod common;

use std::path::Path;

use common::image::srgb_to_linear;
use common::{gpu_or_skip, temp_dir};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene_with, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::render::RenderOptions;
use serde_json::{json, Value};

/// The texture: 2×2, top row red then green, bottom row blue then white (sRGB bytes).
const TEXELS: [[u8; 4]; 4] = [
    [255, 0, 0, 255],
    [0, 255, 0, 255],
    [0, 0, 255, 255],
    [255, 255, 255, 255],
];
/// Pixels across one quad (and the image's height).
const QUAD_PX: u32 = 24;

/// glTF wrap mode codes.
const REPEAT: u32 = 10497;
const CLAMP: u32 = 33071;
const MIRROR: u32 = 33648;
/// glTF filter codes.
const NEAREST: u32 = 9728;
const LINEAR: u32 = 9729;

/// (wrapS, wrapT, magFilter) of each quad, left to right.
const QUADS: [(u32, u32, u32); 4] = [
    (REPEAT, REPEAT, NEAREST),
    (CLAMP, CLAMP, NEAREST),
    (MIRROR, MIRROR, NEAREST),
    (CLAMP, MIRROR, LINEAR),
];

/// Texel `(x, y)` of [`TEXELS`] as linear RGB.
fn texel(x: i64, y: i64) -> [f64; 3] {
    let t = TEXELS[(y * 2 + x) as usize];
    [0, 1, 2].map(|k| srgb_to_linear(f64::from(t[k]) / 255.0))
}

/// The glTF spec's wrap of integer texel coordinate `i` into `[0, n)`.
fn wrap(mode: u32, i: i64, n: i64) -> i64 {
    match mode {
        CLAMP => i.max(0).min(n - 1),
        MIRROR => {
            // Period 2n: 0..n forwards, then n..2n backwards.
            let m = ((i % (2 * n)) + 2 * n) % (2 * n);
            if m < n {
                m
            } else {
                2 * n - 1 - m
            }
        }
        _ => ((i % n) + n) % n,
    }
}

/// The expected linear value at `uv` of the texture through sampler `(wrap_s, wrap_t, filter)`.
fn expected(uv: [f64; 2], (ws, wt, filter): (u32, u32, u32)) -> [f64; 3] {
    let at = |x: i64, y: i64| texel(wrap(ws, x, 2), wrap(wt, y, 2));
    if filter == NEAREST {
        return at((uv[0] * 2.0).floor() as i64, (uv[1] * 2.0).floor() as i64);
    }
    // Bilinear between texel centres.
    let (px, py) = (uv[0] * 2.0 - 0.5, uv[1] * 2.0 - 0.5);
    let (x, y) = (px.floor(), py.floor());
    let (fx, fy) = (px - x, py - y);
    let (x, y) = (x as i64, y as i64);
    let (a, b, c, d) = (at(x, y), at(x + 1, y), at(x, y + 1), at(x + 1, y + 1));
    [0, 1, 2].map(|k| {
        let top = a[k] + (b[k] - a[k]) * fx;
        let bottom = c[k] + (d[k] - c[k]) * fx;
        top + (bottom - top) * fy
    })
}

/// The uv at the centre of pixel `i` (0..QUAD_PX) across a quad: -1 to 2 over the quad.
fn uv_at(i: u32) -> f64 {
    -1.0 + 3.0 * (f64::from(i) + 0.5) / f64::from(QUAD_PX)
}

/// Writes `tex.gltf`, `tex.bin` and `checker.png` into `dir`: one quad per sampler of
/// [`QUADS`], quad `k` covering x in [k - 2, k - 1], y in [-0.5, 0.5], facing +z, with material
/// `k`, emissive through texture `k` (sampler `k`).
fn write_model(dir: &Path) {
    let materials: Vec<Value> = (0..QUADS.len())
        .map(|k| {
            json!({
                "name": format!("quad{k}"),
                "pbrMetallicRoughness": { "baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0 },
                "emissiveFactor": [1.0, 1.0, 1.0],
                "emissiveTexture": { "index": k },
            })
        })
        .collect();
    let samplers: Vec<Value> = QUADS
        .iter()
        .map(|&(ws, wt, filter)| {
            json!({ "wrapS": ws, "wrapT": wt, "magFilter": filter, "minFilter": filter })
        })
        .collect();
    write_quads(dir, &materials, &[false; 4], samplers);
}

/// Writes `tex.gltf`, `tex.bin` and `checker.png` into `dir`: quad `k` covering x in
/// [k - 2, k - 1], y in [-0.5, 0.5], with material `k` of `materials`, facing -z when `back[k]`
/// (else +z); texture `k` is the checker through sampler `k` of `samplers`.
fn write_quads(dir: &Path, materials: &[Value], back: &[bool], samplers: Vec<Value>) {
    let mut bin: Vec<u8> = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();
    let mut push = |bytes: Vec<u8>, accessor: Value, bin: &mut Vec<u8>| {
        let view = json!({ "buffer": 0, "byteOffset": bin.len(), "byteLength": bytes.len() });
        bin.extend_from_slice(&bytes);
        views.push(view);
        let mut accessor = accessor;
        accessor["bufferView"] = json!(views.len() - 1);
        accessors.push(accessor);
        accessors.len() - 1
    };
    let floats = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let mut meshes = Vec::new();
    let textures: Vec<Value> = (0..samplers.len())
        .map(|k| json!({ "source": 0, "sampler": k }))
        .collect();
    for (k, &back) in back.iter().enumerate() {
        let x0 = k as f32 - 2.0;
        let positions = [
            x0,
            -0.5,
            0.0,
            x0 + 1.0,
            -0.5,
            0.0,
            x0 + 1.0,
            0.5,
            0.0,
            x0,
            0.5,
            0.0,
        ];
        let pos = push(
            floats(&positions),
            json!({ "componentType": 5126, "count": 4, "type": "VEC3",
                    "min": [x0, -0.5, 0.0], "max": [x0 + 1.0, 0.5, 0.0] }),
            &mut bin,
        );
        // uv (-1, -1) at the top left, (2, 2) at the bottom right (v points down the image).
        let uvs = [-1.0, 2.0, 2.0, 2.0, 2.0, -1.0, -1.0, -1.0];
        let uv = push(
            floats(&uvs),
            json!({ "componentType": 5126, "count": 4, "type": "VEC2" }),
            &mut bin,
        );
        let z = if back { -1.0 } else { 1.0 };
        let normals = [0.0, 0.0, z].repeat(4);
        let normal = push(
            floats(&normals),
            json!({ "componentType": 5126, "count": 4, "type": "VEC3" }),
            &mut bin,
        );
        let order: [u16; 6] = if back {
            [0, 2, 1, 0, 3, 2]
        } else {
            [0, 1, 2, 0, 2, 3]
        };
        let indices: Vec<u8> = order.iter().flat_map(|i| i.to_le_bytes()).collect();
        let idx = push(
            indices,
            json!({ "componentType": 5123, "count": 6, "type": "SCALAR" }),
            &mut bin,
        );
        meshes.push(json!({ "primitives": [{
            "attributes": { "POSITION": pos, "TEXCOORD_0": uv, "NORMAL": normal },
            "indices": idx, "material": k,
        }]}));
    }
    let nodes: Vec<Value> = (0..back.len()).map(|k| json!({ "mesh": k })).collect();
    let doc = json!({
        "asset": { "version": "2.0" },
        "buffers": [{ "uri": "tex.bin", "byteLength": bin.len() }],
        "bufferViews": views,
        "accessors": accessors,
        "images": [{ "uri": "checker.png" }],
        "samplers": samplers,
        "textures": textures,
        "materials": materials,
        "meshes": meshes,
        "nodes": nodes,
        "scenes": [{ "nodes": (0..back.len()).collect::<Vec<_>>() }],
        "scene": 0,
    });
    std::fs::write(dir.join("tex.bin"), &bin).unwrap();
    std::fs::write(
        dir.join("tex.gltf"),
        serde_json::to_vec_pretty(&doc).unwrap(),
    )
    .unwrap();
    let raw: Vec<u8> = TEXELS.iter().flatten().copied().collect();
    let png: image::RgbaImage = image::ImageBuffer::from_raw(2, 2, raw).unwrap();
    png.save(dir.join("checker.png")).unwrap();
}

/// Compiles and renders the `scene.rt` in `dir`: the four quads of its `tex.gltf` seen by an
/// orthographic camera, [`QUAD_PX`] pixels per quad, at `samples` per pixel.
fn render_quads(
    gpu: &rtc_runtime::gpu::Gpu,
    dir: &Path,
    samples: u32,
    what: &str,
) -> rtc_runtime::image_out::LinearImage {
    let width = QUAD_PX * 4;
    let scene = format!(
        "import \"std/cameras/orthographic.rt\";\n\
         scene quads {{\n\
             settings {{ width: {width}, height: {QUAD_PX}, samples: {samples} }}\n\
             camera Orthographic {{ position: vec3f(0.0, 0.0, 5.0), height: 1.0 }}\n\
             model \"tex.gltf\" {{}}\n\
         }}\n"
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
    common::scene::render(gpu, &compiled, RenderOptions::default(), what).0
}

#[test]
fn sampler_wrap_modes_and_filters_and_the_emissive_texture() {
    let Some(gpu) = gpu_or_skip("sampler_wrap_modes_and_filters_and_the_emissive_texture") else {
        return;
    };
    let dir = temp_dir("gltf_textures", "samplers");
    write_model(&dir);
    let image = render_quads(&gpu, &dir, 1, "samplers");
    let mut worst = 0.0f64;
    let mut checked = 0;
    for (k, &sampler) in QUADS.iter().enumerate() {
        for py in 0..QUAD_PX {
            for i in 0..QUAD_PX {
                let px = k as u32 * QUAD_PX + i;
                let got = image.get(px, py).unwrap();
                let want = expected([uv_at(i), uv_at(py)], sampler);
                for c in 0..3 {
                    let err = (f64::from(got[c]) - want[c]).abs();
                    worst = worst.max(err);
                    assert!(
                        err <= 1e-4,
                        "quad {k} {sampler:?}, pixel ({px}, {py}), uv ({:.4}, {:.4}), channel \
                         {c}: got {} want {}",
                        uv_at(i),
                        uv_at(py),
                        got[c],
                        want[c]
                    );
                }
                checked += 1;
            }
        }
    }
    eprintln!("{checked} pixels checked, largest error {worst:.2e}");
    // Spot checks of the expectations themselves, at the first pixel of each quad (uv -0.9375,
    // texel coordinate -1.875 → floor -2): repeat → texel 0 (red), clamp → texel 0 (red),
    // mirror → -2 mirrors to 1 (white, bottom right, on both axes).
    assert_eq!(expected([uv_at(0), uv_at(0)], QUADS[0]), texel(0, 0));
    assert_eq!(expected([uv_at(0), uv_at(0)], QUADS[1]), texel(0, 0));
    assert_eq!(expected([uv_at(0), uv_at(0)], QUADS[2]), texel(1, 1));
}

/// Back faces and blending: quad 0 is alpha-masked, single-sided and seen from the back: not hit
/// (black background); quad 1 the same but double-sided: hit (emissive 1); quad 2 blended with
/// alpha 0.25, facing the camera: stochastic coverage, so its mean over 24×24 pixels × 64 samples
/// (36,864 independent draws; standard error 0.0023) is 0.25 within 0.015 (6.5 standard errors);
/// quad 3 opaque, single-sided, seen from the back: not hit either (traversal culls it; see
/// `gltf_sided.rs`). The checker texture is unused here except as the base colour's alpha (1).
#[test]
fn single_sided_materials_cull_back_faces_and_blending_is_stochastic_coverage() {
    let Some(gpu) = gpu_or_skip("single_sided_and_blend") else {
        return;
    };
    let dir = temp_dir("gltf_textures", "sided");
    let material = |mode: &str, alpha: f64, double: bool| {
        json!({
            "pbrMetallicRoughness": { "baseColorFactor": [0.0, 0.0, 0.0, alpha], "metallicFactor": 0.0 },
            "emissiveFactor": [1.0, 1.0, 1.0],
            "alphaMode": mode,
            "doubleSided": double,
        })
    };
    let materials = [
        material("MASK", 1.0, false),
        material("MASK", 1.0, true),
        material("BLEND", 0.25, true),
        material("OPAQUE", 1.0, false),
    ];
    write_quads(
        &dir,
        &materials,
        &[true, true, false, true],
        vec![json!({})],
    );
    let samples = 64;
    let image = render_quads(&gpu, &dir, samples, "sided");
    let mean = |k: u32| {
        let mut sum = 0.0f64;
        for y in 0..QUAD_PX {
            for x in 0..QUAD_PX {
                sum += f64::from(image.get(k * QUAD_PX + x, y).unwrap()[0]);
            }
        }
        sum / f64::from(QUAD_PX * QUAD_PX)
    };
    let means: Vec<f64> = (0..4).map(mean).collect();
    eprintln!("quad means: {means:?}");
    assert_eq!(
        means[0], 0.0,
        "a single-sided masked quad seen from the back is not hit"
    );
    assert!((means[1] - 1.0).abs() < 1e-5, "double-sided: {}", means[1]);
    assert!(
        (means[2] - 0.25).abs() < 0.015,
        "blend coverage: {}",
        means[2]
    );
    assert_eq!(
        means[3], 0.0,
        "an opaque single-sided quad seen from the back is not hit"
    );
}

/// `KHR_texture_transform` on the emissive texture (nearest, repeat): quad `k` has transform
/// `TRANSFORMS[k]` (offset, rotation, scale); a pixel must show the texel at the transformed uv,
/// computed here from the extension's GLSL (`translation × rotation × scale`, rotation
/// `mat3(cos, sin, 0, -sin, cos, 0, 0, 0, 1)` column-major). No pixel centre maps to a texel
/// edge (checked: at least 0.05 texels away), so nearest lookups are exact; tolerance 1e-4.
#[test]
fn texture_transforms_map_the_uvs_of_each_texture() {
    const TRANSFORMS: [([f64; 2], f64, [f64; 2]); 4] = [
        ([0.0, 0.0], 0.0, [1.0, 1.0]),
        ([0.25, 0.5], 0.0, [1.0, 1.0]),
        ([0.5, 0.25], std::f64::consts::FRAC_PI_2, [2.0, 3.0]),
        ([0.0, 0.0], 0.0, [0.5, 2.0]),
    ];
    let Some(gpu) = gpu_or_skip("texture_transforms_map_the_uvs_of_each_texture") else {
        return;
    };
    let dir = temp_dir("gltf_textures", "transform");
    let materials: Vec<Value> = TRANSFORMS
        .iter()
        .map(|&(offset, rotation, scale)| {
            json!({
                "pbrMetallicRoughness": { "baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0 },
                "emissiveFactor": [1.0, 1.0, 1.0],
                "emissiveTexture": { "index": 0, "extensions": { "KHR_texture_transform": {
                    "offset": offset, "rotation": rotation, "scale": scale,
                } } },
            })
        })
        .collect();
    write_quads(
        &dir,
        &materials,
        &[false; 4],
        vec![json!({ "magFilter": NEAREST })],
    );
    let image = render_quads(&gpu, &dir, 1, "transform");
    let mut checked = 0;
    for (k, &(offset, rotation, scale)) in TRANSFORMS.iter().enumerate() {
        let (s, c) = rotation.sin_cos();
        for py in 0..QUAD_PX {
            for i in 0..QUAD_PX {
                let (u, v) = (uv_at(i), uv_at(py));
                let (su, sv) = (u * scale[0], v * scale[1]);
                let uv = [c * su - s * sv + offset[0], s * su + c * sv + offset[1]];
                let edge = uv
                    .iter()
                    .map(|x| ((x * 2.0) - (x * 2.0).round()).abs())
                    .fold(1.0, f64::min);
                assert!(
                    edge > 0.05,
                    "quad {k} pixel ({i}, {py}) lies on a texel edge"
                );
                let want = expected(uv, (REPEAT, REPEAT, NEAREST));
                let got = image.get(k as u32 * QUAD_PX + i, py).unwrap();
                for ch in 0..3 {
                    assert!(
                        (f64::from(got[ch]) - want[ch]).abs() <= 1e-4,
                        "quad {k} pixel ({i}, {py}) uv' {uv:?} channel {ch}: got {} want {}",
                        got[ch],
                        want[ch]
                    );
                }
                checked += 1;
            }
        }
    }
    eprintln!("{checked} pixels checked");
}
