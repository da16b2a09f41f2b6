//! glTF files through a scene's `model` entry (compiler check and link, then the entity stage, no
//! GPU): one BLAS per mesh shared by every node that instances it, node × entry transforms, the
//! materials, lights and camera a file brings (packed as the stdlib structs), and broken files as
//! typed E0902 errors at the model's string.

use glam::{Mat4, Quat, Vec3};
use rtc_compiler::driver::{check_text, Options};
use rtc_compiler::layout;
use rtc_compiler::link::registry::Registry;
use rtc_compiler::link::{link, LinkOptions, Linked};
use rtc_compiler::sema::hir::Program;
use rtc_compiler::sema::types::Type;
use serde_json::{json, Value};

use super::gltf_builder::{one_node, small_png, triangle, Builder};
use super::{assert_close, assert_close3, TempDir};
use crate::assets::{AssetError, GltfItem};
use crate::scene::{Entities, EntityOptions, GpuInstance, SceneError, TypedOffset};

/// Checks, links and builds the entities of the only scene of `text`, written as `scene.rt` in `dir`.
fn build(dir: &TempDir, text: &str) -> (Program, Linked, Result<Entities, SceneError>) {
    let name = dir.path().join("scene.rt");
    let checked = check_text(&name.display().to_string(), text, &Options::default());
    assert!(
        !checked.has_errors(),
        "{}",
        rtc_compiler::diag::render_human(&checked.sources, &checked.diagnostics, false)
    );
    let program = checked.program.expect("a program");
    let scene = program.select_scene(None).expect("one scene");
    let linked = link(
        &program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    )
    .unwrap_or_else(|d| panic!("link: {d:?}"));
    let entities = Entities::build(
        &program,
        &program.scenes[linked.scene],
        &linked,
        &EntityOptions::default(),
    );
    (program, linked, entities)
}

/// The `f32` words of field `field` of the `name` instance at `at`.
fn field(p: &Program, e: &Entities, name: &str, at: TypedOffset, field: &str) -> Vec<f32> {
    let (s, st) = p
        .structs
        .iter()
        .find(|(_, st)| st.name == name)
        .expect("struct");
    let ty = p
        .types
        .iter()
        .find(|(_, t)| *t == Type::Struct(s))
        .map(|(id, _)| id)
        .expect("type");
    let index = st.field_index(field).expect("field");
    let offset = layout::field_offsets(p, ty)[index] / 4;
    let words = layout::layout(p, st.fields[index].ty).size / 4;
    let start = (at.offset + offset) as usize;
    e.params()[start..start + words as usize]
        .iter()
        .map(|w| f32::from_bits(*w))
        .collect()
}

/// The id the link plan gave the struct `name`.
fn id_of(p: &Program, l: &Linked, name: &str) -> u32 {
    l.types
        .values()
        .flatten()
        .find(|t| p.structs[t.struct_id].name == name)
        .map(|t| t.id)
        .unwrap_or_else(|| panic!("{name} is not linked"))
}

/// A unit quad (two triangles) in the xy-plane with uvs.
fn quad(b: &mut Builder) -> Value {
    let pos = b.vec3(&[
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ]);
    let uv = b.vec2(&[[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]]);
    let idx = b.indices_u16(&[0, 1, 2, 0, 2, 3]);
    json!({ "attributes": { "POSITION": pos, "TEXCOORD_0": uv }, "indices": idx, "material": 0 })
}

