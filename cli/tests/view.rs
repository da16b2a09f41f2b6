//! `rtc view` under a virtual X display (Xvfb) on the machine's adapter (lavapipe in CI): the window
//! opens, the image shown is written after every frame (`--screenshot`), each frame adds one pass
//! to the same accumulation (1, 2, 3 spp), a mouse drag (xdotool) moves the camera, is shown at half
//! the size (`--preview 2`) and restarts at 1 spp, a save of the scene reloads it keeping the moved
//! camera and the next screenshot shows the change; Ctrl-C (SIGINT) closes it with code 0. Without
//! a display it must say so and exit with code 1.
//!
//! The test starts its own Xvfb (`-displayfd` picks a free display). Where Xvfb, xdotool or a GPU
//! adapter is missing it is skipped with the reason printed, except in CI (`CI=true`), where that
//! fails.

use rtc_runtime::gpu::{AdapterChoice, Gpu};
use rtc_runtime::image_out::read_image;
use std::io::{BufRead, BufReader, Read};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

#[path = "../../runtime/tests/common/scratch.rs"]
mod scratch;

use scratch::Scratch;

const STEP: Duration = Duration::from_secs(240);

fn scene(background: &str) -> String {
    format!(
        r#"import "std/cameras/pinhole.rt";
import "std/materials/lambert.rt";
import "std/lights/point.rt";
import "std/miss/constant.rt";

scene viewed {{
    settings {{ width: 48, height: 48, samples: 3, max_depth: 1 }}
    camera Pinhole {{ position: vec3f(0.0, 1.0, 6.0), look_at: vec3f(0.0, 0.5, 0.0), fov: 30.0 }}
    background ConstantBackground {{ color: {background} }}
    object ball {{ geometry: sphere_mesh(1u), material: Lambert {{ albedo: vec3f(0.5) }} }}
    light key PointLight {{ position: vec3f(2.0, 4.0, 3.0), color: vec3f(1.0), intensity: 30.0 }}
}}
"#
    )
}

fn in_ci() -> bool {
    std::env::var("CI").as_deref() == Ok("true")
}

/// Skips (prints why and returns `true`) unless in CI, where it fails.
fn skip(reason: &str) -> bool {
    assert!(!in_ci(), "CI must run the view test: {reason}");
    eprintln!("skipped: {reason}");
    true
}

struct Killed(Child);

