//! glTF import: files built here (`.gltf` + `.bin`, `.glb`, data URIs), what is imported from
//! them, and every broken variant as a clear error or warning.

use std::f32::consts::FRAC_PI_2;
use std::path::Path;

use glam::{Mat4, Quat, Vec3};
use serde_json::json;

use super::gltf_builder::{
    base64, glb_bytes, one_node, small_png, triangle, Builder, SMALL_PNG_WORDS,
};
use super::{assert_close3, TempDir};
use crate::assets::model::parse_gltf;
use crate::assets::{
    load_gltf, AlphaMode, AssetError, CountProblem, GlbProblem, GltfItem, LightKind, ModelScene,
    Projection, Sampler, TextureFormat, UriProblem, Wrap,
};

fn parse(bytes: &[u8]) -> Result<ModelScene, AssetError> {
    parse_gltf(bytes, Path::new("test.gltf"))
}

fn parse_doc(doc: &serde_json::Value) -> Result<ModelScene, AssetError> {
    parse(&serde_json::to_vec(doc).unwrap())
}

/// Checks the triangle of [`triangle`] imported as the only mesh and instance.
fn check_triangle(scene: &ModelScene) {
    assert_eq!(scene.meshes.len(), 1);
    let mesh = &scene.meshes[0];
    assert_eq!(
        mesh.positions,
        vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    );
    assert_eq!(mesh.indices, vec![[0, 1, 2]]);
    for n in mesh.normals.as_ref().unwrap() {
        assert_close3(*n, [0.0, 0.0, 1.0], 1e-6);
    }
    assert_eq!(scene.instances.len(), 1);
    assert_eq!(scene.instances[0].mesh, 0);
    assert_eq!(scene.instances[0].transform, Mat4::IDENTITY);
    // No material given: glTF's default material.
    assert_eq!(scene.materials.len(), 1);
    assert_eq!(scene.materials[0].name.as_deref(), Some("default"));
    assert_eq!(scene.materials[0].base_color, [1.0; 4]);
    let b = scene.bounds();
    assert_eq!((b.min, b.max), (Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0)));
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
}

#[test]
fn triangle_gltf_with_external_bin() {
    let dir = TempDir::new("gltf");
    let (b, pos, idx) = triangle();
    let path = b.write_gltf(
        &dir,
        "tri",
        one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
    );
    check_triangle(&load_gltf(&path).unwrap());
}

#[test]
fn triangle_glb() {
    let dir = TempDir::new("gltf");
    let (b, pos, idx) = triangle();
    let glb = b.glb(one_node(
        json!([{ "attributes": { "POSITION": pos }, "indices": idx }]),
    ));
    let path = dir.write("tri.glb", &glb);
    check_triangle(&load_gltf(&path).unwrap());
}

#[test]
fn triangle_with_data_uri_buffer_and_no_indices() {
    let (b, pos, _) = triangle();
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        one_node(json!([{ "attributes": { "POSITION": pos } }])),
    );
    check_triangle(&parse_doc(&doc).unwrap());
}

#[test]
fn instanced_mesh_in_a_hierarchy() {
    let (b, pos, idx) = triangle();
    let rotation = Quat::from_rotation_y(FRAC_PI_2);
    let matrix = Mat4::from_translation(Vec3::new(0.0, 0.0, 7.0));
    let doc = b.document(
        Some("unused.bin"),
        json!({
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx }] }],
            "nodes": [
                { "name": "parent", "translation": [10.0, 0.0, 0.0], "children": [1, 2, 3] },
                { "mesh": 0, "translation": [0.0, 1.0, 0.0] },
                { "mesh": 0, "scale": [2.0, 2.0, 2.0], "rotation": rotation.to_array() },
                { "mesh": 0, "matrix": matrix.to_cols_array() },
                { "mesh": 0, "name": "not in the scene" },
            ],
            "scenes": [{ "nodes": [0] }],
        }),
    );
    // The data is given inline instead: swap the URI for a data URI.
    let mut doc = doc;
    doc["buffers"][0]["uri"] = json!(format!(
        "data:application/octet-stream;base64,{}",
        base64(&b.bin)
    ));
    let scene = parse_doc(&doc).unwrap();

    assert_eq!(
        scene.meshes.len(),
        1,
        "one MeshData shared by all instances"
    );
    assert_eq!(scene.instances.len(), 3);
    assert!(scene.instances.iter().all(|i| i.mesh == 0));
    assert_eq!(
        scene.instances.iter().map(|i| i.node).collect::<Vec<_>>(),
        [1, 2, 3]
    );
    let x = Vec3::X;
    let world = |i: usize| scene.instances[i].transform.transform_point3(x);
    assert_close3(world(0), [11.0, 1.0, 0.0], 1e-6);
    // Rotation by 90° about y takes +x to -z, after scaling by 2.
    assert_close3(world(1), [10.0, 0.0, -2.0], 1e-5);
    assert_close3(world(2), [11.0, 0.0, 7.0], 1e-6);
    let b = scene.bounds();
    assert_close3(b.min, [10.0, 0.0, -2.0], 1e-5);
    assert_close3(b.max, [11.0, 2.0, 7.0], 1e-5);
}