/// A `.glb` with one quad mesh instanced by two nodes under a translated, scaled parent, a
/// textured material, a camera, and a point, a directional and a spot light.
fn hierarchy_glb() -> Vec<u8> {
    let mut b = Builder::default();
    let prim = quad(&mut b);
    let png = small_png();
    let image_view = b.view(&png, None);
    let rest = json!({
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": { "KHR_lights_punctual": { "lights": [
            { "type": "point", "color": [1.0, 0.5, 0.25], "intensity": 20.0, "range": 9.0 },
            { "type": "directional", "intensity": 3.0 },
            { "type": "spot", "intensity": 7.0, "spot": { "innerConeAngle": 0.25, "outerConeAngle": 0.5 } },
        ] } },
        "meshes": [{ "primitives": [prim] }],
        "materials": [{
            "name": "painted",
            "pbrMetallicRoughness": {
                "baseColorFactor": [0.5, 0.25, 1.0, 1.0],
                "baseColorTexture": { "index": 0 },
                "metallicFactor": 0.125,
                "roughnessFactor": 0.75,
            },
            "emissiveFactor": [0.0, 0.5, 0.0],
        }],
        "textures": [{ "source": 0 }],
        "images": [{ "bufferView": image_view, "mimeType": "image/png" }],
        "cameras": [{ "type": "perspective", "perspective": { "yfov": 0.5, "znear": 0.1 } }],
        "nodes": [
            { "children": [1, 2, 3, 4, 5, 6], "translation": [10.0, 0.0, 0.0], "scale": [2.0, 2.0, 2.0] },
            { "mesh": 0, "translation": [1.0, 0.0, 0.0] },
            { "mesh": 0, "translation": [0.0, 3.0, 0.0] },
            { "camera": 0, "translation": [0.0, 0.0, 5.0] },
            { "translation": [0.0, 4.0, 0.0], "extensions": { "KHR_lights_punctual": { "light": 0 } } },
            // Rotated -90° about x: its -z points down (-y).
            { "rotation": [-0.70710677, 0.0, 0.0, 0.70710677], "extensions": { "KHR_lights_punctual": { "light": 1 } } },
            { "translation": [0.0, 1.0, 0.0], "extensions": { "KHR_lights_punctual": { "light": 2 } } },
        ],
        "scenes": [{ "nodes": [0] }],
    });
    b.glb(rest)
}

const NO_CAMERA: &str =
    "scene s {\n    model \"model.glb\" { transform: translate(vec3f(0.0, 0.0, -1.0)) }\n}\n";

#[test]
fn two_nodes_share_one_blas_and_get_node_times_entry_transforms() {
    let dir = TempDir::new("gltf-scene");
    dir.write("model.glb", hierarchy_glb());
    let (_, _, e) = build(&dir, NO_CAMERA);
    let e = e.expect("entities");
    assert_eq!(e.meshes().len(), 1, "one mesh");
    assert_eq!(e.stats().blas_builds, 1, "one BLAS for both nodes");
    assert_eq!(e.objects().len(), 2);
    let entry = Mat4::from_translation(Vec3::new(0.0, 0.0, -1.0));
    let parent = Mat4::from_scale_rotation_translation(
        Vec3::splat(2.0),
        Quat::IDENTITY,
        Vec3::new(10.0, 0.0, 0.0),
    );
    let expected = [
        entry * parent * Mat4::from_translation(Vec3::X),
        entry * parent * Mat4::from_translation(Vec3::new(0.0, 3.0, 0.0)),
    ];
    for (o, want) in e.objects().iter().zip(expected) {
        assert!(
            o.transform.abs_diff_eq(want, 1e-6),
            "{} vs {want}",
            o.transform
        );
        assert!(o
            .name
            .as_deref()
            .is_some_and(|n| n.contains("model.glb#nodes[")));
    }
    // The world-space corner (1, 1, 0) of the first instance: (10 + 2·(1 + 1), 2, -1).
    let corner = e.objects()[0]
        .transform
        .transform_point3(Vec3::new(1.0, 1.0, 0.0));
    assert_close3(corner, [14.0, 2.0, -1.0], 1e-6);
    // Both instances are in the TLAS, pointing at the same BLAS root.
    let roots: Vec<u32> = e.instances().iter().map(|i| i.blas_root).collect();
    assert_eq!(roots.len(), 2);
    assert_eq!(roots[0], roots[1]);
}

