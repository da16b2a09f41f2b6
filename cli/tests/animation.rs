//! End-to-end tests of `rtc render --frames/--fps/--shard` on lavapipe (skipped, saying so, where
//! no adapter exists): a tiny animated scene's frames rendered in three shards are byte-identical
//! to the unsharded run's; frames differ from one another; the animation builds no BLAS after the
//! setup; `--shard auto/N` reads `JOB_COMPLETION_INDEX` or `SLURM_ARRAY_TASK_ID`; bad arguments
//! are usage errors (exit code 2) with a message, and bad keys are located diagnostics.

mod common;

use common::{no_gpu, rtc, s, scratch, text};
use std::path::{Path, PathBuf};
use std::process::Command;

const SCENE: &str = r#"import "std/cameras/pinhole.rt";
import "std/materials/lambert.rt";
import "std/lights/point.rt";

scene tiny {
    settings { width: 24, height: 16, fps: 8 }
    camera Pinhole { position: vec3f(0.0, 1.5, 5.0), look_at: vec3f(0.0, 0.5, 0.0) }
    object floor { geometry: quad_mesh(), material: Lambert {}, transform: scale(4.0) }
    object box {
        geometry: cube_mesh(),
        material: Lambert { albedo: vec3f(0.8, 0.3, 0.2) },
        transform: translate(vec3f(0.0, 0.5, 0.0)) * scale(0.5),
    }
    light key PointLight { position: vec3f(2.0, 4.0, 3.0), intensity: 40.0 }
    animate box spin(vec3f(0.0, 1.0, 0.0), 60.0)
    animate box move(vec3f(0.2, 0.0, 0.0))
    animate camera.position keys smooth { 0.0: vec3f(0.0, 1.5, 5.0), 0.75: vec3f(2.0, 2.0, 4.0) }
    animate key.intensity keys { 0.0: 40.0, 0.75: 10.0 }
}
"#;

fn write_scene(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("tiny.rt");
    std::fs::write(&path, text).expect("write the scene");
    path
}

fn frame(dir: &Path, n: u32) -> Vec<u8> {
    std::fs::read(dir.join(format!("f_{n:03}.png"))).unwrap_or_else(|e| panic!("frame {n}: {e}"))
}

#[test]
fn sharded_frames_are_byte_identical_to_unsharded_ones() {
    let dir = scratch("animation", "shards");
    let scene = write_scene(&dir, SCENE);
    let whole = dir.join("whole");
    let parts = dir.join("parts");
    std::fs::create_dir_all(&whole).unwrap();
    std::fs::create_dir_all(&parts).unwrap();
    let pattern = |d: &Path| d.join("f_%03d.png");
    let out = rtc(&[
        "render",
        s(&scene),
        "--frames",
        "0..7",
        "-o",
        s(&pattern(&whole)),
    ]);
    if no_gpu(&out) {
        return;
    }
    let t = text(&out);
    assert!(out.status.success(), "{t}");
    assert!(t.contains("frames: 7 of 0..7 (shard 0/1) at 8 fps"), "{t}");
    assert!(
        t.contains("2 BLAS builds at setup, 0 over the frames after it; 8 TLAS builds"),
        "object motion rebuilds only the TLAS, once a frame: {t}"
    );
    for i in 0..3 {
        let shard = format!("{i}/3");
        let out = rtc(&[
            "render",
            s(&scene),
            "--frames",
            "0..7",
            "--shard",
            &shard,
            "-o",
            s(&pattern(&parts)),
        ]);
        assert!(out.status.success(), "{}", text(&out));
    }
    let mut names: Vec<String> = std::fs::read_dir(&parts)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let want: Vec<String> = (0..7).map(|n| format!("f_{n:03}.png")).collect();
    assert_eq!(names, want, "each frame once over the shards");
    for n in 0..7 {
        assert!(frame(&whole, n) == frame(&parts, n), "frame {n} differs");
    }
    for n in 1..7 {
        assert!(
            frame(&whole, n) != frame(&whole, n - 1),
            "frames {n} and {} are one image",
            n - 1
        );
    }
    // A still of the animated scene is its frame 0.
    let still = dir.join("still.png");
    let out = rtc(&["render", s(&scene), "-o", s(&still)]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(std::fs::read(&still).unwrap() == frame(&whole, 0));
}

#[test]
fn shard_auto_reads_the_job_index() {
    let dir = scratch("animation", "auto");
    let scene = write_scene(&dir, SCENE);
    for (var, index, frames) in [
        ("JOB_COMPLETION_INDEX", "1", [1, 4]),
        ("SLURM_ARRAY_TASK_ID", "2", [2, 5]),
    ] {
        let out_dir = dir.join(var);
        std::fs::create_dir_all(&out_dir).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_rtc"))
            .args([
                "render",
                s(&scene),
                "--frames",
                "0..6",
                "--shard",
                "auto/3",
                "-o",
            ])
            .arg(out_dir.join("f_%03d.png"))
            .env("XDG_RUNTIME_DIR", std::env::temp_dir())
            .env("NO_COLOR", "1")
            .env_remove("JOB_COMPLETION_INDEX")
            .env_remove("SLURM_ARRAY_TASK_ID")
            .env(var, index)
            .output()
            .expect("run rtc");
        if no_gpu(&out) {
            return;
        }
        assert!(out.status.success(), "{}", text(&out));
        let mut names: Vec<String> = std::fs::read_dir(&out_dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        let want: Vec<String> = frames.iter().map(|n| format!("f_{n:03}.png")).collect();
        assert_eq!(names, want, "{var}");
    }
}

#[test]
fn bad_frame_arguments_are_usage_errors() {
    let dir = scratch("animation", "usage");
    let scene = write_scene(&dir, SCENE);
    let pattern = dir.join("f_%03d.png");
    let plain = dir.join("f.png");
    let cases: [(&[&str], &Path, &str); 6] = [
        (&["--frames", "5..2"], &pattern, "holds no frame"),
        (&["--frames", "x..2"], &pattern, "not a frame number"),
        (&["--frames", "0..3"], &plain, "has no frame number"),
        (&["--shard", "3/3"], &pattern, "must be below the count 3"),
        (&["--shard", "0/0"], &pattern, "at least 1"),
        (&["--shard", "1-3"], &pattern, "write `I/N`"),
    ];
    for (extra, output, message) in cases {
        let mut args = vec!["render", s(&scene)];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["-o", s(output)]);
        let out = rtc(&args);
        let t = text(&out);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {t}");
        assert!(t.contains(message), "{extra:?}: {t}");
        assert!(!t.contains("panicked"), "{t}");
    }
    // `all` with the scene's 7 frames and no placeholder: refused after compiling, still a
    // usage error.
    let out = rtc(&["render", s(&scene), "--frames", "all", "-o", s(&plain)]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    // Bad keys are located diagnostics (exit 1), before any GPU work.
    let bad = SCENE.replace("0.75: vec3f(2.0, 2.0, 4.0)", "0.0: vec3f(2.0, 2.0, 4.0)");
    let scene = write_scene(&dir, &bad);
    let out = rtc(&["render", s(&scene), "--frames", "0..2", "-o", s(&pattern)]);
    let t = text(&out);
    assert_eq!(out.status.code(), Some(1), "{t}");
    assert!(t.contains("error[E0711]: two keys at one time"), "{t}");
    assert!(t.contains("tiny.rt:17:"), "{t}");
}
