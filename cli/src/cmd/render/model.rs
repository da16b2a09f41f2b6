//! `rtc render model.gltf|model.glb`: a bare glTF file rendered through a scene written for it.
//!
//! The file is read once here to see what it lacks; then a scene is synthesised as `.rt` text with
//! one `model` entry (the file, by its name) plus the defaults it needs, and written to a fresh
//! temporary folder ([`SynthScene`], removed on drop) so it goes through the normal compile and
//! render path, with the model's folder as the first asset root ([`SynthScene::model_dir`]), so the
//! model and the files it names are confined to its folder as in any scene:
//! - **camera**: the file's first perspective camera if it has one, else a `Pinhole` framing the
//!   model's world-space bounds (from the front, [`ELEVATION_DEG`] above the centre, at the distance
//!   where the bounding sphere fills [`FRAME_FILL`] of a [`FOV_DEG`] vertical field of view);
//! - **light**: the file's `KHR_lights_punctual` lights if it has any, else a rig that lights what
//!   the camera sees ([`light_rig`]): a `DirectionalLight` headlight from just above and left of
//!   the camera (intensity π: a white diffuse surface facing it shows its albedo), and a dim one
//!   from straight above as sky fill (π/4), whichever side of the model the camera is on;
//! - **background**: always a `SkyGradient`;
//! - **settings**: [`DEFAULT_SIZE`] at [`DEFAULT_SAMPLES`] samples per pixel (`--size`, `--spp`
//!   override them as for any scene).
//!
//! Every default chosen is listed in [`SynthScene::defaults`], one sentence each, which
//! `rtc render` prints. A file that cannot be read is an error naming it (the loader's message).

use rtc_runtime::assets::model::{ModelScene, Projection};
use rtc_runtime::assets::{load_gltf_with, AssetError, AssetRoots};
use std::path::{Path, PathBuf};

/// Vertical field of view of the framing camera, degrees.
pub const FOV_DEG: f32 = 40.0;
/// How far above the model's centre the framing camera looks down from, degrees.
pub const ELEVATION_DEG: f32 = 20.0;
/// The fraction of the field of view the bounding sphere fills.
pub const FRAME_FILL: f32 = 0.9;
/// Image size of the synthesised scene.
pub const DEFAULT_SIZE: [u32; 2] = [640, 480];
/// Samples per pixel of the synthesised scene.
pub const DEFAULT_SAMPLES: u32 = 4;

/// Whether `path` names a glTF file (by extension).
pub fn is_model(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}

/// Why no scene could be made for a model.
#[derive(Debug, thiserror::Error)]
pub enum ModelError {
    /// The file cannot be read or is not valid glTF.
    #[error(transparent)]
    Asset(#[from] AssetError),
    /// The path cannot be written in a scene's string.
    #[error("`{}`: the path is not valid UTF-8, so it cannot be named in a scene", .0.display())]
    Path(PathBuf),
    /// The model has no camera and bounds too large to frame in `f32`.
    #[error(
        "`{}`: the model's bounds (from {min} to {max}) are too large to frame with a default \
         camera in `f32`; give the file a perspective camera, or render it from a scene with a \
         `camera` entry and a `transform` that scales the model down",
        path.display()
    )]
    Unframeable {
        /// The model file.
        path: PathBuf,
        /// The bounds' low corner, as text.
        min: String,
        /// The bounds' high corner, as text.
        max: String,
    },
    /// The temporary scene could not be written.
    #[error("cannot write the scene for the model to `{}`: {source}", path.display())]
    Write {
        /// The scene file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
}

/// A scene written for a model, in a temporary folder removed on drop.
#[derive(Debug)]
pub struct SynthScene {
    /// The scene file.
    pub path: PathBuf,
    /// The defaults chosen, one sentence each.
    pub defaults: Vec<String>,
    /// The model's folder (absolute): the scene names the model relative to it, so it must be
    /// the first asset root of the render.
    pub model_dir: PathBuf,
    dir: PathBuf,
}

impl SynthScene {
    /// The asset roots of its render: the model's folder first (the scene names the model
    /// relative to it), then `roots`.
    pub fn asset_roots(&self, roots: &AssetRoots) -> AssetRoots {
        AssetRoots::new(
            std::iter::once(self.model_dir.clone()).chain(roots.folders().iter().cloned()),
        )
    }
}