#[test]
fn materials_lights_and_camera_become_stdlib_instances() {
    let dir = TempDir::new("gltf-scene");
    dir.write("model.glb", hierarchy_glb());
    let (p, l, e) = build(&dir, NO_CAMERA);
    let e = e.expect("entities");

    // Material: GltfMaterial with the file's factors and its embedded texture.
    let material = e.objects()[0].material;
    assert_eq!(material.type_id, id_of(&p, &l, "GltfMaterial"));
    assert_eq!(
        field(&p, &e, "GltfMaterial", material, "base_color"),
        [0.5, 0.25, 1.0, 1.0]
    );
    assert_eq!(field(&p, &e, "GltfMaterial", material, "metallic"), [0.125]);
    assert_eq!(field(&p, &e, "GltfMaterial", material, "roughness"), [0.75]);
    assert_eq!(
        field(&p, &e, "GltfMaterial", material, "emissive"),
        [0.0, 0.5, 0.0]
    );
    let texture = e
        .textures()
        .iter()
        .find(|t| t.source.ends_with("model.glb#images[0]"))
        .expect("the embedded image is a texture");
    assert_eq!((texture.width, texture.height), (2, 1));

    // Lights, in node order, in world space (entry · parent · node).
    let lights = e.lights();
    assert_eq!(lights.len(), 3);
    assert_eq!(lights[0].type_id, id_of(&p, &l, "PointLight"));
    assert_eq!(lights[1].type_id, id_of(&p, &l, "DirectionalLight"));
    assert_eq!(lights[2].type_id, id_of(&p, &l, "SpotLight"));
    let position = field(&p, &e, "PointLight", lights[0], "position");
    assert_close3(
        [position[0], position[1], position[2]],
        [10.0, 8.0, -1.0],
        1e-5,
    );
    assert_eq!(
        field(&p, &e, "PointLight", lights[0], "color"),
        [1.0, 0.5, 0.25]
    );
    assert_eq!(field(&p, &e, "PointLight", lights[0], "intensity"), [20.0]);
    assert_eq!(field(&p, &e, "PointLight", lights[0], "range"), [9.0]);
    let dir_light = field(&p, &e, "DirectionalLight", lights[1], "direction");
    assert_close3(
        [dir_light[0], dir_light[1], dir_light[2]],
        [0.0, -1.0, 0.0],
        1e-5,
    );
    assert_eq!(
        field(&p, &e, "DirectionalLight", lights[1], "intensity"),
        [3.0]
    );
    let inner = field(&p, &e, "SpotLight", lights[2], "inner_angle")[0];
    let outer = field(&p, &e, "SpotLight", lights[2], "outer_angle")[0];
    assert_close(inner, 0.25f32.to_degrees(), 1e-4);
    assert_close(outer, 0.5f32.to_degrees(), 1e-4);

    // Camera: a Pinhole at the camera node, looking along its -z, fov = yfov in degrees.
    let camera = e.camera();
    assert_eq!(camera.type_id, id_of(&p, &l, "Pinhole"));
    let at = field(&p, &e, "Pinhole", camera, "position");
    assert_close3([at[0], at[1], at[2]], [10.0, 0.0, 9.0], 1e-5);
    let look = field(&p, &e, "Pinhole", camera, "look_at");
    assert_close3([look[0], look[1], look[2]], [10.0, 0.0, 8.0], 1e-5);
    assert_close(
        field(&p, &e, "Pinhole", camera, "fov")[0],
        0.5f32.to_degrees(),
        1e-4,
    );
}

#[test]
fn a_scene_camera_wins_over_the_models() {
    let dir = TempDir::new("gltf-scene");
    dir.write("model.glb", hierarchy_glb());
    let text = "import \"std/cameras/orthographic.rt\";\n\
                scene s {\n    camera Orthographic {}\n    model \"model.glb\" {}\n}\n";
    let (p, l, e) = build(&dir, text);
    let e = e.expect("entities");
    assert_eq!(e.camera().type_id, id_of(&p, &l, "Orthographic"));
    assert!(
        l.types
            .values()
            .flatten()
            .all(|t| p.structs[t.struct_id].name != "Pinhole"),
        "no Pinhole is linked when the scene has a camera"
    );
}

