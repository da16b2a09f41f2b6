//! Asset paths stay inside the folders they were given (`assets::confine`): one test per form of
//! escape (absolute path, `..`, percent-encoded `..`, `file://`, a symlink pointing out, a
//! backslash, a drive letter) for glTF buffer URIs, glTF image URIs and the scene's `load_mesh`,
//! `load_image` and `model` paths; and what stays allowed (`data:` URIs, `..` inside the folder,
//! a folder named as an asset root).
//!
//! Each test puts a readable "secret" file in a sibling folder `outside/` of the folder the
//! referring file is in (`inside/`), so an escape that worked would read it.

use std::path::PathBuf;

use rtc_compiler::driver::{check_text, Options};
use rtc_compiler::link::registry::Registry;
use rtc_compiler::link::{link, LinkOptions};
use serde_json::json;

use super::gltf_builder::{base64, one_node, small_png, triangle};
use super::TempDir;
use crate::assets::{
    load_gltf, load_gltf_with, AssetError, AssetRoots, GltfItem, PathProblem, UriProblem,
};
use crate::scene::{Entities, EntityOptions, SceneError};

/// `inside/` (where the referring file goes) and `outside/` (holding `secret.bin`,
/// `secret.png` and `secret.obj`) in a fresh temp folder.
struct Layout {
    tmp: TempDir,
}

impl Layout {
    fn new(tag: &str) -> Layout {
        let tmp = TempDir::new(tag);
        // `inside/sub` exists so that `sub/../../outside/…` resolves (and is refused as leading
        // out, rather than failing to open).
        std::fs::create_dir_all(tmp.path().join("inside/sub")).unwrap();
        std::fs::create_dir_all(tmp.path().join("outside")).unwrap();
        let (b, _, _) = triangle();
        std::fs::write(tmp.path().join("outside/secret.bin"), &b.bin).unwrap();
        std::fs::write(tmp.path().join("outside/secret.png"), small_png()).unwrap();
        std::fs::write(
            tmp.path().join("outside/secret.obj"),
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        )
        .unwrap();
        Layout { tmp }
    }

    fn inside(&self) -> PathBuf {
        self.tmp.path().join("inside")
    }

    fn outside(&self) -> PathBuf {
        self.tmp.path().join("outside")
    }

    /// A symlink `inside/name` to `outside/target`.
    #[cfg(unix)]
    fn link(&self, name: &str, target: &str) {
        std::os::unix::fs::symlink(self.outside().join(target), self.inside().join(name)).unwrap();
    }
}

/// The URIs (or paths) that must be refused, by form, for a file called `secret.<ext>` in the
/// sibling folder `outside/`.
fn escapes(layout: &Layout, ext: &str) -> Vec<(&'static str, String)> {
    let absolute = layout.outside().join(format!("secret.{ext}"));
    let absolute = absolute.to_str().unwrap().to_owned();
    let mut forms = vec![
        ("absolute", absolute.clone()),
        ("dot-dot", format!("../outside/secret.{ext}")),
        ("dot-dot deeper", format!("sub/../../outside/secret.{ext}")),
        ("backslash", format!("..\\outside\\secret.{ext}")),
        ("drive letter", format!("C:/outside/secret.{ext}")),
        ("file URI", format!("file://{absolute}")),
    ];
    #[cfg(unix)]
    {
        layout.link(&format!("link.{ext}"), &format!("secret.{ext}"));
        forms.push(("symlink", format!("link.{ext}")));
    }
    forms
}

/// Whether `err` is an escape (anything else, above all a successful read, is not).
fn is_escape(err: &AssetError) -> bool {
    matches!(err, AssetError::Escape { .. })
}

// ---- glTF buffers ----

/// A `.gltf` in `inside/` whose buffer's URI is `uri`.
fn gltf_with_buffer_uri(layout: &Layout, uri: &str) -> PathBuf {
    let (b, pos, idx) = triangle();
    let doc = b.document(
        Some(uri),
        one_node(json!([{ "attributes": { "POSITION": pos }, "indices": idx }])),
    );
    let path = layout.inside().join("model.gltf");
    std::fs::write(&path, serde_json::to_vec(&doc).unwrap()).unwrap();
    path
}

