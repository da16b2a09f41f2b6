//! Assets held in memory (`AssetRoots::in_memory`, the renderer in a web page) are confined as
//! files on disk are: glTF buffer and image URIs and the scene's `load_mesh`/`load_image`/`model`
//! paths that lead out of the referring file's folder are refused (E0903 for the scene's), those
//! inside load, a missing file is "cannot be read"; and `model::external_files` lists exactly the
//! files reading a glTF file will ask for.
//!
//! The in-memory set holds a readable "secret" in a sibling folder `outside/` of the folder the
//! referring file is in (`inside/`), so an escape that worked would read it.

use std::path::{Path, PathBuf};
use std::sync::Arc;

use rtc_compiler::driver::{check_text, Options};
use rtc_compiler::link::registry::Registry;
use rtc_compiler::link::{link, LinkOptions};
use rtc_compiler::source::MemoryFiles;
use serde_json::json;

use super::gltf_builder::{base64, one_node, small_png, triangle};
use crate::assets::model::external_files;
use crate::assets::{load_gltf_with, AssetError, AssetRoots, PathProblem};
use crate::scene::{Entities, EntityOptions, SceneError};

/// `inside/tri.bin`, `inside/sub/ok.png`, and the secrets `outside/secret.{bin,png,obj}`, plus
/// `extra` files.
fn files(extra: &[(&str, Vec<u8>)]) -> MemoryFiles {
    let (b, _, _) = triangle();
    let mut files = MemoryFiles::new();
    files.insert("inside/tri.bin", b.bin.clone());
    files.insert("inside/sub/ok.png", small_png());
    files.insert("outside/secret.bin", b.bin.clone());
    files.insert("outside/secret.png", small_png());
    files.insert("outside/secret.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    for (path, bytes) in extra {
        files.insert(path, bytes.clone());
    }
    files
}

/// A `.gltf` whose buffer's URI is `buffer` and whose one image's URI is `image`.
fn gltf(buffer: &str, image: &str) -> Vec<u8> {
    let (b, pos, idx) = triangle();
    let mut rest = one_node(json!([
        { "attributes": { "POSITION": pos }, "indices": idx, "material": 0 }
    ]));
    rest["materials"] = json!([{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }]);
    rest["textures"] = json!([{ "source": 0 }]);
    rest["images"] = json!([{ "uri": image }]);
    serde_json::to_vec(&b.document(Some(buffer), rest)).unwrap()
}

/// Reads `inside/model.gltf` (buffer URI `buffer`, image URI `image`) from memory.
fn load(buffer: &str, image: &str) -> Result<crate::assets::ModelScene, AssetError> {
    let files = files(&[("inside/model.gltf", gltf(buffer, image))]);
    let roots = AssetRoots::in_memory(Arc::new(files));
    load_gltf_with("inside/model.gltf", &roots)
}

/// The forms of a URI that leads to `outside/secret.<ext>` from `inside/`.
fn escapes(ext: &str) -> Vec<String> {
    vec![
        format!("../outside/secret.{ext}"),
        format!("sub/../../outside/secret.{ext}"),
        format!("%2e%2e/outside/secret.{ext}"),
        format!("..%2Foutside%2Fsecret.{ext}"),
        format!("/outside/secret.{ext}"),
        format!("..\\outside\\secret.{ext}"),
        format!("C:/outside/secret.{ext}"),
        format!("file:///outside/secret.{ext}"),
    ]
}

#[test]
fn gltf_uris_in_memory_cannot_leave_the_files_folder() {
    for uri in escapes("bin") {
        let err = load(&uri, "sub/ok.png").expect_err(&uri);
        assert!(matches!(err, AssetError::Escape { .. }), "{uri}: {err:?}");
    }
    for uri in escapes("png") {
        let err = load("tri.bin", &uri).expect_err(&uri);
        assert!(matches!(err, AssetError::Escape { .. }), "{uri}: {err:?}");
    }
    // `..` that leads out names the resolved file and the folder it must be in.
    match load("../outside/secret.bin", "sub/ok.png").unwrap_err() {
        AssetError::Escape { problem, .. } => match *problem {
            PathProblem::Outside { resolved, allowed } => {
                assert_eq!(resolved, PathBuf::from("outside/secret.bin"));
                assert_eq!(allowed, vec![PathBuf::from("inside")]);
            }
            other => panic!("{other:?}"),
        },
        other => panic!("{other:?}"),
    }
}

