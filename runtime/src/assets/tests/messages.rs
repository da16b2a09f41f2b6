//! Issue 21's asset messages and repairs: glTF `extras` of every JSON type, accessors without a
//! `bufferView` (zeros, with sparse substitutions), element counts called elements, a corrupt
//! PNG described in words (no Rust debug text), a binding too large for the device naming the
//! mesh or texture and its file, and NaN/infinite texels replaced by 0 with a warning that names
//! the file and the count.

use std::path::Path;

use image::{ImageBuffer, Rgb, Rgba};
use rtc_compiler::driver::{check_text, Options};
use rtc_compiler::link::registry::Registry;
use rtc_compiler::link::{link, LinkOptions};
use serde_json::json;

use super::gltf_builder::{base64, one_node, triangle, Builder};
use super::TempDir;
use crate::assets::model::parse_gltf;
use crate::assets::texture::decode_image;
use crate::assets::{load_image, AssetError, CountProblem, GltfItem};
use crate::gpu::BufferError;
use crate::scene::{Entities, EntityOptions, SceneError};

fn parse_doc(doc: &serde_json::Value) -> Result<crate::assets::ModelScene, AssetError> {
    parse_gltf(&serde_json::to_vec(doc).unwrap(), Path::new("test.gltf"))
}

#[test]
fn extras_of_every_json_type_are_accepted() {
    let (b, pos, idx) = triangle();
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let values = [
        json!(5),
        json!(-2.5),
        json!("a note"),
        json!([1, "two", null, { "three": 3 }]),
        json!(true),
        json!(null),
        json!({ "author": "x", "nested": { "k": [1, 2] } }),
    ];
    for extras in values {
        let mut doc = b.document(
            Some(&uri),
            one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx, "extras": extras.clone() }])),
        );
        doc["extras"] = extras.clone();
        doc["asset"]["extras"] = extras.clone();
        doc["nodes"][0]["extras"] = extras.clone();
        doc["meshes"][0]["extras"] = extras.clone();
        doc["accessors"][0]["extras"] = extras.clone();
        doc["buffers"][0]["extras"] = extras.clone();
        doc["bufferViews"][0]["extras"] = extras.clone();
        let scene = parse_doc(&doc).unwrap_or_else(|e| panic!("extras {extras}: {e}"));
        assert_eq!(scene.meshes.len(), 1, "extras {extras}");
        assert_eq!(scene.meshes[0].positions[1], [1.0, 0.0, 0.0]);
    }
}

#[test]
fn an_accessor_without_a_buffer_view_is_zeros() {
    // POSITION: three zeros, with sparse substitutions for vertices 1 and 2.
    let mut b = Builder::default();
    let indices = b.view(&[1u8, 0, 2, 0], None); // u16 1, 2
    let values: Vec<u8> = [[2.0f32, 0.0, 0.0], [0.0, 3.0, 0.0]]
        .iter()
        .flatten()
        .flat_map(|f| f.to_le_bytes())
        .collect();
    let values = b.view(&values, None);
    let pos = b.accessor(json!({
        "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [2,3,0],
        "sparse": { "count": 2, "indices": { "bufferView": indices, "componentType": 5123 },
                    "values": { "bufferView": values } },
    }));
    // TEXCOORD_0 without a view and without sparse: all zeros.
    let uv = b.accessor(json!({ "componentType": 5126, "count": 3, "type": "VEC2" }));
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        one_node(json!([{ "attributes": { "POSITION": pos, "TEXCOORD_0": uv } }])),
    );
    let scene = parse_doc(&doc).unwrap();
    let mesh = &scene.meshes[0];
    assert_eq!(
        mesh.positions,
        vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 3.0, 0.0]]
    );
    assert_eq!(mesh.uvs.as_deref(), Some(&[[0.0, 0.0]; 3][..]));
    assert_eq!(mesh.indices, vec![[0, 1, 2]]);
}