#[test]
fn gltf_buffer_uris_cannot_leave_the_files_folder() {
    let layout = Layout::new("confine-buf");
    let mut forms = escapes(&layout, "bin");
    forms.push(("percent-encoded", "%2e%2e/outside/secret.bin".to_owned()));
    forms.push((
        "percent-encoded slash",
        "..%2Foutside%2Fsecret.bin".to_owned(),
    ));
    for (form, uri) in forms {
        let path = gltf_with_buffer_uri(&layout, &uri);
        let err = load_gltf(&path).expect_err(form);
        assert!(is_escape(&err), "{form}: {err:?}");
        let AssetError::Escape {
            item,
            path: at,
            written,
            ..
        } = &err
        else {
            unreachable!()
        };
        assert_eq!(*item, Some(GltfItem::Buffer(0)), "{form}");
        assert_eq!(at, &path, "{form}");
        assert_eq!(written, &uri, "{form}");
        // The message names the glTF file, the URI and the folder it must be in.
        let message = err.to_string();
        assert!(message.contains("model.gltf"), "{form}: {message}");
        assert!(message.contains("buffers[0]"), "{form}: {message}");
        assert!(message.contains(&uri), "{form}: {message}");
        assert!(message.contains("inside"), "{form}: {message}");
    }
}

#[test]
fn the_form_of_a_refused_buffer_uri_is_named() {
    let layout = Layout::new("confine-form");
    let cases = [
        ("/etc/hostname", PathProblem::Absolute),
        ("..\\x.bin", PathProblem::Backslash),
        ("C:/x.bin", PathProblem::DriveLetter),
        ("file:///etc/hostname", PathProblem::Uri),
        ("FILE:x.bin", PathProblem::Uri),
        ("%2Fetc%2Fhostname", PathProblem::Absolute),
        ("%5C..%5Cx.bin", PathProblem::Backslash),
    ];
    for (uri, expected) in cases {
        let err = load_gltf(gltf_with_buffer_uri(&layout, uri)).expect_err(uri);
        match err {
            AssetError::Escape { problem, .. } => assert_eq!(*problem, expected, "{uri}"),
            other => panic!("{uri}: {other:?}"),
        }
    }
    // `..` that leads out: the resolved file is named.
    let err = load_gltf(gltf_with_buffer_uri(&layout, "../outside/secret.bin")).unwrap_err();
    match &err {
        AssetError::Escape { problem, .. } => match problem.as_ref() {
            PathProblem::Outside { resolved, allowed } => {
                assert!(resolved.ends_with("outside/secret.bin"), "{resolved:?}");
                assert_eq!(allowed, &vec![layout.inside()]);
            }
            other => panic!("{other:?}"),
        },
        other => panic!("{other:?}"),
    }
    // Other schemes stay "not supported", not escapes.
    let err = load_gltf(gltf_with_buffer_uri(&layout, "https://example.com/x.bin")).unwrap_err();
    assert!(
        matches!(
            err,
            AssetError::Uri {
                problem: UriProblem::UnsupportedScheme,
                ..
            }
        ),
        "{err:?}"
    );
}

#[test]
fn buffers_inside_the_folder_data_uris_and_asset_roots_still_load() {
    let layout = Layout::new("confine-ok");
    let (b, _, _) = triangle();
    std::fs::create_dir_all(layout.inside().join("sub")).unwrap();
    std::fs::write(layout.inside().join("tri.bin"), &b.bin).unwrap();
    std::fs::write(layout.inside().join("with space.bin"), &b.bin).unwrap();
    for uri in ["tri.bin", "sub/../tri.bin", "./tri.bin", "with%20space.bin"] {
        let scene = load_gltf(gltf_with_buffer_uri(&layout, uri)).unwrap_or_else(|e| {
            panic!("{uri}: {e}");
        });
        assert_eq!(scene.meshes.len(), 1, "{uri}");
    }
    let data = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let scene = load_gltf(gltf_with_buffer_uri(&layout, &data)).unwrap();
    assert_eq!(scene.meshes[0].positions.len(), 3);
    // A symlink that stays inside the folder is followed.
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(
            layout.inside().join("tri.bin"),
            layout.inside().join("l.bin"),
        )
        .unwrap();
        load_gltf(gltf_with_buffer_uri(&layout, "l.bin")).unwrap();
    }
    // A folder named as an asset root may be reached with `..` (and only it).
    let path = gltf_with_buffer_uri(&layout, "../outside/secret.bin");
    let roots = AssetRoots::new([layout.outside()]);
    let scene = load_gltf_with(&path, &roots).unwrap();
    assert_eq!(scene.meshes.len(), 1);
    // A missing file inside is still "cannot be read", naming it.
    let err = load_gltf(gltf_with_buffer_uri(&layout, "nope.bin")).unwrap_err();
    assert!(
        matches!(&err, AssetError::MissingFile { file, .. } if file.ends_with("nope.bin")),
        "{err:?}"
    );
}

