//! `rtc watch` as a user runs it: a subprocess watching a scene in a temporary folder, driven
//! through edits (valid, invalid, fixed again, an import added and then removed; a glTF `model`
//! file gaining a light type) and stopped with SIGINT, the way Ctrl-C stops it. Each step waits for
//! the reload's report line (generous timeouts: the machines that run this are slow and shared) and
//! then checks the files and the messages. With an adapter, each report's kernel lines say whether
//! the preview's kernels were compiled or reused (the scene of the first build again reuses its
//! kernels; a scene left at `EXEC_AUTO` runs the wavefront model's stage kernels here).

use std::io::{BufRead, BufReader, Read};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant, SystemTime};

#[path = "../../runtime/tests/common/scratch.rs"]
mod scratch;

use scratch::Scratch;

/// How long one reload may take before the test gives up.
const STEP: Duration = Duration::from_secs(180);

const HEADER: &str = r#"import "std/cameras/pinhole.rt";
import "std/materials/lambert.rt";
import "std/materials/mirror.rt";
import "std/lights/point.rt";
import "std/miss/gradient.rt";
"#;

/// The scene, with `material` for the ball and `fov` for the camera.
fn scene(imports: &str, material: &str, fov: &str) -> String {
    format!(
        r#"{HEADER}{imports}
scene watched {{
    settings {{ width: 32, height: 32, samples: 1, max_depth: 2 }}
    camera Pinhole {{ position: vec3f(0.0, 1.5, 5.0), look_at: vec3f(0.0, 0.5, 0.0), fov: {fov} }}
    background SkyGradient {{}}
    let grey = Lambert {{ albedo: vec3f(0.5) }};
    object floor {{ geometry: quad_mesh(), material: grey, transform: scale(10.0) }}
    object ball {{ geometry: sphere_mesh(1u), material: {material}, transform: translate(vec3f(0.0, 1.0, 0.0)) }}
    light key PointLight {{ position: vec3f(2.0, 4.0, 3.0), color: vec3f(1.0), intensity: 30.0 }}
}}
"#
    )
}

/// A running `rtc watch` and every line it printed (stdout and stderr, in arrival order).
struct Watch {
    child: Child,
    lines: Arc<Mutex<Vec<String>>>,
}

impl Watch {
    fn start(scene: &Path, out: &Path, preview: &Path) -> Watch {
        let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
            .args(["--color", "never", "watch"])
            .arg(scene)
            .arg("--out")
            .arg(out)
            .arg("-o")
            .arg(preview)
            .args(["--size", "32x32", "--spp", "1", "--target", "wgsl,spirv"])
            .env("XDG_RUNTIME_DIR", std::env::temp_dir())
            .env("RTC_PIPELINE_CACHE", "off")
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("start rtc watch");
        let lines = Arc::new(Mutex::new(Vec::new()));
        let stdout = child.stdout.take().expect("stdout");
        let stderr = child.stderr.take().expect("stderr");
        collect(stdout, Arc::clone(&lines));
        collect(stderr, Arc::clone(&lines));
        Watch { child, lines }
    }

    fn count(&self) -> usize {
        self.lines.lock().expect("lines").len()
    }

    fn since(&self, from: usize) -> String {
        self.lines.lock().expect("lines")[from..].join("\n")
    }