#[test]
fn a_model_without_camera_in_a_scene_without_camera_is_a_typed_error() {
    let dir = TempDir::new("gltf-scene");
    let (b, pos, idx) = triangle();
    dir.write(
        "model.glb",
        b.glb(one_node(json!([
            { "attributes": { "POSITION": pos }, "indices": idx }
        ]))),
    );
    let (_, _, e) = build(&dir, NO_CAMERA);
    let err = e.expect_err("no camera");
    assert!(matches!(err, SceneError::NoCamera { .. }), "{err}");
    assert!(err.to_string().contains("add a `camera` entry"), "{err}");
}

/// Builds a scene over `file` and returns the E0902 diagnostic's message and note.
fn load_error(dir: &TempDir, file: &str) -> (SceneError, String) {
    let text = format!(
        "import \"std/cameras/pinhole.rt\";\nscene s {{\n    camera Pinhole {{}}\n    model \"{file}\" {{}}\n}}\n"
    );
    let (_, _, e) = build(dir, &text);
    let err = e.expect_err("a broken model");
    let diag = err.to_diagnostic().expect("an E0902 diagnostic");
    assert_eq!(diag.code.0, "E0902");
    assert!(diag.message.contains(file), "{}", diag.message);
    let text = format!("{} | {}", diag.message, err);
    (err, text)
}

#[test]
fn broken_files_are_e0902_at_the_models_string() {
    let dir = TempDir::new("gltf-scene");
    // Truncated .glb.
    let glb = hierarchy_glb();
    dir.write("cut.glb", &glb[..glb.len() / 2]);
    let (err, text) = load_error(&dir, "cut.glb");
    assert!(
        matches!(
            err,
            SceneError::Asset {
                source: AssetError::Glb { .. },
                ..
            }
        ),
        "{text}"
    );
    assert!(text.contains("truncated"), "{text}");

    // Bad JSON.
    dir.write(
        "bad.gltf",
        "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ }",
    );
    let (err, text) = load_error(&dir, "bad.gltf");
    assert!(
        matches!(
            err,
            SceneError::Asset {
                source: AssetError::BadJson { .. },
                ..
            }
        ),
        "{text}"
    );

    // An accessor that reaches past its buffer.
    let (mut b, _, idx) = triangle();
    let pos = b.accessor(json!({
        "bufferView": 0, "componentType": 5126, "count": 1000, "type": "VEC3",
        "min": [0.0, 0.0, 0.0], "max": [1.0, 1.0, 0.0],
    }));
    dir.write(
        "overrun.glb",
        b.glb(one_node(json!([
            { "attributes": { "POSITION": pos }, "indices": idx }
        ]))),
    );
    let (err, text) = load_error(&dir, "overrun.glb");
    assert!(
        matches!(
            err,
            SceneError::Asset {
                source: AssetError::AccessorOutOfRange { .. },
                ..
            }
        ),
        "{text}"
    );

    // A missing .bin buffer.
    let (b, pos, idx) = triangle();
    let doc = b.document(
        Some("gone.bin"),
        one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
    );
    dir.write("nobin.gltf", serde_json::to_vec(&doc).unwrap());
    let (err, text) = load_error(&dir, "nobin.gltf");
    assert!(
        matches!(
            err,
            SceneError::Asset {
                source: AssetError::MissingFile {
                    item: GltfItem::Buffer(0),
                    ..
                },
                ..
            }
        ),
        "{text}"
    );
    assert!(text.contains("gone.bin"), "{text}");
}