#[test]
fn element_counts_are_called_elements() {
    let (mut b, _, _) = triangle();
    let indices = b.view(&[0u8, 9], None);
    let values = b.view(&[0u8; 24], None);
    // sparse.count above count, then a sparse index past the end.
    for (sparse_count, index_type, problem_is) in [(5u64, 5121, "count"), (2, 5121, "index")] {
        let pos = b.accessor(json!({
            "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [0,0,0],
            "sparse": { "count": sparse_count, "indices": { "bufferView": indices, "componentType": index_type },
                        "values": { "bufferView": values } },
        }));
        let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
        let doc = b.document(
            Some(&uri),
            one_node(json!([{ "attributes": { "POSITION": pos } }])),
        );
        let err = parse_doc(&doc).unwrap_err();
        let message = err.to_string();
        match (&err, problem_is) {
            (
                AssetError::AccessorCount {
                    item,
                    problem: CountProblem::SparseCount { sparse, count },
                    ..
                },
                "count",
            ) => {
                assert_eq!((*item, *sparse, *count), (GltfItem::Accessor(pos), 5, 3));
                assert!(message.contains("5 elements"), "{message}");
            }
            (
                AssetError::AccessorCount {
                    problem: CountProblem::SparseIndex { index, count },
                    ..
                },
                "index",
            ) => {
                assert_eq!((*index, *count), (9, 3));
                assert!(message.contains("3 elements"), "{message}");
            }
            other => panic!("{problem_is}: {other:?}"),
        }
        assert!(!message.contains("bytes"), "{message}");
        assert!(message.starts_with("test.gltf: accessors["), "{message}");
    }
}

#[test]
fn a_corrupt_png_is_described_in_words() {
    let img: ImageBuffer<Rgb<u8>, _> =
        ImageBuffer::from_fn(16, 16, |x, y| Rgb([x as u8 * 9, y as u8 * 5, 7]));
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .unwrap();
    let idat = bytes.windows(4).position(|w| w == b"IDAT").unwrap();
    let label = Path::new("wall.png");
    // A damaged checksum, damaged compressed data, a damaged header and a truncation.
    let mut crc = bytes.clone();
    let last = crc.len() - 13; // inside IDAT's CRC (IEND is the last 12 bytes)
    crc[last] ^= 0xff;
    let mut deflate = bytes.clone();
    deflate[idat + 4] ^= 0xff;
    deflate[idat + 5] ^= 0xff;
    let mut header = bytes.clone();
    header[16 + 8] = 3; // bit depth 3 in IHDR
    let cases = [
        ("crc", crc),
        ("deflate", deflate),
        ("header", header),
        ("truncated", bytes[..bytes.len() / 2].to_vec()),
    ];
    for (what, bad) in cases {
        let err = decode_image(&bad, label).unwrap_err();
        let message = err.to_string();
        assert!(
            message.starts_with("wall.png: cannot decode the image: "),
            "{what}: {message}"
        );
        for debug in [
            "ChunkType",
            "{",
            "}",
            "Format(",
            "Some(",
            "BadZlib",
            "Inner",
        ] {
            assert!(
                !message.contains(debug),
                "{what}: debug text `{debug}` in: {message}"
            );
        }
        assert!(
            message.contains("PNG") || message.contains("truncated"),
            "{what}: {message}"
        );
        eprintln!("{what}: {message}");
    }
}

/// An EXR with NaN, +inf and -inf texels.
fn exr_with_nonfinite(dir: &TempDir) -> std::path::PathBuf {
    let img: ImageBuffer<Rgba<f32>, _> = ImageBuffer::from_fn(4, 2, |x, y| match (x, y) {
        (0, 0) => Rgba([f32::NAN, 0.5, 0.5, 1.0]),
        (1, 0) => Rgba([0.5, f32::INFINITY, 0.5, 1.0]),
        (2, 1) => Rgba([0.5, 0.5, f32::NEG_INFINITY, f32::NAN]),
        _ => Rgba([0.25, 0.5, 2.0, 1.0]),
    });
    let path = dir.path().join("sky.exr");
    image::DynamicImage::ImageRgba32F(img)
        .save_with_format(&path, image::ImageFormat::OpenExr)
        .unwrap();
    path
}