// ---- glTF images ----

/// A `.gltf` in `inside/` with an embedded triangle and one material whose base-colour image's URI
/// is `uri`.
fn gltf_with_image_uri(layout: &Layout, uri: &str) -> PathBuf {
    let (b, pos, idx) = triangle();
    let data = format!("data:application/octet-stream;base64,{}", base64(&b.bin));
    let mut rest = one_node(json!([
        { "attributes": { "POSITION": pos }, "indices": idx, "material": 0 }
    ]));
    rest["materials"] = json!([{ "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 } } }]);
    rest["textures"] = json!([{ "source": 0 }]);
    rest["images"] = json!([{ "uri": uri }]);
    let doc = b.document(Some(&data), rest);
    let path = layout.inside().join("textured.gltf");
    std::fs::write(&path, serde_json::to_vec(&doc).unwrap()).unwrap();
    path
}

#[test]
fn gltf_image_uris_cannot_leave_the_files_folder() {
    let layout = Layout::new("confine-img");
    let mut forms = escapes(&layout, "png");
    forms.push(("percent-encoded", "%2E%2E/outside/secret.png".to_owned()));
    for (form, uri) in forms {
        let path = gltf_with_image_uri(&layout, &uri);
        let err = load_gltf(&path).expect_err(form);
        match &err {
            AssetError::Escape { item, .. } => assert_eq!(
                *item,
                Some(GltfItem::BaseColorImage {
                    material: 0,
                    image: 0
                }),
                "{form}"
            ),
            other => panic!("{form}: {other:?}"),
        }
        let message = err.to_string();
        assert!(message.contains("textured.gltf"), "{form}: {message}");
        assert!(message.contains("materials[0]"), "{form}: {message}");
    }
    // The same image inside the folder loads.
    std::fs::write(layout.inside().join("ok.png"), small_png()).unwrap();
    let scene = load_gltf(gltf_with_image_uri(&layout, "ok.png")).unwrap();
    assert_eq!(scene.textures.len(), 1);
}

// ---- scene paths ----

const HEADER: &str =
    "import \"std/cameras/pinhole.rt\";\nimport \"std/materials/unlit_texture.rt\";\n";

/// Builds the entities of a scene file `scene.rt` in the layout's `inside` folder holding `entry`, with `roots`.
fn build_scene(layout: &Layout, entry: &str, roots: AssetRoots) -> Result<Entities, SceneError> {
    let text = format!("{HEADER}scene s {{\n    camera Pinhole {{}}\n    {entry}\n}}\n");
    let file = layout.inside().join("scene.rt");
    std::fs::write(&file, &text).unwrap();
    let checked = check_text(&file.display().to_string(), &text, &Options::default());
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
            asset_roots: roots,
            ..EntityOptions::default()
        },
    )
}

/// A string literal of the language holding `text`.
fn literal(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\""))
}