#[test]
fn gltf_files_in_memory_inside_the_folder_load_and_missing_ones_are_named() {
    let (b, _, _) = triangle();
    let data = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    for (buffer, image) in [
        ("tri.bin", "sub/ok.png"),
        ("./tri.bin", "sub/../sub/ok.png"),
        (data.as_str(), "sub%2Fok.png"),
    ] {
        let scene = load(buffer, image).unwrap_or_else(|e| panic!("{buffer} {image}: {e}"));
        assert_eq!(scene.meshes.len(), 1, "{buffer}");
        assert_eq!(scene.textures.len(), 1, "{image}");
    }
    let err = load("nope.bin", "sub/ok.png").unwrap_err();
    assert!(
        matches!(&err, AssetError::MissingFile { file, .. } if file == Path::new("inside/nope.bin")),
        "{err:?}"
    );
    assert!(err.to_string().contains("in memory"), "{err}");
}

#[test]
fn external_files_are_what_reading_the_gltf_asks_for() {
    let roots = AssetRoots::in_memory(Arc::new(files(&[])));
    let at = Path::new("inside/model.gltf");
    let listed = |buffer: &str, image: &str| external_files(&gltf(buffer, image), at, &roots);
    assert_eq!(
        listed("tri.bin", "sub/ok.png"),
        [
            PathBuf::from("inside/tri.bin"),
            PathBuf::from("inside/sub/ok.png")
        ]
    );
    // Missing files are listed (they are what a host must fetch); the same file once.
    assert_eq!(
        listed("a%20b.bin", "a b.bin"),
        [PathBuf::from("inside/a b.bin")]
    );
    // `data:` URIs, other schemes and escapes are not.
    let (b, _, _) = triangle();
    let data = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    assert_eq!(
        listed(&data, "https://example.com/x.png"),
        Vec::<PathBuf>::new()
    );
    for uri in escapes("bin") {
        assert_eq!(listed(&uri, &uri), Vec::<PathBuf>::new(), "{uri}");
    }
    // Bytes that are not glTF name nothing.
    assert!(external_files(b"not json", at, &roots).is_empty());
}

/// The entities of a scene file `scene.rt` in the folder `inside` holding `entry`, its assets
/// from `files` in memory.
fn build_scene(entry: &str, files: MemoryFiles) -> Result<Entities, SceneError> {
    let text = format!(
        "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/unlit_texture.rt\";\n\
         scene s {{\n    camera Pinhole {{}}\n    {entry}\n}}\n"
    );
    let checked = check_text("inside/scene.rt", &text, &Options::default());
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
    .expect("link");
    Entities::build(
        &program,
        &program.scenes[linked.scene],
        &linked,
        &EntityOptions {
            asset_roots: AssetRoots::in_memory(Arc::new(files)),
            ..EntityOptions::default()
        },
    )
}

/// A scene entry naming `path` with `kind` (`load_mesh`, `load_image`, `model`).
fn entry(kind: &str, path: &str) -> String {
    match kind {
        "load_mesh" => format!(
            "object o {{ geometry: load_mesh(\"{path}\"), material: UnlitTexture {{ texture: solid_texture(vec4f(1.0)) }} }}"
        ),
        "load_image" => format!(
            "object o {{ geometry: cube_mesh(), material: UnlitTexture {{ texture: load_image(\"{path}\") }} }}"
        ),
        _ => format!("model \"{path}\" {{}}"),
    }
}

#[test]
fn scene_paths_in_memory_cannot_leave_the_scenes_folder() {
    let (b, pos, idx) = triangle();
    let data = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let model = b.document(
        Some(&data),
        one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
    );
    let model = serde_json::to_vec(&model).unwrap();
    for (kind, ext) in [
        ("load_mesh", "obj"),
        ("load_image", "png"),
        ("model", "gltf"),
    ] {
        let secrets = [("outside/secret.gltf", model.clone())];
        for path in [
            format!("../outside/secret.{ext}"),
            format!("sub/../../outside/secret.{ext}"),
        ] {
            let err = build_scene(&entry(kind, &path), files(&secrets)).expect_err(&path);
            assert!(
                matches!(
                    err,
                    SceneError::Asset {
                        span: Some(_),
                        source: AssetError::Escape { .. }
                    }
                ),
                "{kind} {path}: {err:?}"
            );
            assert_eq!(err.to_diagnostic().expect("a diagnostic").code.0, "E0903");
        }
        // The same file inside the folder loads; a missing one cannot be read.
        let inside = format!("inside/mine.{ext}");
        let bytes = match ext {
            "obj" => b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".to_vec(),
            "png" => small_png(),
            _ => model.clone(),
        };
        let ok = build_scene(
            &entry(kind, &format!("mine.{ext}")),
            files(&[(&inside, bytes)]),
        );
        assert!(ok.is_ok(), "{kind}: {:?}", ok.err());
        let err = build_scene(&entry(kind, &format!("gone.{ext}")), files(&[])).unwrap_err();
        assert!(
            matches!(
                err,
                SceneError::Asset {
                    source: AssetError::Read { .. },
                    ..
                }
            ),
            "{kind}: {err:?}"
        );
    }
}
