//! No input panics: random bytes, random bytes behind each format's magic, mutated valid files
//! and OBJ-like text go through every loader, which may fail but must return.

use std::path::Path;

use proptest::collection::vec;
use proptest::prelude::*;
use serde_json::json;

use super::gltf_builder::{base64, small_png, triangle};
use super::TempDir;
use crate::assets::model::parse_gltf;
use crate::assets::obj::parse_obj;
use crate::assets::texture::decode_image;
use crate::assets::{load_gltf, load_image, load_obj};

/// Runs every loader on `bytes`; only a panic fails.
fn all_loaders(bytes: &[u8]) {
    let _ = parse_gltf(bytes, Path::new("fuzz.glb"));
    let _ = parse_obj(bytes, Path::new("fuzz.obj"));
    let _ = decode_image(bytes, Path::new("fuzz.img"));
}

/// A `.glb` that exercises most of the importer: sparse accessor, strided u8 uvs, an embedded
/// PNG, a material, a camera, a light and a node hierarchy.
pub(super) fn rich_glb() -> Vec<u8> {
    let (mut b, pos, idx) = triangle();
    let sparse_indices = b.view(&[1u8, 2], None);
    let sparse_values = b.view(&[0u8; 24], None);
    let sparse = b.accessor(json!({
        "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0],
        "sparse": { "count": 2, "indices": { "bufferView": sparse_indices, "componentType": 5121 },
                    "values": { "bufferView": sparse_values } },
    }));
    let uv_view = b.view(&[0, 0, 9, 9, 255, 0, 9, 9, 0, 255, 9, 9], Some(4));
    let uv = b.accessor(json!({
        "bufferView": uv_view, "componentType": 5121, "normalized": true, "count": 3, "type": "VEC2",
    }));
    let image = b.view(&small_png(), None);
    b.glb(json!({
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": [{ "type": "spot", "spot": {} }] } },
        "meshes": [{ "primitives": [
            { "attributes": { "POSITION": pos, "TEXCOORD_0": uv }, "indices": idx, "material": 0 },
            { "attributes": { "POSITION": sparse }, "mode": 4 },
        ] }],
        "materials": [{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }],
        "textures": [{ "source": 0 }],
        "images": [{ "bufferView": image, "mimeType": "image/png" }],
        "cameras": [{ "type": "perspective", "perspective": { "yfov": 1.0, "znear": 0.1 } }],
        "nodes": [
            { "children": [1, 2], "translation": [1, 2, 3] },
            { "mesh": 0, "rotation": [0.0, 0.6, 0.0, 0.8] },
            { "camera": 0, "children": [3] },
            { "extensions": { "KHR_lights_punctual": { "light": 0 } } },
        ],
        "scenes": [{ "nodes": [0] }],
        "scene": 0,
    }))
}

/// The JSON of a `.gltf` with a data-URI buffer (so mutations stay self-contained).
fn rich_gltf_json() -> Vec<u8> {
    let (b, pos, idx) = triangle();
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        json!({
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": pos, "NORMAL": pos }, "indices": idx }] }],
            "nodes": [{ "mesh": 0, "children": [1] }, { "mesh": 0, "scale": [1, 2, 3] }],
            "scenes": [{ "nodes": [0] }],
        }),
    );
    serde_json::to_vec(&doc).unwrap()
}

fn encoded(format: image::ImageFormat) -> Vec<u8> {
    let img: image::Rgba32FImage = image::ImageBuffer::from_fn(5, 3, |x, y| {
        image::Rgba([x as f32 / 4.0, y as f32 / 2.0, 0.5, 1.0])
    });
    let dynamic = image::DynamicImage::ImageRgba32F(img);
    let dynamic = match format {
        image::ImageFormat::Png | image::ImageFormat::Jpeg => {
            image::DynamicImage::ImageRgb8(dynamic.to_rgb8())
        }
        image::ImageFormat::Hdr => image::DynamicImage::ImageRgb32F(dynamic.to_rgb32f()),
        _ => dynamic,
    };
    let mut bytes = Vec::new();
    dynamic
        .write_to(&mut std::io::Cursor::new(&mut bytes), format)
        .unwrap();
    bytes
}

/// Applies `(position, byte)` overwrites and an optional truncation.
fn mutate(mut bytes: Vec<u8>, edits: &[(usize, u8)], cut: Option<usize>) -> Vec<u8> {
    let len = bytes.len();
    for &(at, b) in edits {
        bytes[at % len] = b;
    }
    if let Some(cut) = cut {
        bytes.truncate(cut % (len + 1));
    }
    bytes
}