#[test]
fn cameras_and_punctual_lights() {
    let doc = json!({
        "asset": { "version": "2.0" },
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": [
            { "type": "point", "name": "bulb", "color": [1.0, 0.5, 0.25], "intensity": 20.0, "range": 10.0 },
            { "type": "spot", "spot": { "innerConeAngle": 0.2, "outerConeAngle": 0.5 } },
            { "type": "directional", "intensity": 3.0 },
        ] } },
        "cameras": [
            { "type": "perspective", "name": "main", "perspective": { "yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1 } },
            { "type": "orthographic", "orthographic": { "xmag": 2.0, "ymag": 1.0, "znear": 0.01, "zfar": 100.0 } },
        ],
        "nodes": [
            { "camera": 0, "translation": [0.0, 1.0, 5.0] },
            { "children": [2], "translation": [0.0, 3.0, 0.0] },
            { "extensions": { "KHR_lights_punctual": { "light": 0 } }, "translation": [1.0, 0.0, 0.0] },
            // Rotated -90° about x: its -z axis points down (-y).
            { "extensions": { "KHR_lights_punctual": { "light": 1 } },
              "rotation": Quat::from_rotation_x(-FRAC_PI_2).to_array(), "translation": [0.0, 4.0, 0.0] },
            { "extensions": { "KHR_lights_punctual": { "light": 2 } } },
            { "camera": 1 },
        ],
        "scenes": [{ "nodes": [0, 1, 3, 4, 5] }],
        "scene": 0,
    });
    let scene = parse_doc(&doc).unwrap();
    assert!(scene.meshes.is_empty() && scene.instances.is_empty());
    assert!(scene.bounds().is_empty());

    assert_eq!(scene.cameras.len(), 2);
    let main = scene.default_camera().unwrap();
    assert_eq!(main.name.as_deref(), Some("main"));
    assert_eq!(
        main.projection,
        Projection::Perspective {
            yfov: 0.8,
            aspect: Some(1.5),
            znear: 0.1,
            zfar: None
        }
    );
    assert_close3(main.position(), [0.0, 1.0, 5.0], 1e-6);
    assert_close3(main.forward(), [0.0, 0.0, -1.0], 1e-6);
    assert_close3(main.up(), [0.0, 1.0, 0.0], 1e-6);
    assert_eq!(
        scene.cameras[1].projection,
        Projection::Orthographic {
            xmag: 2.0,
            ymag: 1.0,
            znear: 0.01,
            zfar: 100.0
        }
    );

    assert_eq!(scene.lights.len(), 3);
    let point = &scene.lights[0];
    assert_eq!(point.kind, LightKind::Point);
    assert_eq!(point.name.as_deref(), Some("bulb"));
    assert_eq!(
        (point.color, point.intensity, point.range),
        ([1.0, 0.5, 0.25], 20.0, Some(10.0))
    );
    assert_close3(point.position, [1.0, 3.0, 0.0], 1e-6);
    let spot = &scene.lights[1];
    assert_eq!(
        spot.kind,
        LightKind::Spot {
            inner_cone_angle: 0.2,
            outer_cone_angle: 0.5
        }
    );
    assert_close3(spot.position, [0.0, 4.0, 0.0], 1e-6);
    assert_close3(spot.direction, [0.0, -1.0, 0.0], 1e-6);
    assert_eq!(
        (spot.color, spot.intensity, spot.range),
        ([1.0; 3], 1.0, None)
    );
    let sun = &scene.lights[2];
    assert_eq!(sun.kind, LightKind::Directional);
    assert_close3(sun.direction, [0.0, 0.0, -1.0], 1e-6);
}

