//! glTF vertex attributes on the GPU: `COLOR_0` vertex colours, textures on `TEXCOORD_1`, and
//! normal maps with the file's `TANGENT` or MikkTSpace tangents, rendered from generated glTF files
//! on whatever adapter exists (lavapipe on CI); a test skips only when there is no adapter.
//!
//! Every file is a row of unit quads in the plane z = 0 facing +z (x in [k - n/2, k - n/2 + 1]
//! for quad k, y in [-0.5, 0.5], uv (0, 0) at the top left), seen by an orthographic camera
//! along -z, one ray through each pixel centre. Lit quads use a non-metallic material of
//! roughness 1 under one directional light of radiance `E`, whose glTF BRDF has a closed form
//! (α = 1: `D = 1/π`, `V = 1 / (2 (n·l + n·v))`, and Schlick's `F` depends on `v·h` only):
//! `L = E (n·l) ((1 - F) c / π + F / (2π (n·l + n·v)))`, computed here in f64 from the normal
//! the test expects; tolerances are stated at each test.

mod common;

use std::path::Path;

use common::{gpu_or_skip, temp_dir};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene_with, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::render::RenderOptions;
use serde_json::{json, Value};

/// Pixels across one quad (and the image's height).
const QUAD_PX: u32 = 16;

/// The light's direction of travel and radiance (`DirectionalLight` `direction`, `intensity`).
const LIGHT_TRAVEL: [f64; 3] = [-0.6, -0.2, -0.75];
const LIGHT_E: f64 = 3.0;