/// One line of OBJ-like text, biased towards the tricky parts (face indices).
fn obj_line() -> impl Strategy<Value = String> {
    let index = prop_oneof![
        -6i64..8,
        Just(i64::MAX),
        Just(i64::MIN),
        Just(i64::from(u32::MAX) + 1),
    ];
    let corner = (
        index.clone(),
        proptest::option::of(index.clone()),
        proptest::option::of(index),
    )
        .prop_map(|(v, t, n)| match (t, n) {
            (None, None) => format!("{v}"),
            (Some(t), None) => format!("{v}/{t}"),
            (None, Some(n)) => format!("{v}//{n}"),
            (Some(t), Some(n)) => format!("{v}/{t}/{n}"),
        });
    let float = prop_oneof![-2.0f32..2.0, Just(f32::NAN), Just(f32::INFINITY), Just(0.0)];
    prop_oneof![
        (float.clone(), float.clone(), float.clone())
            .prop_map(|(a, b, c)| format!("v {a} {b} {c}")),
        (float.clone(), float.clone()).prop_map(|(a, b)| format!("vt {a} {b}")),
        (float.clone(), float.clone(), float).prop_map(|(a, b, c)| format!("vn {a} {b} {c}")),
        vec(corner.clone(), 0..6).prop_map(|c| format!("f {}", c.join(" "))),
        vec(corner, 0..4).prop_map(|c| format!("l {}", c.join(" "))),
        Just("o object".to_owned()),
        Just("g".to_owned()),
        Just("usemtl x".to_owned()),
        Just("mtllib nothing.mtl".to_owned()),
        "[ -~]{0,12}",
    ]
}

proptest! {
    // 256 cases unless PROPTEST_CASES says otherwise (set it high for a longer local hunt).
    #![proptest_config(ProptestConfig { failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(bytes in vec(any::<u8>(), 0..600)) {
        all_loaders(&bytes);
    }

    #[test]
    fn random_bytes_behind_a_magic_never_panic(
        magic in prop::sample::select(vec![
            &b"glTF\x02\0\0\0"[..], b"glTF", b"{", b"\x89PNG\r\n\x1a\n", b"\xff\xd8\xff\xe0",
            b"#?RADIANCE\n", b"\x76\x2f\x31\x01", b"v 1 2 3\nf ",
        ]),
        rest in vec(any::<u8>(), 0..300),
    ) {
        let mut bytes = magic.to_vec();
        bytes.extend_from_slice(&rest);
        all_loaders(&bytes);
    }

    #[test]
    fn mutated_glb_never_panics(
        edits in vec((any::<usize>(), any::<u8>()), 1..6),
        cut in proptest::option::of(any::<usize>()),
    ) {
        let bytes = mutate(rich_glb(), &edits, cut);
        let _ = parse_gltf(&bytes, Path::new("m.glb"));
    }

    #[test]
    fn mutated_gltf_numbers_never_panic(
        edits in vec((any::<usize>(), prop::sample::select(b"0123456789-.e".to_vec())), 1..4),
    ) {
        // Overwriting with digits keeps the JSON mostly well-formed, so the mutation reaches
        // indices, offsets, counts and strides rather than the JSON parser.
        let bytes = mutate(rich_gltf_json(), &edits, None);
        let _ = parse_gltf(&bytes, Path::new("m.gltf"));
    }

    #[test]
    fn obj_like_text_never_panics(lines in vec(obj_line(), 0..24)) {
        let text = lines.join("\n");
        if let Ok(mesh) = parse_obj(text.as_bytes(), Path::new("m.obj")) {
            prop_assert!(mesh.validate().is_ok());
            prop_assert_eq!(mesh.normals.as_ref().map(Vec::len), Some(mesh.positions.len()));
        }
    }

    #[test]
    fn mutated_images_never_panic(
        format in prop::sample::select(vec![
            image::ImageFormat::Png, image::ImageFormat::Jpeg,
            image::ImageFormat::OpenExr, image::ImageFormat::Hdr,
        ]),
        edits in vec((any::<usize>(), any::<u8>()), 1..6),
        cut in proptest::option::of(any::<usize>()),
    ) {
        let bytes = mutate(encoded(format), &edits, cut);
        if let Ok(texture) = decode_image(&bytes, Path::new("m.img")) {
            prop_assert_eq!(
                texture.words.len(),
                texture.texel_count() * texture.format.words_per_texel()
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_files_never_panic(bytes in vec(any::<u8>(), 0..256)) {
        let dir = TempDir::new("fuzz");
        let path = dir.write("random.bin", &bytes);
        let _ = load_gltf(&path);
        let _ = load_obj(&path);
        let _ = load_image(&path);
    }
}