#[test]
fn material_with_external_base_color_texture() {
    let dir = TempDir::new("gltf");
    dir.write("albedo map.png", small_png());
    let (b, pos, idx) = triangle();
    let mut b = b;
    let uv = b.vec2(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    let color = b.vec3(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    let path = b.write_gltf(
        &dir,
        "textured",
        json!({
            "extensionsUsed": ["KHR_materials_emissive_strength"],
            "meshes": [{ "primitives": [
                { "attributes": { "POSITION": pos, "TEXCOORD_0": uv, "COLOR_0": color }, "indices": idx, "material": 0 },
                { "attributes": { "POSITION": pos }, "indices": idx, "material": 0 },
            ] }],
            "materials": [{
                "name": "painted",
                "pbrMetallicRoughness": {
                    "baseColorFactor": [0.5, 0.6, 0.7, 0.8],
                    "baseColorTexture": { "index": 0 },
                    "metallicFactor": 0.25,
                    "roughnessFactor": 0.75,
                },
                "normalTexture": { "index": 0 },
                "emissiveFactor": [1.0, 0.5, 0.0],
                "extensions": { "KHR_materials_emissive_strength": { "emissiveStrength": 4.0 } },
                "alphaMode": "MASK",
                "alphaCutoff": 0.3,
                "doubleSided": true,
            }],
            "textures": [{ "source": 0, "sampler": 0 }],
            "samplers": [{}],
            "images": [{ "uri": "albedo%20map.png" }],
            "nodes": [{ "mesh": 0 }],
            "scenes": [{ "nodes": [0] }],
        }),
    );
    let scene = load_gltf(&path).unwrap();
    assert_eq!(scene.meshes.len(), 2);
    assert_eq!(
        scene.meshes[0].uvs.as_deref(),
        Some(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]][..])
    );
    assert_eq!(
        scene.materials.len(),
        1,
        "both primitives share the material"
    );
    assert!(scene.instances.iter().all(|i| i.material == 0));
    let m = &scene.materials[0];
    assert_eq!(m.name.as_deref(), Some("painted"));
    assert_eq!(m.base_color, [0.5, 0.6, 0.7, 0.8]);
    assert_eq!(m.base_color_texture, Some(0));
    assert_eq!((m.metallic, m.roughness), (0.25, 0.75));
    assert_eq!(m.emissive, [4.0, 2.0, 0.0]);
    assert_eq!(
        (m.alpha_mode, m.alpha_cutoff, m.double_sided),
        (AlphaMode::Mask, 0.3, true)
    );
    assert_eq!(
        scene.textures.len(),
        2,
        "base colour (sRGB), normal (linear)"
    );
    assert_eq!((scene.textures[0].width, scene.textures[0].height), (2, 1));
    assert_eq!(scene.textures[0].words, SMALL_PNG_WORDS);
    // The normal texture and the vertex colours are imported now: no warning names them.
    assert!(
        !scene
            .warnings
            .iter()
            .any(|w| w.contains("not imported") || w.contains("COLOR_0")),
        "{:?}",
        scene.warnings
    );
    assert_eq!(m.normal_texture, Some(1), "the image again, as linear data");
    assert!(m.vertex_colors && m.is_detailed());
    let extras = scene.meshes[0]
        .extras
        .as_ref()
        .expect("colours and tangents");
    assert_eq!(
        extras.colors.as_deref(),
        Some(
            &[
                [1.0, 0.0, 0.0, 1.0],
                [0.0, 1.0, 0.0, 1.0],
                [0.0, 0.0, 1.0, 1.0]
            ][..]
        )
    );
    // MikkTSpace from TEXCOORD_0 (u along +x, v along +y, so with v flipped the bitangent is
    // -y: w = -1).
    let tangents = extras.tangents.as_ref().expect("generated tangents");
    for t in tangents.iter().flatten() {
        assert!((t[0] - 1.0).abs() < 1e-5 && t[1].abs() < 1e-5, "{t:?}");
        assert_eq!(t[3], -1.0, "{t:?}");
    }
    // The primitive without uvs gets no tangents to generate from, said in a warning.
    assert!(
        scene
            .warnings
            .iter()
            .any(|w| w.contains("meshes[0].primitives[1]: no TANGENT and no TEXCOORD_0")),
        "{:?}",
        scene.warnings
    );
}

