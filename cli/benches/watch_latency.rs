//! Edit-to-output latency of `rtc watch`: runs the `rtc` binary of this build (the bench profile:
//! optimised) on a copy of `examples/hello/scene.rt` with a 256x256 preview, edits the scene
//! `RTC_BENCH_EDITS` times (default 30; each edit changes the camera's field of view, a valid edit
//! that recompiles) and reads the latencies `rtc watch` reports for each reload:
//!
//! - edit to code: from the file's modification time to the kernel code and manifest written
//!   (includes the file-event delivery and the debounce, `--debounce-ms`, default 15 ms);
//! - edit to preview: the same, to the preview PNG written;
//! - round trip: measured here, from just before the write to the report line read from the pipe.
//!
//! Run with `cargo bench -p rtc --bench watch_latency`. `RTC_BENCH_SIZE` (default `256x256`),
//! `RTC_BENCH_SPP` (default 1) and `RTC_BENCH_ADAPTER` (default `auto`) change the preview. The
//! goals (issue 7) are under 50 ms to the code and under 300 ms to a 256x256 preview on lavapipe.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

fn env_or(name: &str, default: &str) -> String {
    std::env::var(name).unwrap_or_else(|_| default.to_owned())
}

/// The `X` of `label X ms` in `line`.
fn figure(line: &str, label: &str) -> Option<f64> {
    let rest = &line[line.find(label)? + label.len()..];
    rest.trim_start().split(' ').next()?.parse().ok()
}

fn stats(name: &str, values: &mut [f64]) {
    if values.is_empty() {
        println!("{name:<22} (no samples)");
        return;
    }
    values.sort_by(f64::total_cmp);
    let at = |q: f64| values[((values.len() - 1) as f64 * q).round() as usize];
    println!(
        "{name:<22} median {:>8.1} ms   p90 {:>8.1} ms   min {:>8.1} ms   max {:>8.1} ms   (n = {})",
        at(0.5),
        at(0.9),
        values[0],
        values[values.len() - 1],
        values.len()
    );
}

fn main() {
    // `cargo bench` passes `--bench`; any other argument is a filter we do not use.
    let edits: u32 = env_or("RTC_BENCH_EDITS", "30").parse().unwrap_or(30);
    let size = env_or("RTC_BENCH_SIZE", "256x256");
    let spp = env_or("RTC_BENCH_SPP", "1");
    let adapter = env_or("RTC_BENCH_ADAPTER", "auto");

    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let original = std::fs::read_to_string(root.join("examples/hello/scene.rt"))
        .expect("examples/hello/scene.rt");
    let dir: PathBuf = std::env::temp_dir().join(format!("rtc-watch-bench-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("scene.rt");
    std::fs::write(&file, &original).expect("write the scene");

    let mut child = Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(["--color", "never", "watch"])
        .arg(&file)
        .arg("--out")
        .arg(dir.join("out"))
        .arg("-o")
        .arg(dir.join("preview.png"))
        .args(["--size", &size, "--spp", &spp, "--adapter", &adapter])
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .expect("start rtc watch");
    let (tx, rx) = mpsc::channel::<String>();
    let stdout = child.stdout.take().expect("stdout");
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            if tx.send(line).is_err() {
                break;
            }
        }
    });
    let wait_for = |needle: &str| -> Vec<String> {
        let mut seen = Vec::new();
        loop {
            match rx.recv_timeout(Duration::from_secs(300)) {
                Ok(line) => {
                    let done = line.contains(needle);
                    seen.push(line);
                    if done {
                        return seen;
                    }
                }
                Err(e) => panic!(
                    "no `{needle}` from rtc watch ({e}); got:\n{}",
                    seen.join("\n")
                ),
            }
        }
    };
    wait_for("Ctrl-C to stop");

    let (mut code, mut preview, mut round_trip) = (Vec::new(), Vec::new(), Vec::new());
    let mut phases: Vec<Vec<String>> = Vec::new();
    for i in 0..edits {
        let fov = format!("fov: {}.0", 41 + i % 20);
        let text = original.replacen("fov: 40.0", &fov, 1);
        // Let the previous reload's writes settle, as between two saves of a person.
        std::thread::sleep(Duration::from_millis(100));
        let start = Instant::now();
        std::fs::write(&file, text).expect("edit");
        let lines = wait_for(&format!("[watch] #{} ", i + 2));
        let lines = [lines, wait_for("edit to")].concat();
        round_trip.push(start.elapsed().as_secs_f64() * 1e3);
        let last = lines.last().cloned().unwrap_or_default();
        assert!(
            last.contains(" ok"),
            "edit {i} failed:\n{}",
            lines.join("\n")
        );
        code.extend(figure(&last, "edit to code"));
        preview.extend(figure(&last, "edit to preview"));
        if i == edits / 2 {
            phases.push(lines);
        }
    }
    let _ = child.kill();
    let _ = child.wait();

    println!(
        "rtc watch latency, {edits} edits of examples/hello/scene.rt, preview {size} at {spp} spp"
    );
    stats("edit to code", &mut code);
    stats("edit to preview", &mut preview);
    stats("round trip (to report)", &mut round_trip);
    if let Some(lines) = phases.first() {
        println!("one reload's report:\n{}", lines.join("\n"));
    }
    let _ = std::fs::remove_dir_all(&dir);
}