/// The scene entries naming `path` as a mesh, an image and a model.
fn entries(path: &str) -> [(&'static str, String); 3] {
    let lit = literal(path);
    [
        (
            "load_mesh",
            format!(
                "object o {{ geometry: load_mesh({lit}), material: UnlitTexture {{ texture: solid_texture(vec4f(1.0)) }} }}"
            ),
        ),
        (
            "load_image",
            format!(
                "object o {{ geometry: cube_mesh(), material: UnlitTexture {{ texture: load_image({lit}) }} }}"
            ),
        ),
        ("model", format!("model {lit} {{}}")),
    ]
}

/// Asserts the scene error is an escape reported as E0903 at the string, with a help line.
#[track_caller]
fn assert_e0903(err: &SceneError, what: &str) {
    assert!(
        matches!(
            err,
            SceneError::Asset {
                span: Some(_),
                source: AssetError::Escape { .. }
            }
        ),
        "{what}: {err:?}"
    );
    let diag = err.to_diagnostic().expect("a diagnostic");
    assert_eq!(diag.code.0, "E0903", "{what}");
    assert!(
        diag.help.iter().any(|h| h.contains("--asset-root")),
        "{what}: {diag:?}"
    );
    assert!(
        diag.notes.iter().any(|n| n.contains("scene.rt")),
        "{what}: {diag:?}"
    );
}

#[test]
fn scene_asset_paths_cannot_leave_the_scenes_folder() {
    let layout = Layout::new("confine-scene");
    for (kind, ext) in [
        ("load_mesh", "obj"),
        ("load_image", "png"),
        ("model", "glb"),
    ] {
        if ext == "glb" {
            let (b, pos, idx) = triangle();
            let glb = b.glb(one_node(
                json!([{ "attributes": { "POSITION": pos }, "indices": idx }]),
            ));
            std::fs::write(layout.outside().join("secret.glb"), glb).unwrap();
        }
        for (form, path) in escapes(&layout, ext) {
            let entry = entries(&path)
                .into_iter()
                .find(|(k, _)| *k == kind)
                .unwrap()
                .1;
            let err = build_scene(&layout, &entry, AssetRoots::none())
                .err()
                .unwrap_or_else(|| panic!("{kind} {form}: the escape loaded"));
            assert_e0903(&err, &format!("{kind} {form}"));
        }
        // Percent escapes mean nothing in a scene's path: `%2e%2e` is a folder name inside, so
        // the path names a missing file inside the scene's folder (E0902), never the secret.
        let entry = entries(&format!("%2e%2e/outside/secret.{ext}"))
            .into_iter()
            .find(|(k, _)| *k == kind)
            .unwrap()
            .1;
        let err = build_scene(&layout, &entry, AssetRoots::none())
            .err()
            .unwrap();
        let diag = err.to_diagnostic().expect("a diagnostic");
        assert_eq!(diag.code.0, "E0902", "{kind}: {diag:?}");
        assert!(diag.message.contains("inside"), "{kind}: {}", diag.message);
    }
}

#[test]
fn scene_assets_come_from_the_folder_or_an_asset_root() {
    let layout = Layout::new("confine-roots");
    let (b, pos, idx) = triangle();
    let glb = b.glb(one_node(
        json!([{ "attributes": { "POSITION": pos }, "indices": idx }]),
    ));
    std::fs::write(layout.outside().join("secret.glb"), glb).unwrap();
    let roots = || AssetRoots::new([layout.outside()]);
    for (kind, ext) in [
        ("load_mesh", "obj"),
        ("load_image", "png"),
        ("model", "glb"),
    ] {
        let pick = |path: &str| {
            entries(path)
                .into_iter()
                .find(|(k, _)| *k == kind)
                .unwrap()
                .1
        };
        // Found in the asset root by name, and through `..` into it.
        build_scene(&layout, &pick(&format!("secret.{ext}")), roots())
            .unwrap_or_else(|e| panic!("{kind} by name: {e}"));
        build_scene(&layout, &pick(&format!("../outside/secret.{ext}")), roots())
            .unwrap_or_else(|e| panic!("{kind} through ..: {e}"));
        // Without the root, by name it is simply missing (E0902).
        let err = build_scene(&layout, &pick(&format!("secret.{ext}")), AssetRoots::none())
            .err()
            .unwrap();
        assert_eq!(err.to_diagnostic().unwrap().code.0, "E0902", "{kind}");
        // The root does not make absolute paths acceptable.
        let abs = layout.outside().join(format!("secret.{ext}"));
        let err = build_scene(&layout, &pick(abs.to_str().unwrap()), roots())
            .err()
            .unwrap();
        assert_e0903(&err, kind);
        // Inside the scene's folder, `..` that stays inside is fine.
        std::fs::create_dir_all(layout.inside().join("sub")).unwrap();
        std::fs::copy(
            layout.outside().join(format!("secret.{ext}")),
            layout.inside().join(format!("mine.{ext}")),
        )
        .unwrap();
        build_scene(
            &layout,
            &pick(&format!("sub/../mine.{ext}")),
            AssetRoots::none(),
        )
        .unwrap_or_else(|e| panic!("{kind} inside: {e}"));
    }
}

/// A glTF model inside the scene's folder cannot use its buffers to reach outside either: E0903
/// at the `model` string, naming the glTF file and the buffer.
#[test]
fn a_models_buffer_escape_is_e0903_at_the_model_string() {
    let layout = Layout::new("confine-model-buf");
    gltf_with_buffer_uri(&layout, "../outside/secret.bin");
    let err = build_scene(&layout, "model \"model.gltf\" {}", AssetRoots::none())
        .err()
        .unwrap();
    let diag = err.to_diagnostic().unwrap();
    assert_eq!(diag.code.0, "E0903");
    assert!(diag.message.contains("buffers[0]"), "{}", diag.message);
    assert!(diag.message.contains("model.gltf"), "{}", diag.message);
}