#[test]
fn extra_attributes_of_the_wrong_type_are_dropped_with_a_warning() {
    let dir = TempDir::new("gltf");
    let (b, pos, idx) = triangle();
    let mut b = b;
    let uv = b.vec2(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    // COLOR_0 as VEC2, TANGENT as VEC3, TEXCOORD_1 as VEC3: each ignored with a warning.
    let bad2 = b.vec2(&[[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]);
    let bad3 = b.vec3(&[[1.0, 0.0, 0.0]; 3]);
    let path = b.write_gltf(
        &dir,
        "bad",
        json!({
            "meshes": [{ "primitives": [
                { "attributes": { "POSITION": pos, "TEXCOORD_0": uv, "COLOR_0": bad2,
                                  "TANGENT": bad3, "TEXCOORD_1": bad3, "COLOR_1": bad3 },
                  "indices": idx, "material": 0 },
            ] }],
            "materials": [{
                "pbrMetallicRoughness": { "baseColorTexture": { "index": 0, "texCoord": 1 } },
                "normalTexture": { "index": 0 },
                "occlusionTexture": { "index": 0, "texCoord": 2 },
            }],
            "textures": [{ "source": 0 }],
            "images": [{ "uri": "t.png" }],
            "nodes": [{ "mesh": 0 }],
            "scenes": [{ "nodes": [0] }],
        }),
    );
    dir.write("t.png", small_png());
    let scene = load_gltf(&path).unwrap();
    let warnings = scene.warnings.join("\n");
    for want in [
        "meshes[0].primitives[0]: its COLOR_0 is ignored",
        "meshes[0].primitives[0]: its TANGENT is ignored",
        "meshes[0].primitives[0]: its TEXCOORD_1 is ignored",
        "meshes[0].primitives[0]: its material samples a texture with TEXCOORD_1, which the \
         primitive lacks",
        "meshes[0].primitives[0]: COLOR_1 not imported",
        "materials[0]: its occlusion texture uses TEXCOORD_2, sampled with TEXCOORD_0",
    ] {
        assert!(warnings.contains(want), "{want:?} not in:\n{warnings}");
    }
    let extras = scene.meshes[0].extras.as_ref().expect("tangents generated");
    assert!(extras.colors.is_none() && extras.uvs1.is_none());
    assert!(extras.tangents.is_some(), "MikkTSpace from TEXCOORD_0");
    assert_eq!(
        scene.materials[0].uv_sets, 1,
        "the base colour texture on set 1"
    );
}

#[test]
fn every_core_texture_with_its_sampler_and_what_is_not_imported_named() {
    let dir = TempDir::new("gltf");
    dir.write("a.png", small_png());
    let (mut b, pos, idx) = triangle();
    let uv = b.vec2(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    let path = b.write_gltf(
        &dir,
        "maps",
        json!({
            "extensionsUsed": ["KHR_texture_transform"],
            "meshes": [{ "primitives": [
                { "attributes": { "POSITION": pos, "TEXCOORD_0": uv }, "indices": idx, "material": 0 },
            ] }],
            "materials": [{
                "name": "helmet",
                "pbrMetallicRoughness": {
                    "baseColorTexture": { "index": 0 },
                    "metallicRoughnessTexture": { "index": 1, "texCoord": 1 },
                },
                "normalTexture": { "index": 1, "scale": 0.5 },
                "occlusionTexture": {
                    "index": 1, "strength": 0.25,
                    "extensions": { "KHR_texture_transform": { "offset": [1.0, 0.0], "texCoord": 1 } },
                },
                "emissiveTexture": {
                    "index": 0,
                    "extensions": { "KHR_texture_transform": {
                        "offset": [0.5, 0.25], "rotation": FRAC_PI_2, "scale": [2.0, 3.0],
                    } },
                },
                "emissiveFactor": [1.0, 1.0, 1.0],
            }],
            "textures": [{ "source": 0 }, { "source": 0, "sampler": 0 }],
            "samplers": [{ "wrapS": 33071, "wrapT": 33648, "magFilter": 9728 }],
            "images": [{ "uri": "a.png" }],
            "nodes": [{ "mesh": 0 }],
            "scenes": [{ "nodes": [0] }],
        }),
    );
    let scene = load_gltf(&path).unwrap();
    let m = &scene.materials[0];
    // Base colour and emissive: the image as sRGB, default sampler (one texture for both).
    assert_eq!(m.base_color_texture, Some(0));
    assert_eq!(m.emissive_texture, Some(0));
    assert_eq!(m.emissive, [1.0; 3]);
    // Metallic-roughness and occlusion: the same image as linear data through sampler 0.
    assert_eq!(m.metallic_roughness_texture, Some(1));
    assert_eq!(m.occlusion_texture, Some(1));
    assert_eq!(m.occlusion_strength, 0.25);
    assert_eq!(scene.textures.len(), 2);
    assert_eq!(scene.textures[0].format, TextureFormat::Rgba8Srgb);
    assert_eq!(scene.textures[0].sampler, Sampler::default());
    assert_eq!(scene.textures[1].format, TextureFormat::Rgba8Unorm);
    assert_eq!(scene.textures[1].words, SMALL_PNG_WORDS);
    assert_eq!(
        scene.textures[1].sampler,
        Sampler {
            wrap_u: Wrap::ClampToEdge,
            wrap_v: Wrap::MirroredRepeat,
            nearest: true
        }
    );
    assert_eq!(
        scene.texture_labels,
        ["images[0]", "images[0]~clamp,mirror,nearest~linear"]
    );
    let warnings = scene.warnings.join("\n");
    // The normal texture and uv set 1 are imported: no warning says otherwise; the file's
    // primitive lacks TEXCOORD_1, which is said.
    for gone in ["normal texture", "sampled with TEXCOORD_0"] {
        assert!(!warnings.contains(gone), "{gone:?} in:\n{warnings}");
    }
    assert!(
        warnings.contains("samples a texture with TEXCOORD_1, which the primitive lacks"),
        "{warnings}"
    );
    assert_eq!(
        m.uv_sets, 0b1010,
        "metallic-roughness and occlusion on set 1"
    );
    assert!(!warnings.contains("KHR_texture_transform"), "{warnings}");
    // KHR_texture_transform: u' = cos·sx·u − sin·sy·v + ox, v' = sin·sx·u + cos·sy·v + oy; at a
    // quarter turn with scale (2, 3), offset (0.5, 0.25): u' = −3v + 0.5, v' = 2u + 0.25.
    let [r0, r1] = m.uv_transforms[2];
    let close = |a: [f32; 3], b: [f32; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6);
    assert!(
        close(r0, [0.0, -3.0, 0.5]) && close(r1, [2.0, 0.0, 0.25]),
        "{r0:?} {r1:?}"
    );
    assert_eq!(m.uv_transforms[3], [[1.0, 0.0, 1.0], [0.0, 1.0, 0.0]]);
    assert_eq!(m.uv_transforms[0], [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    assert!(!warnings.contains("only base colour"), "{warnings}");
}

#[test]
fn glb_with_embedded_image_u8_uvs_and_sparse_positions() {
    let (mut b, _, idx) = triangle();
    // Positions all zero except through a sparse substitution; no bufferView for the base.
    let sparse_indices = b.view(&[1u8, 2], None);
    let sparse_values = b.view(
        &[[1.0f32, 0.0, 0.0], [0.0, 1.0, 0.0]]
            .iter()
            .flatten()
            .flat_map(|c| c.to_le_bytes())
            .collect::<Vec<u8>>(),
        None,
    );
    let pos = b.accessor(json!({
        "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0],
        "sparse": { "count": 2,
            "indices": { "bufferView": sparse_indices, "componentType": 5121 },
            "values": { "bufferView": sparse_values } },
    }));
    // Normalised u8 uvs, interleaved with padding: stride 4, two bytes used.
    let uv_view = b.view(&[0, 0, 9, 9, 255, 0, 9, 9, 0, 255, 9, 9], Some(4));
    let uv = b.accessor(json!({
        "bufferView": uv_view, "componentType": 5121, "normalized": true, "count": 3, "type": "VEC2",
    }));
    let image_view = b.view(&small_png(), None);
    let glb = b.glb(json!({
        "meshes": [{ "primitives": [
            { "attributes": { "POSITION": pos, "TEXCOORD_0": uv }, "indices": idx, "material": 0 },
        ] }],
        "materials": [{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }],
        "textures": [{ "source": 0 }],
        "images": [{ "bufferView": image_view, "mimeType": "image/png" }],
        "nodes": [{ "mesh": 0 }],
        "scenes": [{ "nodes": [0] }],
    }));
    let scene = parse_gltf(&glb, Path::new("test.glb")).unwrap();
    let mesh = &scene.meshes[0];
    assert_eq!(
        mesh.positions,
        vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    );
    assert_eq!(
        mesh.uvs.as_deref(),
        Some(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]][..])
    );
    assert_eq!(scene.textures[0].words, SMALL_PNG_WORDS);
    assert_eq!(scene.materials[0].base_color_texture, Some(0));
    assert_eq!(scene.materials[0].metallic, 1.0, "glTF defaults");
}

#[test]
fn without_scenes_every_parentless_node_is_shown() {
    let (b, pos, idx) = triangle();
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        json!({
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx }] }],
            "nodes": [{ "mesh": 0, "children": [1] }, { "mesh": 0 }, { "mesh": 0 }],
        }),
    );
    let scene = parse_doc(&doc).unwrap();
    assert_eq!(
        scene.instances.iter().map(|i| i.node).collect::<Vec<_>>(),
        [0, 1, 2]
    );
    assert!(scene.warnings.iter().any(|w| w.contains("no scene")));
}