#[test]
fn a_missing_texture_names_the_file_and_the_material() {
    let dir = TempDir::new("gltf-scene");
    let mut b = Builder::default();
    let prim = quad(&mut b);
    let doc = b.document(
        Some("tex.bin"),
        json!({
            "meshes": [{ "primitives": [prim] }],
            "materials": [{ "name": "wood", "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }],
            "textures": [{ "source": 0 }],
            "images": [{ "uri": "wood.png" }],
            "nodes": [{ "mesh": 0 }],
            "scenes": [{ "nodes": [0] }],
        }),
    );
    dir.write("tex.bin", &b.bin);
    dir.write("tex.gltf", serde_json::to_vec(&doc).unwrap());
    let (err, text) = load_error(&dir, "tex.gltf");
    assert!(
        matches!(
            err,
            SceneError::Asset {
                source: AssetError::MissingFile {
                    item: GltfItem::BaseColorImage {
                        material: 0,
                        image: 0
                    },
                    ..
                },
                ..
            }
        ),
        "{text}"
    );
    assert!(
        text.contains("wood.png") && text.contains("materials[0]"),
        "{text}"
    );
}

#[test]
fn unknown_material_fields_warn_or_fail_as_stated() {
    let dir = TempDir::new("gltf-scene");
    let (b, pos, idx) = triangle();
    let rest = |required: bool| {
        let mut v = json!({
            "extensionsUsed": ["KHR_materials_clearcoat"],
            "meshes": [{ "primitives": [{ "attributes": { "POSITION": pos }, "indices": idx, "material": 0 }] }],
            "materials": [{
                "pbrMetallicRoughness": { "baseColorFactor": [1.0, 0.0, 0.0, 1.0] },
                "shininess": 12,
                "extensions": { "KHR_materials_clearcoat": { "clearcoatFactor": 1.0 } },
            }],
            "nodes": [{ "mesh": 0 }],
            "scenes": [{ "nodes": [0] }],
        });
        if required {
            v["extensionsRequired"] = json!(["KHR_materials_clearcoat"]);
        }
        v
    };
    // An unknown extension the file merely uses: a warning naming it; an unknown plain field
    // (`shininess`) is ignored, as glTF readers must.
    dir.write("used.glb", b.glb(rest(false)));
    let text = "import \"std/cameras/pinhole.rt\";\nscene s {\n    camera Pinhole {}\n    model \"used.glb\" {}\n}\n";
    let (_, _, e) = build(&dir, text);
    let e = e.expect("entities");
    assert!(
        e.warnings()
            .iter()
            .any(|w| w.contains("used.glb") && w.contains("KHR_materials_clearcoat")),
        "{:?}",
        e.warnings()
    );
    assert_eq!(e.objects().len(), 1);
    // The same extension required: the file cannot be rendered faithfully, an error.
    dir.write("required.glb", b.glb(rest(true)));
    let (err, text) = load_error(&dir, "required.glb");
    assert!(
        matches!(
            err,
            SceneError::Asset {
                source: AssetError::InvalidGltf { .. },
                ..
            }
        ),
        "{text}"
    );
    assert!(text.contains("KHR_materials_clearcoat"), "{text}");
}

#[test]
fn a_rebuild_with_the_store_reads_no_model_and_builds_no_blas_until_the_file_changes() {
    let dir = TempDir::new("gltf-store");
    dir.write("model.glb", hierarchy_glb());
    let name = dir.path().join("scene.rt");
    let checked = check_text(&name.display().to_string(), NO_CAMERA, &Options::default());
    let program = checked.program.expect("a program");
    let scene = program.select_scene(None).expect("one scene");
    let linked = link(
        &program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    )
    .unwrap_or_else(|d| panic!("link: {d:?}"));
    let desc = &program.scenes[linked.scene];
    let mut store = crate::scene::AssetStore::new();
    let options = EntityOptions::default();
    let first = Entities::build_with_store(&program, desc, &linked, &options, &mut store)
        .expect("entities");
    let after_first = store.counters();
    assert_eq!((after_first.models_read, after_first.blas_builds), (1, 1));
    let second = Entities::build_with_store(&program, desc, &linked, &options, &mut store)
        .expect("entities");
    assert_eq!(store.counters().models_read, 1, "not read again");
    assert_eq!(store.counters().blas_builds, 1, "no BLAS built again");
    assert_eq!(second.stats().blas_builds, 0);
    assert_eq!(first.nodes(), second.nodes());
    assert_eq!(first.params(), second.params());
    assert_eq!(first.texels(), second.texels());
    // A changed file is read again and its mesh's BLAS built again.
    let mut changed = hierarchy_glb();
    changed.extend_from_slice(&[0x20; 4]);
    dir.write("model.glb", changed);
    Entities::build_with_store(&program, desc, &linked, &options, &mut store).expect("entities");
    assert_eq!(store.counters().models_read, 2);
    assert_eq!(store.counters().blas_builds, 2);
}

#[test]
fn a_model_file_named_twice_is_read_once_and_shares_its_blas() {
    let dir = TempDir::new("gltf-scene");
    dir.write("model.glb", hierarchy_glb());
    let text = "scene s {\n    model \"model.glb\" {}\n    model \"model.glb\" { transform: translate(vec3f(0.0, 50.0, 0.0)) }\n}\n";
    let (_, _, e) = build(&dir, text);
    let e = e.expect("entities");
    assert_eq!(e.objects().len(), 4);
    assert_eq!(e.stats().blas_builds, 1);
    assert_eq!(e.lights().len(), 6);
    let y = e.objects()[2].transform.transform_point3(Vec3::ZERO).y;
    assert_close(y, 50.0, 1e-5);
}

#[test]
fn masked_materials_get_the_any_hit_material_and_only_they_are_flagged() {
    let dir = TempDir::new("gltf-scene");
    let mut b = Builder::default();
    let prim = quad(&mut b);
    let masked = json!({ "attributes": prim["attributes"].clone(), "indices": prim["indices"].clone(), "material": 1 });
    dir.write(
        "mask.glb",
        b.glb(json!({
            "meshes": [{ "primitives": [prim] }, { "primitives": [masked] }],
            "materials": [
                { "pbrMetallicRoughness": { "baseColorFactor": [1.0, 1.0, 1.0, 0.5] } },
                { "alphaMode": "MASK", "alphaCutoff": 0.3, "pbrMetallicRoughness": { "baseColorFactor": [1.0, 1.0, 1.0, 0.5] } },
            ],
            "nodes": [{ "mesh": 0 }, { "mesh": 1, "translation": [2.0, 0.0, 0.0] }],
            "scenes": [{ "nodes": [0, 1] }],
        })),
    );
    let text = "import \"std/cameras/pinhole.rt\";\nscene s {\n    camera Pinhole {}\n    model \"mask.glb\" {}\n}\n";
    let (p, l, e) = build(&dir, text);
    let e = e.expect("entities");
    let [opaque, cut] = e.objects() else {
        panic!("two objects")
    };
    assert_eq!(opaque.material.type_id, id_of(&p, &l, "GltfMaterial"));
    assert_eq!(cut.material.type_id, id_of(&p, &l, "GltfMaskedMaterial"));
    assert_eq!(
        field(&p, &e, "GltfMaskedMaterial", cut.material, "alpha_cutoff"),
        [0.3]
    );
    assert_eq!(opaque.flags & GpuInstance::FLAG_ANY_HIT, 0);
    assert_ne!(cut.flags & GpuInstance::FLAG_ANY_HIT, 0);
    assert!(l.config.has_any_hit);
}

/// The names of the linked types of role-namespace `role` (`light`, `material`, …).
fn linked_names(p: &Program, l: &Linked, role: &str) -> Vec<String> {
    l.types
        .iter()
        .filter(|(r, _)| r.name() == role)
        .flat_map(|(_, ts)| ts.iter().map(|t| p.structs[t.struct_id].name.clone()))
        .collect()
}

/// A `.glb` with one opaque triangle and one light of each `lights` type (`point`, `spot`,
/// `directional`), each on its own node.
fn lights_glb(lights: &[&str]) -> Vec<u8> {
    let (b, pos, idx) = triangle();
    let mut doc = one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }]));
    let list: Vec<Value> = lights
        .iter()
        .map(|&t| match t {
            "spot" => json!({ "type": t, "spot": {} }),
            _ => json!({ "type": t }),
        })
        .collect();
    let mut nodes = vec![json!({ "mesh": 0 })];
    nodes.extend((0..lights.len()).map(|i| {
        json!({ "translation": [0.0, 2.0, 0.0], "extensions": { "KHR_lights_punctual": { "light": i } } })
    }));
    doc["nodes"] = json!(nodes);
    doc["scenes"] = json!([{ "nodes": (0..nodes.len()).collect::<Vec<_>>() }]);
    doc["extensionsUsed"] = json!(["KHR_lights_punctual"]);
    doc["extensions"] = json!({ "KHR_lights_punctual": { "lights": list } });
    b.glb(doc)
}