impl Drop for Killed {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// Starts Xvfb on a free display; returns it and the display name (`:N`).
fn start_xvfb() -> Option<(Killed, String)> {
    let mut child = Command::new("Xvfb")
        .args([
            "-displayfd",
            "1",
            "-screen",
            "0",
            "320x240x24",
            "-nolisten",
            "tcp",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let stdout = child.stdout.take()?;
    let mut line = String::new();
    BufReader::new(stdout).read_line(&mut line).ok()?;
    let n: u32 = line.trim().parse().ok()?;
    Some((Killed(child), format!(":{n}")))
}

fn collect(stream: impl Read + Send + 'static, lines: Arc<Mutex<Vec<String>>>) {
    std::thread::spawn(move || {
        for line in BufReader::new(stream).lines().map_while(Result::ok) {
            lines.lock().expect("lines").push(line);
        }
    });
}

fn wait_for(
    child: &mut Child,
    lines: &Arc<Mutex<Vec<String>>>,
    from: usize,
    needle: &str,
) -> usize {
    let start = Instant::now();
    loop {
        {
            let l = lines.lock().expect("lines");
            if let Some(i) = l[from..].iter().position(|x| x.contains(needle)) {
                return from + i;
            }
        }
        if let Ok(Some(status)) = child.try_wait() {
            std::thread::sleep(Duration::from_millis(200));
            panic!(
                "rtc view ended ({status}) before `{needle}`:\n{}",
                lines.lock().expect("lines").join("\n")
            );
        }
        assert!(
            start.elapsed() < STEP,
            "no `{needle}` after {STEP:?}:\n{}",
            lines.lock().expect("lines").join("\n")
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Mean linear red and blue of an image file.
fn red_blue(path: &Path) -> (f32, f32) {
    let image = read_image(path).expect("screenshot");
    let n = image.pixels().len().max(1) as f32;
    let (r, b) = image
        .pixels()
        .iter()
        .fold((0.0, 0.0), |(r, b), p| (r + p[0], b + p[2]));
    (r / n, b / n)
}

fn temp_dir(name: &str) -> Scratch {
    Scratch::new(&format!("view-{name}-{}", std::process::id()))
}

#[test]
fn view_shows_the_scene_and_a_reload_changes_the_screenshot() {
    if let Err(e) = Gpu::new(&AdapterChoice::default()) {
        skip(&format!("no GPU adapter ({e})"));
        return;
    }
    let Some((_xvfb, display)) = start_xvfb() else {
        skip("Xvfb is not installed (apt-get install xvfb)");
        return;
    };
    let dir = temp_dir("reload");
    let file = dir.join("scene.rt");
    let shot = dir.join("shot.png");
    std::fs::write(&file, scene("vec3f(0.0, 0.0, 1.0)")).expect("write");
    let runtime_dir = dir.join("xdg");
    std::fs::create_dir_all(&runtime_dir).expect("xdg dir");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["--color", "never", "view"])
        .arg(&file)
        .arg("--screenshot")
        .arg(&shot)
        // Every step during a camera move at half the width and height.
        .args(["--preview", "2"])
        .env("DISPLAY", &display)
        .env_remove("WAYLAND_DISPLAY")
        .env("XDG_RUNTIME_DIR", &runtime_dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start rtc view");
    let lines = Arc::new(Mutex::new(Vec::new()));
    collect(child.stdout.take().expect("stdout"), Arc::clone(&lines));
    collect(child.stderr.take().expect("stderr"), Arc::clone(&lines));
    let mut child = Killed(child);

    // Refined to the scene's 3 samples per pixel, one pass a frame: blue background.
    let at = wait_for(&mut child.0, &lines, 0, "[view] frame 1: 1 spp");
    let at = wait_for(&mut child.0, &lines, at, "[view] frame 2: 2 spp");
    let at = wait_for(
        &mut child.0,
        &lines,
        at,
        "[view] screenshot 3 of the window: 3 spp",
    );
    let (r, b) = red_blue(&shot);
    assert!(
        b > 0.3 && r < 0.5 * b,
        "expected mostly blue, got red {r}, blue {b}"
    );
    let file_camera = "[view] camera at (0.000, 1.000, 6.000) looking at (0.000, 0.500, 0.000)";
    assert!(
        lines.lock().expect("lines")[..at]
            .iter()
            .any(|l| l == file_camera),
        "the file's camera first"
    );

    // A drag orbits the camera: the accumulation restarts at one pass from the moved camera.
    let xdotool = |args: &[&str]| {
        Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &display)
            .stdout(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    if !xdotool(&["search", "--sync", "--name", "rtc view"]) {
        skip("xdotool is not installed or found no window (apt-get install xdotool)");
        return;
    }
    for step in [
        &["mousemove", "--sync", "24", "24"][..],
        &["mousedown", "1"],
        &["mousemove", "--sync", "34", "24"],
        &["mousemove", "--sync", "44", "26"],
        &["mouseup", "1"],
    ] {
        assert!(xdotool(step), "xdotool {step:?}");
    }
    // Each drag event restarts from its camera; settle on the last one, refined to 3 spp.
    let mut camera_at = wait_for(&mut child.0, &lines, at, "[view] camera at");
    let at = loop {
        let done = wait_for(&mut child.0, &lines, camera_at, "3 spp");
        std::thread::sleep(Duration::from_millis(300));
        let last = lines.lock().expect("lines")[..]
            .iter()
            .rposition(|l| l.starts_with("[view] camera at"))
            .expect("a camera line");
        if last == camera_at {
            break done;
        }
        camera_at = last;
    };
    let moved_camera = lines.lock().expect("lines")[camera_at].clone();
    assert_ne!(moved_camera, file_camera, "the drag moved the camera");
    let restarted = lines.lock().expect("lines")[camera_at..at].join("\n");
    assert!(
        restarted.contains(": 1/2 preview (24x24)")
            && restarted.contains(": 1 spp")
            && restarted.contains(": 2 spp"),
        "a move is shown at half the size, then the accumulation starts again at one pass:\n{restarted}"
    );

    // A save: the background turns red; the next frames show it, from the moved camera.
    std::fs::write(&file, scene("vec3f(1.0, 0.0, 0.0)")).expect("edit");
    let at = wait_for(&mut child.0, &lines, at, "[watch] #2 ok");
    let camera_at = wait_for(&mut child.0, &lines, at, "[view] camera at");
    assert_eq!(
        lines.lock().expect("lines")[camera_at],
        moved_camera,
        "a reload keeps the moved camera"
    );
    let at = wait_for(&mut child.0, &lines, camera_at, ": 3 spp");
    let shot_line = lines.lock().expect("lines")[at].clone();
    let frame: u32 = shot_line
        .trim_start_matches("[view] frame ")
        .split(':')
        .next()
        .and_then(|n| n.parse().ok())
        .expect("frame number");
    let at = wait_for(
        &mut child.0,
        &lines,
        at,
        &format!("[view] screenshot {frame} of the window"),
    );
    let (r, b) = red_blue(&shot);
    assert!(
        r > 0.3 && b < 0.5 * r,
        "expected mostly red after the reload, got red {r}, blue {b}"
    );

    // An invalid save keeps the window and the last image.
    std::fs::write(&file, scene("vec3f(1.0, 0.0,")).expect("edit");
    let at = wait_for(&mut child.0, &lines, at, "[watch] #3 failed");
    assert!(lines.lock().expect("lines")[..]
        .join("\n")
        .contains("error[E0"));

    // Ctrl-C closes it cleanly.
    let pid = child.0.id().to_string();
    assert!(Command::new("kill")
        .args(["-INT", &pid])
        .status()
        .expect("kill")
        .success());
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.0.try_wait().expect("wait") {
            break s;
        }
        assert!(start.elapsed() < STEP, "rtc view did not close on SIGINT");
        std::thread::sleep(Duration::from_millis(50));
    };
    std::thread::sleep(Duration::from_millis(200));
    let text = lines.lock().expect("lines")[at..].join("\n");
    assert!(status.success(), "exit status {status}: {text}");
    assert!(text.contains("[view] closed"), "{text}");
}

#[test]
fn an_animated_scene_plays_and_space_pauses_it_to_refine() {
    if let Err(e) = Gpu::new(&AdapterChoice::default()) {
        skip(&format!("no GPU adapter ({e})"));
        return;
    }
    let Some((_xvfb, display)) = start_xvfb() else {
        skip("Xvfb is not installed (apt-get install xvfb)");
        return;
    };
    let dir = temp_dir("animated");
    let file = dir.join("scene.rt");
    let animated = scene("vec3f(0.0, 0.0, 1.0)").replace(
        "    light key",
        "    animate ball move(vec3f(0.5, 0.0, 0.0))\n    light key",
    );
    let animated = animated.replace("samples: 3,", "samples: 3, fps: 24, frames: 48,");
    std::fs::write(&file, animated).expect("write");
    let runtime_dir = dir.join("xdg");
    std::fs::create_dir_all(&runtime_dir).expect("xdg dir");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["--color", "never", "view"])
        .arg(&file)
        .env("DISPLAY", &display)
        .env_remove("WAYLAND_DISPLAY")
        .env("XDG_RUNTIME_DIR", &runtime_dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start rtc view");
    let lines = Arc::new(Mutex::new(Vec::new()));
    collect(child.stdout.take().expect("stdout"), Arc::clone(&lines));
    collect(child.stderr.take().expect("stderr"), Arc::clone(&lines));
    let mut child = Killed(child);

    let at = wait_for(
        &mut child.0,
        &lines,
        0,
        "[view] the scene is animated: playing its 2.00 s",
    );
    // Playing: every frame is a fresh pass at a later time, never more than 1 spp.
    let at = wait_for(&mut child.0, &lines, at, "[view] frame 5:");
    let played = lines.lock().expect("lines")[..=at].join("\n");
    for n in 1..=5 {
        let line = played
            .lines()
            .find(|l| l.starts_with(&format!("[view] frame {n}:")))
            .expect("frame line");
        assert!(
            line.contains(": 1 spp,") && line.contains("playing at"),
            "{line}"
        );
    }
    // Space pauses: the paused frame refines to the scene's 3 spp.
    let key = Command::new("xdotool")
        .args([
            "search",
            "--sync",
            "--name",
            "rtc view",
            "windowfocus",
            "--sync",
        ])
        .env("DISPLAY", &display)
        .stdout(Stdio::null())
        .status()
        .and_then(|_| {
            // Without a window manager the window gets the keyboard by an explicit focus.
            Command::new("xdotool")
                .args(["mousemove", "--sync", "24", "24", "key", "space"])
                .env("DISPLAY", &display)
                .stdout(Stdio::null())
                .status()
        });
    if !key.is_ok_and(|s| s.success()) {
        skip("xdotool is not installed or found no window (apt-get install xdotool)");
        return;
    }
    let at = wait_for(&mut child.0, &lines, at, "[view] paused at");
    let at = wait_for(&mut child.0, &lines, at, ": 3 spp,");
    assert!(lines.lock().expect("lines")[at].contains("paused at"));
}

#[test]
fn view_without_a_display_says_so() {
    let dir = temp_dir("nodisplay");
    let file = dir.join("scene.rt");
    std::fs::write(&file, scene("vec3f(0.0)")).expect("write");
    let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["--color", "never", "view"])
        .arg(&file)
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("run");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("needs a display"), "{stderr}");
    assert!(
        !stderr.contains("ICE") && !stderr.contains("panicked"),
        "{stderr}"
    );
}