impl Drop for SynthScene {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// A string literal of the language holding `text`.
fn literal(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// `vec3f(x, y, z)` with enough digits to round-trip.
fn vec3(v: glam::Vec3) -> String {
    format!("vec3f({:?}, {:?}, {:?})", v.x, v.y, v.z)
}

/// The scene text for `model` (a file read as `data`) and the defaults it chose.
pub fn scene_text(model: &str, data: &ModelScene) -> (String, Vec<String>) {
    let mut defaults = Vec::new();
    let mut imports = vec!["std/miss/gradient.rt"];
    let mut entries = vec![
        format!(
            "    settings {{ width: {}, height: {}, samples: {} }}",
            DEFAULT_SIZE[0], DEFAULT_SIZE[1], DEFAULT_SAMPLES
        ),
        "    background SkyGradient {}".to_owned(),
    ];
    defaults.push("background: a sky gradient (SkyGradient)".to_owned());

    let has_camera = data
        .cameras
        .iter()
        .any(|c| matches!(c.projection, Projection::Perspective { .. }));
    let bounds = data.bounds();
    let (center, radius) = if bounds.is_empty() {
        (glam::Vec3::ZERO, 1.0)
    } else {
        let r = bounds.size().length() * 0.5;
        (bounds.center(), if r > 0.0 { r } else { 1.0 })
    };
    let elevation = ELEVATION_DEG.to_radians();
    let toward_camera = glam::Vec3::new(0.0, elevation.sin(), elevation.cos());
    if has_camera {
        defaults.push("camera: the file's first perspective camera".to_owned());
    } else {
        imports.push("std/cameras/pinhole.rt");
        let distance = radius / (FRAME_FILL * (FOV_DEG.to_radians() * 0.5).tan());
        let position = center + toward_camera * distance;
        entries.push(format!(
            "    camera Pinhole {{ position: {}, look_at: {}, fov: {FOV_DEG:?} }}",
            vec3(position),
            vec3(center)
        ));
        defaults.push(if bounds.is_empty() {
            format!(
                "camera: the file has none and no geometry; a Pinhole at {} looking at the origin",
                fmt3(position)
            )
        } else {
            format!(
                "camera: the file has none; a Pinhole framing the model's bounds (centre {}, \
                 radius {radius:.3}) from {} with a {FOV_DEG}° field of view",
                fmt3(center),
                fmt3(position)
            )
        });
    }
    if data.lights.is_empty() {
        imports.push("std/lights/directional.rt");
        // The camera the scene will use: the file's first perspective one, else the framing one.
        let (eye_forward, eye_up) = match data
            .cameras
            .iter()
            .find(|c| matches!(c.projection, Projection::Perspective { .. }))
        {
            Some(c) => (c.forward(), c.up()),
            None => (-toward_camera, glam::Vec3::Y),
        };
        let (key, fill) = light_rig(eye_forward, eye_up);
        entries.push(format!(
            "    light key DirectionalLight {{ direction: {}, intensity: {:?} }}",
            vec3(key),
            KEY_INTENSITY
        ));
        entries.push(format!(
            "    light fill DirectionalLight {{ direction: {}, intensity: {:?} }}",
            vec3(fill),
            FILL_INTENSITY
        ));
        defaults.push(format!(
            "light: the file has none; a DirectionalLight headlight from just above and left of \
             the camera, shining along {} (intensity π), and a dim DirectionalLight from above \
             as sky fill, shining along {} (intensity π/4)",
            fmt3(key),
            fmt3(fill)
        ));
    } else {
        defaults.push(format!(
            "lights: the file's {} KHR_lights_punctual light(s)",
            data.lights.len()
        ));
    }
    entries.push(format!("    model {} {{}}", literal(model)));

    let mut text = format!("// Written by `rtc render` for {}.\n", literal(model));
    for i in imports {
        text.push_str(&format!("import \"{i}\";\n"));
    }
    text.push_str("\nscene model {\n");
    for e in entries {
        text.push_str(&e);
        text.push('\n');
    }
    text.push_str("}\n");
    (text, defaults)
}

/// The default rig's headlight intensity: π, so a white diffuse surface facing it shows its albedo.
pub const KEY_INTENSITY: f32 = std::f32::consts::PI;
/// The default rig's sky fill intensity: a quarter of the headlight's.
pub const FILL_INTENSITY: f32 = std::f32::consts::FRAC_PI_4;
/// How far the headlight sits above and to the left of the camera's view direction, degrees.
pub const KEY_OFFSET_DEG: f32 = 20.0;

/// The default light rig for a camera looking along `forward` with `up` as its up: the
/// directions (of travel) of a headlight coming from [`KEY_OFFSET_DEG`] above and to the left of
/// the view direction, so that everything the camera sees faces it and shading still shows the
/// shape, and of a fill from straight above (the sky), so that what faces up is never black.
pub fn light_rig(forward: glam::Vec3, up: glam::Vec3) -> (glam::Vec3, glam::Vec3) {
    let forward = forward.normalize_or(glam::Vec3::NEG_Z);
    let right = forward.cross(up).normalize_or(glam::Vec3::X);
    let up = right.cross(forward);
    let offset = KEY_OFFSET_DEG.to_radians();
    // Toward the light: back toward the camera, tilted up and to the left.
    let toward = (-forward + (up - right) * offset.tan()).normalize();
    (-toward, glam::Vec3::NEG_Y)
}

fn fmt3(v: glam::Vec3) -> String {
    format!("({:.3}, {:.3}, {:.3})", v.x, v.y, v.z)
}

/// Reads the model at `path` (its buffers and images from its folder or `roots`) and writes a
/// scene for it into a fresh temporary folder.
pub fn synthesize(path: &Path, roots: &AssetRoots) -> Result<SynthScene, ModelError> {
    let data = load_gltf_with(path, roots)?;
    let has_camera = data
        .cameras
        .iter()
        .any(|c| matches!(c.projection, Projection::Perspective { .. }));
    let bounds = data.bounds();
    // The default camera stands back by the bounds' diagonal: it must stay finite.
    let reach = bounds.center().abs().max_element() + bounds.size().length() * 4.0;
    if !has_camera && !bounds.is_empty() && !reach.is_finite() {
        return Err(ModelError::Unframeable {
            path: path.to_path_buf(),
            min: format!("{:?}", bounds.min),
            max: format!("{:?}", bounds.max),
        });
    }
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let model = absolute
        .file_name()
        .and_then(|n| n.to_str())
        .ok_or_else(|| ModelError::Path(absolute.clone()))?;
    let model_dir = absolute.parent().map(Path::to_path_buf).unwrap_or_default();
    let (text, defaults) = scene_text(model, &data);
    let dir = unique_dir();
    let scene = dir.join("scene.rt");
    let written = std::fs::create_dir_all(&dir).and_then(|()| std::fs::write(&scene, &text));
    let synth = SynthScene {
        path: scene,
        defaults,
        model_dir,
        dir,
    };
    match written {
        Ok(()) => Ok(synth),
        Err(source) => Err(ModelError::Write {
            path: synth.path.clone(),
            source,
        }),
    }
}

/// A temporary folder name no other `rtc render` of this process or another uses.
fn unique_dir() -> PathBuf {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static NEXT: AtomicUsize = AtomicUsize::new(0);
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    std::env::temp_dir().join(format!(
        "rtc-model-{}-{nanos}-{}",
        std::process::id(),
        NEXT.fetch_add(1, Ordering::Relaxed)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gltf_extensions_are_recognised_case_insensitively() {
        assert!(is_model(Path::new("a.glb")));
        assert!(is_model(Path::new("dir/a.GLTF")));
        assert!(!is_model(Path::new("a.rt")));
        assert!(!is_model(Path::new("glb")));
    }

    #[test]
    fn paths_are_escaped_in_the_scene_string() {
        assert_eq!(literal(r#"a"b\c"#), r#""a\"b\\c""#);
    }

    #[test]
    fn an_empty_model_gets_every_default() {
        let (text, defaults) = scene_text("/m.glb", &ModelScene::default());
        assert!(text.contains("camera Pinhole"), "{text}");
        assert!(text.contains("light key DirectionalLight"), "{text}");
        assert!(text.contains("light fill DirectionalLight"), "{text}");
        assert!(text.contains("model \"/m.glb\" {}"), "{text}");
        assert_eq!(defaults.len(), 3, "{defaults:?}");
    }
}

#[cfg(test)]
mod rig_tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn the_headlight_faces_what_the_camera_sees_from_any_side() {
        for (forward, up) in [
            (Vec3::NEG_Z, Vec3::Y),
            (Vec3::Z, Vec3::Y),
            (Vec3::new(1.0, -1.0, 0.5), Vec3::Y),
            (Vec3::NEG_Y, Vec3::Z),
        ] {
            let (key, fill) = light_rig(forward, up);
            let f = forward.normalize();
            // A surface facing the camera (normal -forward) gets cos = dot(normal, -key).
            // The light comes from -forward tilted by tan(20°) up and tan(20°) left:
            // cos = 1 / sqrt(1 + 2 tan²(20°)) ≈ 0.889, whatever the view.
            let cos = (-f).dot(-key);
            let tan = KEY_OFFSET_DEG.to_radians().tan();
            let want = 1.0 / (1.0 + 2.0 * tan * tan).sqrt();
            assert!(
                (cos - want).abs() < 1e-5,
                "{forward}: cos {cos}, want {want}"
            );
            assert!((key.length() - 1.0).abs() < 1e-5);
            assert_eq!(fill, Vec3::NEG_Y);
        }
    }
}

#[cfg(test)]
mod link_tests {
    //! A bare glTF file's written scene is specialised like any other: compiled with the roots
    //! `rtc render` passes ([`SynthScene::asset_roots`]), the link step reads the file and links
    //! only what it holds plus the defaults the scene adds.
    use super::*;
    use rtc_compiler::driver::Options;
    use rtc_compiler::kernel::compile_scene;
    use rtc_compiler::link::{LinkOptions, ModelRead};

    /// A folder with `m.gltf` (one opaque triangle, no light, no camera) and its `m.bin`.
    fn model_dir() -> PathBuf {
        let dir = unique_dir();
        std::fs::create_dir_all(&dir).expect("a temporary folder");
        let bin: Vec<u8> = [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
            .iter()
            .flat_map(|x| x.to_le_bytes())
            .collect();
        std::fs::write(dir.join("m.bin"), bin).expect("m.bin");
        let gltf = r#"{
            "asset": {"version": "2.0"},
            "buffers": [{"uri": "m.bin", "byteLength": 36}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 0]}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "nodes": [{"mesh": 0}],
            "scenes": [{"nodes": [0]}],
            "scene": 0
        }"#;
        std::fs::write(dir.join("m.gltf"), gltf).expect("m.gltf");
        dir
    }

    /// The names of the linked types whose role is `role`.
    fn linked(c: &rtc_compiler::kernel::CompiledScene, role: &str) -> Vec<String> {
        let p = c.checked.program.as_ref().expect("a program");
        let mut names: Vec<String> = c
            .linked
            .types
            .iter()
            .filter(|(r, _)| r.name() == role)
            .flat_map(|(_, ts)| ts.iter().map(|t| p.structs[t.struct_id].name.clone()))
            .collect();
        names.sort();
        names
    }

    #[test]
    fn a_file_without_lights_links_the_default_light_and_nothing_else_it_lacks() {
        let dir = model_dir();
        let synth = synthesize(&dir.join("m.gltf"), &AssetRoots::none()).expect("a scene");
        let link = LinkOptions {
            asset_roots: synth.asset_roots(&AssetRoots::none()),
            ..LinkOptions::default()
        };
        let compiled = compile_scene(
            std::slice::from_ref(&synth.path),
            None,
            &Options::default(),
            &link,
        );
        let unlinked = compile_scene(
            std::slice::from_ref(&synth.path),
            None,
            &Options::default(),
            &LinkOptions::default(),
        );
        let _ = std::fs::remove_dir_all(&dir);
        let c = compiled.unwrap_or_else(|_| panic!("compile"));
        assert_eq!(linked(&c, "light"), ["DirectionalLight"]);
        assert_eq!(linked(&c, "material"), ["GltfMaterial"]);
        assert_eq!(linked(&c, "camera"), ["Pinhole"]);
        assert!(!c.linked.config.has_any_hit);
        assert!(
            matches!(&c.linked.models[0].read, ModelRead::Read(_)),
            "{:?}",
            c.linked.models
        );
        assert_eq!(c.linked.model_types, ["GltfMaterial"]);

        // Without the model's folder as a root the written scene's model is not found from the
        // temporary folder: everything a model may bring is linked.
        let u = unlinked.unwrap_or_else(|_| panic!("compile"));
        assert!(matches!(&u.linked.models[0].read, ModelRead::NotRead(_)));
        assert_eq!(
            linked(&u, "light"),
            ["DirectionalLight", "PointLight", "SpotLight"]
        );
    }
}