    /// Waits until a line after `from` contains `needle`; panics with everything printed if not.
    fn wait_for(&mut self, from: usize, needle: &str) -> String {
        let start = Instant::now();
        loop {
            let text = self.since(from);
            if text.contains(needle) {
                return text;
            }
            if let Ok(Some(status)) = self.child.try_wait() {
                panic!("rtc watch ended ({status}) before `{needle}`:\n{text}");
            }
            assert!(
                start.elapsed() < STEP,
                "no `{needle}` after {STEP:?}; printed:\n{}",
                self.since(0)
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for Watch {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn collect(stream: impl Read + Send + 'static, lines: Arc<Mutex<Vec<String>>>) {
    std::thread::spawn(move || {
        for line in BufReader::new(stream).lines().map_while(Result::ok) {
            lines.lock().expect("lines").push(line);
        }
    });
}

/// The report's kernel lines (`rtc wf_shade  compiled  …  (driver … ms)`): under `rtc watch` a
/// scene left at `EXEC_AUTO` runs the wavefront model, five or six stage kernels.
fn kernel_lines(text: &str) -> Vec<&str> {
    let lines: Vec<&str> = text
        .lines()
        .filter(|l| l.trim_start().starts_with("rtc wf_") && l.contains("(driver "))
        .collect();
    assert!(!lines.is_empty(), "no kernel line in {text}");
    lines
}

/// `N` and `M` of the report's `kernels: N compiled, M reused`.
fn kernel_counts(text: &str) -> (u32, u32) {
    let line = text
        .lines()
        .find_map(|l| l.trim().strip_prefix("kernels: "))
        .unwrap_or_else(|| panic!("no kernels line in {text}"));
    let numbers: Vec<u32> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|n| n.parse().ok())
        .collect();
    match numbers[..] {
        [compiled, reused, ..] => (compiled, reused),
        _ => panic!("unreadable kernels line: {line}"),
    }
}

/// `N` and `M` of the report's `parse: N module(s) parsed, M from the cache`.
fn parse_counts(text: &str) -> (u32, u32) {
    let line = text
        .lines()
        .find_map(|l| l.trim().strip_prefix("parse: "))
        .unwrap_or_else(|| panic!("no parse line in {text}"));
    let numbers: Vec<u32> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    match numbers[..] {
        [parsed, cached] => (parsed, cached),
        _ => panic!("bad parse line `{line}`"),
    }
}

fn temp_dir(name: &str) -> Scratch {
    Scratch::new(&format!("watch-{name}-{}", std::process::id()))
}

fn modified(path: &Path) -> SystemTime {
    std::fs::metadata(path)
        .and_then(|m| m.modified())
        .expect("mtime")
}

/// Writes `text` and makes sure its modification time moves on even on a coarse clock.
fn edit(path: &Path, text: &str) {
    std::thread::sleep(Duration::from_millis(20));
    std::fs::write(path, text).expect("write");
}

#[test]
fn watch_follows_edits_keeps_good_outputs_and_tracks_imports() {
    let dir = temp_dir("edits");
    let file = dir.join("scene.rt");
    let out = dir.join("out");
    let preview = dir.join("preview.png");
    let lib = dir.join("lib.rt");
    std::fs::write(&file, scene("", "Mirror {}", "40.0")).expect("write");
    let mut w = Watch::start(&file, &out, &preview);

    // The first build writes the targets, the manifest and (with an adapter) the preview.
    let text = w.wait_for(0, "Ctrl-C to stop");
    assert!(text.contains("[watch] #1 first build"), "{text}");
    assert!(text.contains("[watch] #1 ok"), "{text}");
    assert!(text.contains("check the user's files"), "phases: {text}");
    let wgsl = out.join("kernel.wgsl");
    let spv = out.join("kernel.spv");
    let first_code = std::fs::read_to_string(&wgsl).expect("kernel.wgsl written");
    assert!(spv.is_file() && out.join("manifest.json").is_file());
    assert!(
        !out.join("kernel.hlsl").exists(),
        "only the targets asked for"
    );
    let has_gpu = text.contains("preview adapter:");
    if has_gpu {
        assert!(preview.is_file(), "{text}");
        // Five stage kernels: the shade stage traces the point light's shadow rays (one
        // traversal), so the scene has no shadow stage.
        assert_eq!(kernel_counts(&text), (5, 0), "{text}");
        assert!(
            kernel_lines(&text).iter().all(|l| l.contains("compiled")),
            "{text}"
        );
    } else {
        eprintln!("no adapter here: the preview is not checked\n{text}");
        assert!(text.contains("no preview"), "{text}");
    }

    // 1. A valid edit that changes the kernel: the ball is Lambert now, Mirror is no longer linked.
    let from = w.count();
    let preview_before = has_gpu.then(|| modified(&preview));
    edit(&file, &scene("", "grey", "40.0"));
    let text = w.wait_for(from, "[watch] #2 ok");
    assert!(
        text.contains("#2 changed: ") && text.contains("scene.rt"),
        "{text}"
    );
    assert!(text.contains("edit to code"), "{text}");
    // Parsed again: the scene and the generated `rtc:config` (its feature switches changed with the
    // materials); every other module (prelude, imports, the framework kernel) came from the cache.
    let (parsed, cached) = parse_counts(&text);
    assert!(
        parsed <= 2 && cached >= 10,
        "only the edited file is parsed again: {text}"
    );
    let second_code = std::fs::read_to_string(&wgsl).expect("kernel.wgsl");
    assert_ne!(first_code, second_code, "the kernel was emitted again");
    if let Some(before) = preview_before {
        assert!(
            modified(&preview) > before,
            "the preview was rendered again"
        );
        assert!(text.contains("edit to preview"), "{text}");
        let (compiled, reused) = kernel_counts(&text);
        assert!(compiled >= 1 && compiled + reused == 5, "{text}");
    }

    // 2. An invalid edit: diagnostics, and the outputs of #2 are left alone.
    let from = w.count();
    let code_time = modified(&wgsl);
    let preview_time = has_gpu.then(|| modified(&preview));
    edit(&file, &scene("", "grey", "40.0 +"));
    let text = w.wait_for(from, "[watch] #3 failed");
    assert!(text.contains("error[E0201]"), "{text}");
    assert!(text.contains("scene.rt:"), "file, line and column: {text}");
    assert!(text.contains("kept the last good outputs"), "{text}");
    assert_eq!(std::fs::read_to_string(&wgsl).expect("wgsl"), second_code);
    assert_eq!(modified(&wgsl), code_time, "kernel.wgsl was not rewritten");
    if let Some(t) = preview_time {
        assert_eq!(modified(&preview), t, "the preview was not rewritten");
    }

    // 3. Fixed again.
    let from = w.count();
    edit(&file, &scene("", "Mirror {}", "40.0"));
    let text = w.wait_for(from, "[watch] #4 ok");
    assert!(!text.contains("error"), "{text}");
    let fixed_code = std::fs::read_to_string(&wgsl).expect("wgsl");
    let diff = fixed_code
        .lines()
        .zip(first_code.lines())
        .find(|(a, b)| a != b);
    assert!(
        fixed_code == first_code,
        "the scene of #1 again, but other code: first difference {diff:?}\n{text}"
    );
    if has_gpu {
        // The kernels of #1 again: their pipelines are reused, not compiled.
        assert_eq!(kernel_counts(&text), (0, 5), "{text}");
        assert!(
            kernel_lines(&text)
                .iter()
                .all(|l| l.contains("reused (memory cache)")),
            "{text}"
        );
    }

    // 4. An import added: the new file is watched, and editing it alone reloads.
    let from = w.count();
    std::fs::write(&lib, "const FOV: f32 = 50.0;\n").expect("write lib");
    edit(&file, &scene("import \"lib.rt\";\n", "Mirror {}", "FOV"));
    let text = w.wait_for(from, "[watch] #5 ok");
    assert!(
        text.contains("now watching: ") && text.contains("lib.rt"),
        "{text}"
    );
    let from = w.count();
    edit(&lib, "const FOV: f32 = 55.0;\n");
    let text = w.wait_for(from, "[watch] #6 ok");
    assert!(
        text.contains("#6 changed: ") && text.contains("lib.rt"),
        "{text}"
    );
    assert!(!text.contains("scene.rt"), "only lib.rt changed: {text}");

    // 5. The import removed: lib.rt is no longer watched; editing it does nothing, editing the
    // scene still reloads.
    let from = w.count();
    edit(&file, &scene("", "Mirror {}", "40.0"));
    let text = w.wait_for(from, "[watch] #7 ok");
    assert!(
        text.contains("no longer watching: ") && text.contains("lib.rt"),
        "{text}"
    );
    let from = w.count();
    edit(&lib, "const FOV: f32 = 60.0;\n");
    std::thread::sleep(Duration::from_secs(2));
    edit(&file, &scene("", "grey", "40.0"));
    let text = w.wait_for(from, "[watch] #8 ok");
    assert!(
        !text.contains("lib.rt"),
        "an unwatched file caused a reload: {text}"
    );

    // 6. Ctrl-C (SIGINT) ends the watch cleanly, with exit code 0.
    let from = w.count();
    let pid = w.child.id().to_string();
    let killed = Command::new("kill")
        .args(["-INT", &pid])
        .status()
        .expect("kill");
    assert!(killed.success());
    let start = Instant::now();
    let status = loop {
        if let Some(status) = w.child.try_wait().expect("wait") {
            break status;
        }
        assert!(start.elapsed() < STEP, "rtc watch did not stop on SIGINT");
        std::thread::sleep(Duration::from_millis(50));
    };
    // The reader threads may still be draining the pipes.
    std::thread::sleep(Duration::from_millis(200));
    assert!(status.success(), "exit status {status}: {}", w.since(from));
    assert!(w.since(from).contains("[watch] stopped"), "{}", w.since(0));
}

#[test]
fn a_scene_that_fails_from_the_start_is_still_watched() {
    let dir = temp_dir("broken");
    let file = dir.join("scene.rt");
    let out = dir.join("out");
    std::fs::write(&file, scene("import \"missing.rt\";\n", "grey", "40.0")).expect("write");
    let mut w = Watch::start(&file, &out, &dir.join("p.png"));
    let text = w.wait_for(0, "[watch] #1 failed");
    assert!(text.contains("missing.rt"), "{text}");
    // The folders are watched from this line on; a file created before it is not seen (CI once
    // wrote `missing.rt` between the failed build and the watch).
    w.wait_for(0, "[watch] watching");
    assert!(
        !out.join("kernel.wgsl").exists(),
        "nothing written on error"
    );
    // Creating the missing import fixes it.
    let from = w.count();
    std::fs::write(dir.join("missing.rt"), "const UNUSED: f32 = 1.0;\n").expect("write");
    let text = w.wait_for(from, "[watch] #2 ok");
    assert!(text.contains("missing.rt"), "{text}");
    assert!(out.join("kernel.wgsl").is_file());
}

#[test]
fn bad_arguments_are_usage_errors() {
    let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["watch", "no/such/scene.rt"])
        .output()
        .expect("run");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no/such/scene.rt"));
    let dir = temp_dir("args");
    let file = dir.join("scene.rt");
    std::fs::write(&file, scene("", "grey", "40.0")).expect("write");
    let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .arg("watch")
        .arg(&file)
        .args(["-o", "preview.jpg"])
        .output()
        .expect("run");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains(".png"));
}

/// A `.gltf` (with its buffer as a `data:` URI) of one triangle and one light of each `lights` type.
fn model_gltf(lights: &[&str]) -> String {
    // The triangle (0,0,0), (1,0,0), (0,1,0) as 36 bytes of little-endian f32, in base64.
    const POSITIONS: &str = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    let list: Vec<String> = lights
        .iter()
        .map(|t| match *t {
            "spot" => r#"{"type": "spot", "spot": {}}"#.to_owned(),
            t => format!(r#"{{"type": "{t}"}}"#),
        })
        .collect();
    let mut nodes = vec![r#"{"mesh": 0}"#.to_owned()];
    nodes.extend((0..lights.len()).map(|i| {
        format!(r#"{{"translation": [0, 2, 1], "extensions": {{"KHR_lights_punctual": {{"light": {i}}}}}}}"#)
    }));
    format!(
        r#"{{"asset": {{"version": "2.0"}},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {{"KHR_lights_punctual": {{"lights": [{lights}]}}}},
  "buffers": [{{"uri": "data:application/octet-stream;base64,{POSITIONS}", "byteLength": 36}}],
  "bufferViews": [{{"buffer": 0, "byteLength": 36}}],
  "accessors": [{{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                  "min": [0, 0, 0], "max": [1, 1, 0]}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
  "nodes": [{nodes}],
  "scenes": [{{"nodes": [{indices}]}}],
  "scene": 0}}"#,
        lights = list.join(", "),
        nodes = nodes.join(", "),
        indices = (0..nodes.len())
            .map(|i| i.to_string())
            .collect::<Vec<_>>()
            .join(", "),
    )
}

/// The link step reads which light types a model file holds, so an edit to the file compiles again
/// (it is not an "assets only" reload) and the new light type's program is emitted.
#[test]
fn a_model_file_gaining_a_light_type_compiles_again() {
    let dir = temp_dir("model");
    let file = dir.join("scene.rt");
    let out = dir.join("out");
    let model = dir.join("m.gltf");
    std::fs::write(&model, model_gltf(&["point"])).expect("write");
    std::fs::write(
        &file,
        "import \"std/cameras/pinhole.rt\";\n\
         scene s {\n    camera Pinhole { position: vec3f(0.3, 0.3, 3.0), look_at: vec3f(0.3, 0.3, 0.0) }\n    model \"m.gltf\" {}\n}\n",
    )
    .expect("write");
    let mut w = Watch::start(&file, &out, &dir.join("p.png"));
    let text = w.wait_for(0, "Ctrl-C to stop");
    assert!(text.contains("[watch] #1 ok"), "{text}");
    let wgsl = out.join("kernel.wgsl");
    let first = std::fs::read_to_string(&wgsl).expect("kernel.wgsl");
    assert!(
        first.contains("point_light") && !first.contains("spot_light"),
        "only the point light is linked"
    );

    let from = w.count();
    edit(&model, &model_gltf(&["point", "spot"]));
    let text = w.wait_for(from, "[watch] #2 ok");
    assert!(!text.contains("only assets changed"), "{text}");
    assert!(!text.contains("internal error"), "{text}");
    let second = std::fs::read_to_string(&wgsl).expect("kernel.wgsl");
    assert!(
        second.contains("spot_light"),
        "the spot light is linked now"
    );
}