#[test]
fn node_cycles_are_reported_not_followed() {
    let doc = json!({
        "asset": { "version": "2.0" },
        "nodes": [{ "children": [1] }, { "children": [0] }],
        "scenes": [{ "nodes": [0] }],
    });
    let scene = parse_doc(&doc).unwrap();
    assert!(
        scene
            .warnings
            .iter()
            .any(|w| w.contains("nodes[0] is reached more than once")),
        "{:?}",
        scene.warnings
    );
}

#[test]
fn non_triangle_primitives_are_skipped_with_a_warning() {
    let (b, pos, idx) = triangle();
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        one_node(json!([
            { "attributes": { "POSITION": pos }, "mode": 1 },
            { "attributes": { "POSITION": pos }, "indices": idx },
            { "attributes": { "POSITION": pos }, "mode": 5 },
        ])),
    );
    let scene = parse_doc(&doc).unwrap();
    assert_eq!(scene.meshes.len(), 1);
    assert_eq!(scene.instances.len(), 1);
    assert_eq!(scene.warnings.len(), 2, "{:?}", scene.warnings);
    assert!(scene.warnings[0].contains("meshes[0].primitives[0]: mode Lines is not supported"));
    assert!(scene.warnings[1].contains("meshes[0].primitives[2]: mode TriangleStrip"));
}