#[test]
fn nonfinite_texels_become_zero_and_are_counted() {
    let dir = TempDir::new("nan-texels");
    let path = exr_with_nonfinite(&dir);
    let tex = load_image(&path).unwrap();
    assert_eq!(tex.nonfinite_texels, 3);
    assert_eq!(tex.texel(0, 0), Some([0.0, 0.5, 0.5, 1.0]));
    assert_eq!(tex.texel(1, 0), Some([0.5, 0.0, 0.5, 1.0]));
    assert_eq!(tex.texel(2, 1), Some([0.5, 0.5, 0.0, 0.0]));
    assert_eq!(tex.texel(3, 1), Some([0.25, 0.5, 2.0, 1.0]));
    for y in 0..tex.height {
        for x in 0..tex.width {
            assert!(tex.texel(x, y).unwrap().iter().all(|c| c.is_finite()));
        }
    }
    // A clean image counts none.
    let clean: ImageBuffer<Rgba<f32>, _> =
        ImageBuffer::from_pixel(2, 2, Rgba([1.0, 2.0, 3.0, 1.0]));
    let clean_path = dir.path().join("clean.exr");
    image::DynamicImage::ImageRgba32F(clean)
        .save_with_format(&clean_path, image::ImageFormat::OpenExr)
        .unwrap();
    assert_eq!(load_image(&clean_path).unwrap().nonfinite_texels, 0);

    // Through a scene: a warning naming the file and the count.
    let text = "import \"std/cameras/pinhole.rt\";\nimport \"std/miss/skybox.rt\";\n\
                scene s {\n    camera Pinhole {}\n    background Skybox { image: load_image(\"sky.exr\") }\n}\n";
    let scene_file = dir.path().join("scene.rt");
    let checked = check_text(&scene_file.display().to_string(), text, &Options::default());
    assert!(!checked.has_errors(), "{:?}", checked.diagnostics);
    let program = checked.program.unwrap();
    let scene = program.select_scene(None).unwrap();
    let linked = link(
        &program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    )
    .unwrap();
    let entities = Entities::build(
        &program,
        &program.scenes[linked.scene],
        &linked,
        &EntityOptions::default(),
    )
    .unwrap();
    let warnings = entities.warnings();
    assert!(
        warnings.iter().any(|w| w.contains("sky.exr")
            && w.contains("3 of 8 texels")
            && w.contains("replaced by 0")),
        "{warnings:?}"
    );
}

#[test]
fn a_binding_too_large_names_the_mesh_and_its_file() {
    let dir = TempDir::new("too-large");
    std::fs::write(
        dir.path().join("big.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n",
    )
    .unwrap();
    let (b, pos, idx) = triangle();
    let glb = b.glb(json!({
        "meshes": [{ "name": "Wheel", "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx }] }],
        "nodes": [{ "mesh": 0 }],
    }));
    std::fs::write(dir.path().join("car.glb"), glb).unwrap();
    let text = "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/lambert.rt\";\n\
                scene s {\n    camera Pinhole {}\n    object a { geometry: load_mesh(\"big.obj\"), material: Lambert {} }\n    model \"car.glb\" {}\n}\n";
    let scene_file = dir.path().join("scene.rt");
    let checked = check_text(&scene_file.display().to_string(), text, &Options::default());
    assert!(!checked.has_errors(), "{:?}", checked.diagnostics);
    let program = checked.program.unwrap();
    let scene = program.select_scene(None).unwrap();
    let linked = link(
        &program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    )
    .unwrap();
    let entities = Entities::build(
        &program,
        &program.scenes[linked.scene],
        &linked,
        &EntityOptions::default(),
    )
    .unwrap();
    let too_large = || BufferError::TooLarge {
        binding: 3,
        name: "triangles".to_owned(),
        size: 1 << 30,
        limit: 1 << 27,
        limit_name: "max_storage_buffer_binding_size",
    };
    let err =
        crate::scene::upload_for_tests::name_the_largest_part(too_large(), "triangles", &entities);
    let message = err.to_string();
    assert!(matches!(err, SceneError::BindingTooLarge { .. }), "{err:?}");
    assert!(message.contains("big.obj"), "{message}");
    assert!(message.contains("2 triangles"), "{message}");
    assert!(
        message.contains("max_storage_buffer_binding_size"),
        "{message}"
    );
    // The glTF mesh is named by file and mesh when it is the largest (its BVH records here).
    let mesh_names: Vec<&str> = entities
        .meshes()
        .iter()
        .map(|m| m.source.as_str())
        .collect();
    assert!(
        mesh_names
            .iter()
            .any(|m| m.contains("car.glb#meshes[0].primitives[0] (`Wheel`)")),
        "{mesh_names:?}"
    );
    // Other bindings and other errors pass through unchanged.
    let err =
        crate::scene::upload_for_tests::name_the_largest_part(too_large(), "params", &entities);
    assert!(matches!(err, SceneError::Buffer(_)), "{err:?}");
}