/// One quad's extra data.
#[derive(Default)]
struct Quad {
    /// Its material.
    material: Value,
    /// `NORMAL` of its 4 vertices (default +z).
    normals: Option<[[f32; 3]; 4]>,
    /// `TANGENT` of its 4 vertices.
    tangents: Option<[[f32; 4]; 4]>,
    /// `TEXCOORD_0` (default: (0, 1), (1, 1), (1, 0), (0, 0) at the corners).
    uv0: Option<[[f32; 2]; 4]>,
    /// `TEXCOORD_1`.
    uv1: Option<[[f32; 2]; 4]>,
    /// `COLOR_0`: the bytes and the accessor (componentType, type, normalized).
    colors: Option<(Vec<u8>, u32, &'static str, bool)>,
}

/// Writes `attr.gltf`, `attr.bin` and the images (`image{i}.png`, RGBA8 `(width, texels)`) into
/// `dir`; texture `i` reads image `i` through a nearest, repeating sampler.
fn write_model(dir: &Path, quads: &[Quad], images: &[(u32, Vec<[u8; 4]>)]) {
    let mut bin: Vec<u8> = Vec::new();
    let mut views = Vec::new();
    let mut accessors = Vec::new();
    let mut push = |bytes: Vec<u8>, accessor: Value, bin: &mut Vec<u8>| {
        while bin.len() % 4 != 0 {
            bin.push(0);
        }
        let view = json!({ "buffer": 0, "byteOffset": bin.len(), "byteLength": bytes.len() });
        bin.extend_from_slice(&bytes);
        views.push(view);
        let mut accessor = accessor;
        accessor["bufferView"] = json!(views.len() - 1);
        accessors.push(accessor);
        accessors.len() - 1
    };
    let floats = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let n = quads.len() as f32;
    let mut meshes = Vec::new();
    let mut materials = Vec::new();
    for (k, q) in quads.iter().enumerate() {
        let x0 = k as f32 - n / 2.0;
        let positions = [
            [x0, -0.5, 0.0],
            [x0 + 1.0, -0.5, 0.0],
            [x0 + 1.0, 0.5, 0.0],
            [x0, 0.5, 0.0],
        ];
        let mut attributes = serde_json::Map::new();
        let pos = push(
            floats(positions.as_flattened()),
            json!({ "componentType": 5126, "count": 4, "type": "VEC3",
                    "min": [x0, -0.5, 0.0], "max": [x0 + 1.0, 0.5, 0.0] }),
            &mut bin,
        );
        attributes.insert("POSITION".into(), json!(pos));
        let normals = q.normals.unwrap_or([[0.0, 0.0, 1.0]; 4]);
        let normal = push(
            floats(normals.as_flattened()),
            json!({ "componentType": 5126, "count": 4, "type": "VEC3" }),
            &mut bin,
        );
        attributes.insert("NORMAL".into(), json!(normal));
        let uv0 = q
            .uv0
            .unwrap_or([[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]]);
        let uv = push(
            floats(uv0.as_flattened()),
            json!({ "componentType": 5126, "count": 4, "type": "VEC2" }),
            &mut bin,
        );
        attributes.insert("TEXCOORD_0".into(), json!(uv));
        if let Some(uv1) = q.uv1 {
            let a = push(
                floats(uv1.as_flattened()),
                json!({ "componentType": 5126, "count": 4, "type": "VEC2" }),
                &mut bin,
            );
            attributes.insert("TEXCOORD_1".into(), json!(a));
        }
        if let Some(t) = q.tangents {
            let a = push(
                floats(t.as_flattened()),
                json!({ "componentType": 5126, "count": 4, "type": "VEC4" }),
                &mut bin,
            );
            attributes.insert("TANGENT".into(), json!(a));
        }
        if let Some((bytes, component, ty, normalized)) = &q.colors {
            let a = push(
                bytes.clone(),
                json!({ "componentType": component, "count": 4, "type": ty,
                        "normalized": normalized }),
                &mut bin,
            );
            attributes.insert("COLOR_0".into(), json!(a));
        }
        let indices: Vec<u8> = [0u16, 1, 2, 0, 2, 3]
            .iter()
            .flat_map(|i| i.to_le_bytes())
            .collect();
        let idx = push(
            indices,
            json!({ "componentType": 5123, "count": 6, "type": "SCALAR" }),
            &mut bin,
        );
        meshes.push(json!({ "primitives": [{
            "attributes": attributes, "indices": idx, "material": k,
        }]}));
        materials.push(q.material.clone());
    }
    let textures: Vec<Value> = (0..images.len())
        .map(|i| json!({ "source": i, "sampler": 0 }))
        .collect();
    let image_uris: Vec<Value> = (0..images.len())
        .map(|i| json!({ "uri": format!("image{i}.png") }))
        .collect();
    let doc = json!({
        "asset": { "version": "2.0" },
        "buffers": [{ "uri": "attr.bin", "byteLength": bin.len() }],
        "bufferViews": views,
        "accessors": accessors,
        "images": image_uris,
        "samplers": [{ "magFilter": 9728, "minFilter": 9728 }],
        "textures": textures,
        "materials": materials,
        "meshes": meshes,
        "nodes": (0..quads.len()).map(|k| json!({ "mesh": k })).collect::<Vec<_>>(),
        "scenes": [{ "nodes": (0..quads.len()).collect::<Vec<_>>() }],
        "scene": 0,
    });
    std::fs::write(dir.join("attr.bin"), &bin).unwrap();
    std::fs::write(
        dir.join("attr.gltf"),
        serde_json::to_vec_pretty(&doc).unwrap(),
    )
    .unwrap();
    for (i, (width, texels)) in images.iter().enumerate() {
        let raw: Vec<u8> = texels.iter().flatten().copied().collect();
        let height = texels.len() as u32 / width;
        let png: image::RgbaImage = image::ImageBuffer::from_raw(*width, height, raw).unwrap();
        png.save(dir.join(format!("image{i}.png"))).unwrap();
    }
}

/// Compiles and renders `attr.gltf` in `dir` (`quads` quads), lit by the test's directional
/// light when `lit`, at 1 sample per pixel.
fn render(
    gpu: &rtc_runtime::gpu::Gpu,
    dir: &Path,
    quads: u32,
    lit: bool,
    what: &str,
) -> rtc_runtime::image_out::LinearImage {
    let width = QUAD_PX * quads;
    let [x, y, z] = LIGHT_TRAVEL;
    let light = if lit {
        format!(
            "light DirectionalLight {{ direction: vec3f({x:?}, {y:?}, {z:?}), intensity: {LIGHT_E:?} }}\n"
        )
    } else {
        String::new()
    };
    let scene = format!(
        "import \"std/cameras/orthographic.rt\";\n\
         import \"std/lights/directional.rt\";\n\
         scene quads {{\n\
             settings {{ width: {width}, height: {QUAD_PX}, samples: 1 }}\n\
             camera Orthographic {{ position: vec3f(0.0, 0.0, 5.0), height: 1.0 }}\n\
             {light}\
             model \"attr.gltf\" {{}}\n\
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

fn normalize(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|c| c / l)
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The closed form of the module docs: radiance toward +z of a non-metallic, roughness-1 glTF
/// material of base colour `c` with shading normal `n`, under the test's light.
fn lit_radiance(c: [f64; 3], n: [f64; 3]) -> [f64; 3] {
    let l = normalize(LIGHT_TRAVEL.map(|x| -x));
    let v = [0.0, 0.0, 1.0];
    let h = normalize([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
    let ndl = dot(n, l).max(0.0);
    let ndv = dot(n, v).max(1e-4);
    let k = 1.0 - dot(v, h).clamp(0.0, 1.0);
    let f = 0.04 + 0.96 * k.powi(5);
    let pi = std::f64::consts::PI;
    c.map(|c| LIGHT_E * ndl * ((1.0 - f) * c / pi + f / (2.0 * pi * (ndl + ndv))))
}

/// A non-metallic, roughness-1 material with base colour factor `c`, plus `extra` fields.
fn rough(c: [f64; 3], extra: Value) -> Value {
    let mut m = json!({
        "pbrMetallicRoughness": { "baseColorFactor": [c[0], c[1], c[2], 1.0],
                                  "metallicFactor": 0.0, "roughnessFactor": 1.0 },
        "doubleSided": true,
    });
    if let (Some(m), Value::Object(extra)) = (m.as_object_mut(), extra) {
        m.extend(extra);
    }
    m
}

/// Pixel `(x, y)` of quad `k` checked against `want` within `tol` (absolute), with a message.
fn check(
    image: &rtc_runtime::image_out::LinearImage,
    k: u32,
    want: impl Fn(u32, u32) -> [f64; 3],
    tol: f64,
    what: &str,
) -> f64 {
    let mut worst = 0.0f64;
    for y in 0..QUAD_PX {
        for x in 0..QUAD_PX {
            let got = image.get(k * QUAD_PX + x, y).unwrap();
            let want = want(x, y);
            for c in 0..3 {
                let err = (f64::from(got[c]) - want[c]).abs();
                worst = worst.max(err);
                assert!(
                    err <= tol,
                    "{what}: quad {k} pixel ({x}, {y}) channel {c}: got {} want {}",
                    got[c],
                    want[c]
                );
            }
        }
    }
    worst
}

/// `COLOR_0` multiplies the base colour: quad 0 has RGB float colours (0.8, 0.4, 0.2) at every
/// vertex on a white base, quad 1 normalised RGBA u8 colours (51, 153, 255, 255) on a base of
/// (0.5, 1, 0.5), quad 2 normalised RGBA u16 colours from red on the left to blue on the right
/// (interpolated linearly across the quad, the pixel centre's u), quad 3 no colours (base grey
/// 0.5). Expected: the closed form with `c` = base × colour; tolerance 2e-4 absolute (the
/// colours are stored as unorm8, which holds these values exactly up to f32 rounding, and u16's
/// 1.0 and 0.0 likewise; the interpolation is f32).
#[test]
fn vertex_colours_multiply_the_base_colour() {
    let Some(gpu) = gpu_or_skip("vertex_colours_multiply_the_base_colour") else {
        return;
    };
    let dir = temp_dir("gltf_attributes", "colours");
    let f32_rgb: Vec<u8> = [0.8f32, 0.4, 0.2]
        .repeat(4)
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let u8_rgba: Vec<u8> = [51u8, 153, 255, 255].repeat(4);
    let red = [65535u16, 0, 0, 65535];
    let blue = [0u16, 0, 65535, 65535];
    let u16_rgba: Vec<u8> = [red, blue, blue, red]
        .as_flattened()
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let quads = [
        Quad {
            material: rough([1.0; 3], json!({})),
            colors: Some((f32_rgb, 5126, "VEC3", false)),
            ..Quad::default()
        },
        Quad {
            material: rough([0.5, 1.0, 0.5], json!({})),
            colors: Some((u8_rgba, 5121, "VEC4", true)),
            ..Quad::default()
        },
        Quad {
            material: rough([1.0; 3], json!({})),
            colors: Some((u16_rgba, 5123, "VEC4", true)),
            ..Quad::default()
        },
        Quad {
            material: rough([0.5; 3], json!({})),
            ..Quad::default()
        },
    ];
    write_model(&dir, &quads, &[]);
    let image = render(&gpu, &dir, 4, true, "colours");
    let n = [0.0, 0.0, 1.0];
    let tol = 2e-4;
    let mut worst = check(
        &image,
        0,
        |_, _| lit_radiance([0.8, 0.4, 0.2], n),
        tol,
        "f32 RGB",
    );
    worst = worst.max(check(
        &image,
        1,
        |_, _| lit_radiance([0.1, 0.6, 0.5], n),
        tol,
        "u8 RGBA",
    ));
    worst = worst.max(check(
        &image,
        2,
        |x, _| {
            let u = (f64::from(x) + 0.5) / f64::from(QUAD_PX);
            lit_radiance([1.0 - u, 0.0, u], n)
        },
        tol,
        "u16 RGBA gradient",
    ));
    worst = worst.max(check(
        &image,
        3,
        |_, _| lit_radiance([0.5; 3], n),
        tol,
        "no colours",
    ));
    eprintln!("largest error {worst:.2e}");
}

/// A texture on `TEXCOORD_1`: quad 0's emissive texture (a 2×2 checker, nearest) has
/// `texCoord: 1`, with uv set 0 constant (0.25, 0.25) and set 1 the corners (0, 1) … (0, 0);
/// quad 1 the same texture on set 0 with the same attributes. No light: a pixel is the texel
/// (sRGB-decoded) at its uv. Quad 0 must show the 2×2 checker across it, quad 1 the top-left
/// texel everywhere; tolerance 1e-4 (nearest lookups at pixel centres, none on a texel edge).
#[test]
fn texcoord_1_selects_the_second_uv_set() {
    let Some(gpu) = gpu_or_skip("texcoord_1_selects_the_second_uv_set") else {
        return;
    };
    let dir = temp_dir("gltf_attributes", "uv1");
    let texels = vec![
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [0, 0, 255, 255],
        [255, 255, 255, 255],
    ];
    let srgb = |c: u8| {
        let c = f64::from(c) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    let emissive = |set: u32| {
        json!({
            "pbrMetallicRoughness": { "baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0 },
            "emissiveFactor": [1.0, 1.0, 1.0],
            "emissiveTexture": { "index": 0, "texCoord": set },
        })
    };
    let quad = |set| Quad {
        material: emissive(set),
        uv0: Some([[0.25, 0.25]; 4]),
        uv1: Some([[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]]),
        ..Quad::default()
    };
    write_model(&dir, &[quad(1), quad(0)], &[(2, texels.clone())]);
    let image = render(&gpu, &dir, 2, false, "uv1");
    let at = |x: usize, y: usize| {
        let t = texels[y * 2 + x];
        [srgb(t[0]), srgb(t[1]), srgb(t[2])]
    };
    let half = QUAD_PX / 2;
    check(
        &image,
        0,
        |x, y| at(usize::from(x >= half), usize::from(y >= half)),
        1e-4,
        "texCoord 1",
    );
    check(&image, 1, |_, _| at(0, 0), 1e-4, "texCoord 0");
}

/// Normal mapping against the closed form: every quad's normal texture is one texel `(r, g, b)`
/// encoding the tangent-space normal `m = 2 (r, g, b) / 255 - 1`; on these quads the tangent is
/// +x (u grows to the right) and the bitangent +y (v grows downwards, glTF's normal textures
/// have +y up), so the shading normal is `normalize(s m.x, s m.y, m.z)` for the texture's
/// `scale` `s`. Quad 0: the file's `TANGENT` (1, 0, 0, 1); quad 1: no `TANGENT`, tangents
/// generated with MikkTSpace; quad 2: file tangents, `scale` 0.5; quad 3: no normal texture
/// (the flat normal +z, with vertex colours so it too is a detail material); quad 4: a tangent
/// of zero (degenerate uvs), which must leave the flat normal and no NaN. Tolerance 2e-3
/// absolute on radiances up to about 1 (the tangents are stored octahedrally as 2 × 16 bits,
/// about 1e-4 radians).
#[test]
fn normal_maps_tilt_the_shading_normal() {
    let Some(gpu) = gpu_or_skip("normal_maps_tilt_the_shading_normal") else {
        return;
    };
    let dir = temp_dir("gltf_attributes", "normal");
    let texel = [191u8, 96, 230, 255];
    let m = [0, 1, 2].map(|k| 2.0 * f64::from(texel[k]) / 255.0 - 1.0);
    let mapped = |scale: f64| {
        rough(
            [0.7; 3],
            json!({ "normalTexture": { "index": 0, "scale": scale } }),
        )
    };
    let x_tangent = Some([[1.0, 0.0, 0.0, 1.0]; 4]);
    let white: Vec<u8> = [255u8; 4].repeat(4);
    let quads = [
        Quad {
            material: mapped(1.0),
            tangents: x_tangent,
            ..Quad::default()
        },
        Quad {
            material: mapped(1.0),
            ..Quad::default()
        },
        Quad {
            material: mapped(0.5),
            tangents: x_tangent,
            ..Quad::default()
        },
        Quad {
            material: rough([0.7; 3], json!({})),
            colors: Some((white, 5121, "VEC4", true)),
            ..Quad::default()
        },
        Quad {
            material: mapped(1.0),
            uv0: Some([[0.5, 0.5]; 4]),
            ..Quad::default()
        },
    ];
    write_model(&dir, &quads, &[(1, vec![texel])]);
    let image = render(&gpu, &dir, 5, true, "normal");
    let c = [0.7; 3];
    let tol = 2e-3;
    let tilted = |s: f64| normalize([s * m[0], s * m[1], m[2]]);
    let flat = [0.0, 0.0, 1.0];
    // The map must matter: the tilted normal's radiance differs from the flat one's.
    assert!((lit_radiance(c, tilted(1.0))[0] - lit_radiance(c, flat)[0]).abs() > 0.05);
    let mut worst = check(
        &image,
        0,
        |_, _| lit_radiance(c, tilted(1.0)),
        tol,
        "file tangents",
    );
    worst = worst.max(check(
        &image,
        1,
        |_, _| lit_radiance(c, tilted(1.0)),
        tol,
        "MikkTSpace tangents",
    ));
    worst = worst.max(check(
        &image,
        2,
        |_, _| lit_radiance(c, tilted(0.5)),
        tol,
        "scale 0.5",
    ));
    worst = worst.max(check(
        &image,
        3,
        |_, _| lit_radiance(c, flat),
        tol,
        "no normal texture",
    ));
    worst = worst.max(check(
        &image,
        4,
        |_, _| lit_radiance(c, flat),
        tol,
        "degenerate uvs",
    ));
    eprintln!("largest error {worst:.2e}");
}