// ---- broken files ----

fn valid_glb() -> Vec<u8> {
    let (b, pos, idx) = triangle();
    b.glb(one_node(
        json!([{ "attributes": { "POSITION": pos }, "indices": idx }]),
    ))
}

#[test]
fn truncated_glb_is_an_error_at_every_length() {
    let glb = valid_glb();
    for cut in 0..glb.len() {
        let result = parse_gltf(&glb[..cut], Path::new("t.glb"));
        assert!(result.is_err(), "cut at {cut} of {} loaded", glb.len());
    }
    match parse_gltf(&glb[..glb.len() - 10], Path::new("t.glb")) {
        Err(AssetError::Glb {
            problem: GlbProblem::Truncated { declared, actual },
            ..
        }) => {
            assert_eq!(
                (declared, actual),
                (glb.len() as u64, glb.len() as u64 - 10)
            );
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        parse_gltf(&glb[..7], Path::new("t.glb")),
        Err(AssetError::Glb {
            problem: GlbProblem::NoHeader(7),
            ..
        })
    ));
    let message = parse_gltf(&glb[..glb.len() - 10], Path::new("t.glb"))
        .unwrap_err()
        .to_string();
    assert!(message.starts_with("t.glb: bad .glb file: "), "{message}");
}

#[test]
fn glb_with_bad_version_or_chunks() {
    let mut glb = valid_glb();
    glb[4] = 1;
    assert!(matches!(
        parse(&glb),
        Err(AssetError::Glb {
            problem: GlbProblem::Version(1),
            ..
        })
    ));
    let mut glb = valid_glb();
    glb[16..20].copy_from_slice(b"BIN\0");
    assert!(matches!(
        parse(&glb),
        Err(AssetError::Glb {
            problem: GlbProblem::NoJsonChunk,
            ..
        })
    ));
    let mut glb = valid_glb();
    glb[12..16].copy_from_slice(&u32::MAX.to_le_bytes());
    assert!(matches!(
        parse(&glb),
        Err(AssetError::Glb {
            problem: GlbProblem::ChunkTooLong { index: 0, .. },
            ..
        })
    ));
}

#[test]
fn bad_json_reports_line_and_column() {
    let err = parse(b"{\n  \"asset\": { \"version\": \"2.0\" },\n  \"nodes\": [ }\n").unwrap_err();
    assert!(matches!(err, AssetError::BadJson { .. }), "{err:?}");
    assert!(err.to_string().starts_with("test.gltf:3:"), "{err}");
    // Well-formed JSON of the wrong shape is bad glTF JSON too.
    let err = parse(b"{ \"asset\": { \"version\": 2 } }").unwrap_err();
    assert!(matches!(err, AssetError::BadJson { .. }), "{err:?}");
    // Not JSON at all.
    assert!(matches!(
        parse(b"v 0 0 0\n"),
        Err(AssetError::UnsupportedFormat { .. })
    ));
    assert!(matches!(
        parse(b""),
        Err(AssetError::UnsupportedFormat { .. })
    ));
}