const WITH_CAMERA: &str = "import \"std/cameras/pinhole.rt\";\nscene s {\n    camera Pinhole {}\n    model \"model.glb\" {}\n}\n";

#[test]
fn the_link_step_links_only_the_model_types_the_file_holds() {
    let dir = TempDir::new("gltf-scene");
    dir.write("model.glb", lights_glb(&["point"]));
    let (p, l, e) = build(&dir, WITH_CAMERA);
    let e = e.expect("entities");
    assert_eq!(linked_names(&p, &l, "light"), ["PointLight"]);
    assert_eq!(linked_names(&p, &l, "material"), ["GltfMaterial"]);
    assert!(!l.config.has_any_hit);
    assert_eq!(e.lights().len(), 1);
    assert_eq!(e.lights()[0].type_id, id_of(&p, &l, "PointLight"));
    // The reasons in `left_out` name the file's contents.
    let spot = l
        .left_out
        .iter()
        .find(|o| o.name == "@light spot_light")
        .expect("spot_light left out");
    assert_eq!(spot.reason, "no model file of the scene holds a spot light");
}

#[test]
fn a_file_that_changed_after_linking_is_an_internal_error_naming_file_and_type() {
    let dir = TempDir::new("gltf-scene");
    let path = dir.write("model.glb", lights_glb(&["point"]));
    let name = dir.path().join("scene.rt");
    let checked = check_text(
        &name.display().to_string(),
        WITH_CAMERA,
        &Options::default(),
    );
    let program = checked.program.expect("a program");
    let scene = program.select_scene(None).expect("one scene");
    let linked = link(
        &program,
        scene,
        &mut Registry::new(),
        &LinkOptions::default(),
    )
    .expect("link");
    // The file gains a spot light between the compile and the render.
    std::fs::write(&path, lights_glb(&["point", "spot"])).expect("rewrite");
    let err = Entities::build(
        &program,
        &program.scenes[linked.scene],
        &linked,
        &EntityOptions::default(),
    )
    .expect_err("an internal error");
    assert!(
        matches!(&err, SceneError::ModelUnlinked { name, model } if name == "SpotLight" && model.ends_with("model.glb")),
        "{err}"
    );
    let text = err.to_string();
    assert!(text.starts_with("internal error: "), "{text}");
    assert!(text.contains("compile the scene again"), "{text}");
}

#[test]
fn a_file_the_link_step_cannot_read_links_every_model_type_and_fails_at_its_string() {
    let dir = TempDir::new("gltf-scene");
    let text = "scene s {\n    model \"missing.glb\" {}\n}\n";
    let (p, l, e) = build(&dir, text);
    let mut lights = linked_names(&p, &l, "light");
    lights.sort();
    assert_eq!(lights, ["DirectionalLight", "PointLight", "SpotLight"]);
    assert!(linked_names(&p, &l, "camera").contains(&"Pinhole".to_owned()));
    assert!(l.config.has_any_hit);
    assert!(
        matches!(&l.models[0].read, rtc_compiler::link::ModelRead::NotRead(why) if why.contains("missing.glb")),
        "{:?}",
        l.models
    );
    let err = e.expect_err("a missing file");
    let diag = err.to_diagnostic().expect("a located diagnostic");
    assert_eq!(diag.code.0, "E0902");
    assert!(diag.message.contains("missing.glb"), "{}", diag.message);
}