#[test]
fn missing_bin_names_the_file() {
    let dir = TempDir::new("gltf");
    let (b, pos, idx) = triangle();
    let path = b.write_gltf(
        &dir,
        "lost",
        one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
    );
    std::fs::remove_file(dir.path().join("lost.bin")).unwrap();
    match load_gltf(&path) {
        Err(ref err @ AssetError::MissingFile { ref file, item, .. }) => {
            assert_eq!(file, &dir.path().join("lost.bin"));
            assert_eq!(item, GltfItem::Buffer(0));
            let message = err.to_string();
            assert!(
                message.contains("buffers[0] refers to `") && message.contains("lost.bin"),
                "{message}"
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn missing_texture_image_names_the_file() {
    let dir = TempDir::new("gltf");
    let (b, pos, idx) = triangle();
    let path = b.write_gltf(
        &dir,
        "untextured",
        json!({
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx, "material": 0 }] }],
            "materials": [{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }],
            "textures": [{ "source": 0 }],
            "images": [{ "uri": "gone.png" }],
            "nodes": [{ "mesh": 0 }],
            "scenes": [{ "nodes": [0] }],
        }),
    );
    match load_gltf(&path) {
        Err(AssetError::MissingFile { file, item, .. }) => {
            assert_eq!(file, dir.path().join("gone.png"));
            assert_eq!(
                item,
                GltfItem::BaseColorImage {
                    material: 0,
                    image: 0
                }
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn accessor_reference_out_of_range_is_invalid_gltf() {
    let (b, pos, _) = triangle();
    for primitive in [
        json!({ "attributes": { "POSITION": pos }, "indices": 99 }),
        json!({ "attributes": { "POSITION": 99 } }),
        json!({ "attributes": { "POSITION": pos, "NORMAL": 42 } }),
    ] {
        let doc = b.document(Some("x.bin"), one_node(json!([primitive])));
        match parse_doc(&doc) {
            Err(AssetError::InvalidGltf { problems, .. }) => {
                assert!(
                    problems
                        .iter()
                        .any(|(at, _)| at.starts_with("meshes[0].primitives[0]")),
                    "{problems:?}"
                );
            }
            other => panic!("{primitive}: {other:?}"),
        }
    }
}

#[test]
fn accessor_data_out_of_range_is_an_error() {
    let (mut b, _, idx) = triangle();
    let view = b.view(&[0u8; 24], None); // two VEC3s
    let pos = b.accessor(json!({
        "bufferView": view, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [0,0,0],
    }));
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
    );
    match parse_doc(&doc) {
        Err(AssetError::AccessorOutOfRange {
            item,
            needed,
            available,
            ..
        }) => {
            assert_eq!((item, needed, available), (GltfItem::Accessor(pos), 36, 24));
        }
        other => panic!("{other:?}"),
    }
    // A view past the end of its buffer.
    let mut doc = doc;
    doc["bufferViews"][view]["byteLength"] = json!(4000);
    assert!(matches!(
        parse_doc(&doc),
        Err(AssetError::AccessorOutOfRange {
            item: GltfItem::BufferView(_),
            ..
        })
    ));
}

#[test]
fn index_out_of_range_is_an_error() {
    let mut b = Builder::default();
    let pos = b.vec3(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);
    let idx = b.indices_u16(&[0, 1, 5]);
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
    );
    match parse_doc(&doc) {
        Err(err @ AssetError::IndexOutOfRange { .. }) => {
            assert_eq!(
                err.to_string(),
                "test.gltf: meshes[0].primitives[0]: index 5 is out of range (3 vertices)"
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn wrong_accessor_types_are_errors() {
    let (mut b, _, idx) = triangle();
    let flat = b.view(&[0u8; 36], None);
    let vec2 = b.accessor(json!({
        "bufferView": flat, "componentType": 5126, "count": 3, "type": "VEC2", "min": [0,0,0], "max": [0,0,0],
    }));
    let strided = b.view(&[0u8; 36], Some(4));
    let narrow = b.accessor(json!({
        "bufferView": strided, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [0,0,0],
    }));
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    for pos in [vec2, narrow] {
        let doc = b.document(
            Some(&uri),
            one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
        );
        match parse_doc(&doc) {
            Err(AssetError::AccessorFormat {
                usage: "POSITION",
                item,
                ..
            }) => {
                assert_eq!(item, GltfItem::Accessor(pos));
            }
            other => panic!("{other:?}"),
        }
    }
}

#[test]
fn buffer_problems_are_errors() {
    let (b, pos, idx) = triangle();
    let prims = one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }]));
    type Check = fn(&AssetError) -> bool;
    let cases: [(String, Check); 4] = [
        ("data:application/octet-stream;base64,@@@@".into(), |e| {
            matches!(
                e,
                AssetError::Uri {
                    problem: UriProblem::BadBase64,
                    ..
                }
            )
        }),
        ("https://example.com/x.bin".into(), |e| {
            matches!(
                e,
                AssetError::Uri {
                    problem: UriProblem::UnsupportedScheme,
                    ..
                }
            )
        }),
        ("x%zz.bin".into(), |e| {
            matches!(
                e,
                AssetError::Uri {
                    problem: UriProblem::BadPercentEncoding,
                    ..
                }
            )
        }),
        // Shorter than byteLength.
        (
            format!(
                "data:application/octet-stream;base64,{}",
                base64(&b.bin[..4])
            ),
            |e| {
                matches!(
                    e,
                    AssetError::BufferTooShort {
                        declared: 12..,
                        actual: 4,
                        ..
                    }
                )
            },
        ),
    ];
    for (uri, check) in cases {
        let err = parse_doc(&b.document(Some(&uri), prims.clone())).unwrap_err();
        assert!(check(&err), "{uri}: {err:?}");
    }
    // A .gltf buffer without a URI has nowhere to take its bytes from.
    let err = parse_doc(&b.document(None, prims)).unwrap_err();
    assert!(
        matches!(
            err,
            AssetError::Uri {
                problem: UriProblem::NoData,
                ..
            }
        ),
        "{err:?}"
    );
}

#[test]
fn unsupported_required_extension_is_invalid() {
    let doc = json!({
        "asset": { "version": "2.0" },
        "extensionsUsed": ["KHR_draco_mesh_compression"],
        "extensionsRequired": ["KHR_draco_mesh_compression"],
    });
    let err = parse_doc(&doc).unwrap_err();
    assert!(matches!(err, AssetError::InvalidGltf { .. }), "{err:?}");
    assert!(err.to_string().contains("extensionsRequired[0]"), "{err}");
    // Used but not required: a warning.
    let doc = json!({
        "asset": { "version": "2.0" },
        "extensionsUsed": ["KHR_materials_sheen", "KHR_lights_punctual", "KHR_texture_transform"],
    });
    let scene = parse_doc(&doc).unwrap();
    assert_eq!(
        scene.warnings,
        ["extension(s) KHR_materials_sheen ignored (the file does not require them)"]
    );
}

#[test]
fn empty_scene_and_unreadable_file() {
    let scene = parse_doc(&json!({ "asset": { "version": "2.0" } })).unwrap();
    assert!(scene.meshes.is_empty() && scene.cameras.is_empty() && scene.warnings.is_empty());
    assert!(matches!(
        load_gltf("/nonexistent/rtc/m.glb"),
        Err(AssetError::Read { .. })
    ));
    let scene = parse_gltf(
        &glb_bytes(&json!({ "asset": { "version": "2.0" } }), None),
        Path::new("e.glb"),
    )
    .unwrap();
    assert!(scene.instances.is_empty());
}

#[test]
fn large_counts_without_data_are_refused() {
    // A sparse accessor without a base view is zeros plus substitutions; its count is capped so
    // that a tiny file cannot demand gigabytes.
    let mut b = Builder::default();
    let indices = b.view(&[0u8; 4], None);
    let values = b.view(&[0u8; 12], None);
    let pos = b.accessor(json!({
        "componentType": 5126, "count": 4_000_000_000u64, "type": "VEC3", "min": [0,0,0], "max": [0,0,0],
        "sparse": { "count": 1, "indices": { "bufferView": indices, "componentType": 5125 },
                    "values": { "bufferView": values } },
    }));
    let uri = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let doc = b.document(
        Some(&uri),
        one_node(json!([{ "attributes": { "POSITION": pos } }])),
    );
    let result = parse_doc(&doc);
    match &result {
        Err(
            e @ AssetError::AccessorCount {
                problem: CountProblem::ViewlessTooLarge { count, max },
                ..
            },
        ) => {
            assert_eq!((*count, *max), (4_000_000_000, 1 << 24));
            // Element counts are called elements, never bytes.
            let message = e.to_string();
            assert!(message.contains("4000000000 elements"), "{message}");
            assert!(!message.contains("bytes"), "{message}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn base64_and_percent_decoding() {
    use crate::assets::model::buffers_for_tests::{decode_base64, percent_decode};
    for bytes in [&b""[..], b"a", b"ab", b"abc", b"abcd", &[0, 255, 128, 7, 9]] {
        assert_eq!(decode_base64(&base64(bytes)).as_deref(), Some(bytes));
        assert_eq!(
            decode_base64(base64(bytes).trim_end_matches('=')).as_deref(),
            Some(bytes)
        );
    }
    assert_eq!(decode_base64("a"), None);
    assert_eq!(decode_base64("ab!c"), None);
    assert_eq!(
        percent_decode("a%20b%C3%A9.png").as_deref(),
        Some("a bé.png")
    );
    assert_eq!(percent_decode("%2"), None);
    assert_eq!(percent_decode("%ff"), None);
}
