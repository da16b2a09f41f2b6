//! `rtc bench --compile [PATH] [--exec MODEL]`: time to first pixel with a cold driver cache, and
//! the time from a one-line material edit to the new preview.
//!
//! What is measured, each in a **child process** of this same `rtc` (so every measurement starts
//! with a fresh driver) with `MESA_SHADER_CACHE_DISABLE=true` (Mesa reads it when the driver
//! loads, hence the child), `__GL_SHADER_DISK_CACHE=0` (NVIDIA's driver's, for a lent GPU) and
//! `RTC_PIPELINE_CACHE=off`:
//! - **cold**: for every example (`PATH` is a folder of folders holding a `scene.rt`, default
//!   `examples`; or one scene file), `rtc render scene.rt --size 64x48 --spp 1`: the child's wall
//!   time from start to exit (time to first pixel: compile, assets, BVHs, pipelines, render, PNG)
//!   and what its summary reports: the pipelines' milliseconds and one line per kernel;
//! - **edit**: the thesis scene (`PATH/thesis_scene`, when present) copied to a temporary folder
//!   with its Blinn-Phong material copied beside it, run under `rtc watch` with a 64x48 preview;
//!   after the first build one constant of the material's code changes (`INV_PI / 8.0` becomes
//!   `INV_PI / 9.0`), and the watch reports the edit-to-preview time and which kernels it
//!   compiled and which it reused.
//!
//! `RTC_BENCH_RUNNER` (a command prefix, e.g. `bash docs/bench/current_lavapipe.sh`) starts every
//! child through another program, so the same benchmark measures another driver.
//!
//! Each measurement runs once per execution model (`--exec`, default both), passed to the child
//! `rtc render --exec` / `rtc watch --exec`, as is `--cpu-jit` (default `auto`, with which these
//! 64x48 1-spp children get lavapipe's quick JIT; `--cpu-jit optimized` measures the optimised
//! compile). Each cold row says which JIT its child used (its summary's host line). Prints a table; `--json FILE` writes every figure. No
//! figure is invented: a child that fails is a row with its error.

use super::super::Context;
use crate::exit::Exit;
use crate::{report, term};
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// The execution models `--exec` accepts (`rtc render --exec`'s values).
pub const EXEC_MODELS: &[&str] = &["megakernel", "wavefront"];

/// The preview size of every measurement.
const SIZE: &str = "64x48";

/// The material edit: this text of `std/materials/blinn_phong.rt` becomes the second.
const EDIT: (&str, &str) = ("(INV_PI / 8.0)", "(INV_PI / 9.0)");

/// One kernel line of a summary.
#[derive(Clone, Debug, PartialEq)]
pub struct KernelLine {
    /// The kernel's label.
    pub label: String,
    /// `compiled`, `reused (memory cache)`, `reused (disk cache)`.
    pub origin: String,
    /// Milliseconds in all.
    pub total_ms: f64,
    /// Milliseconds of the driver.
    pub driver_ms: f64,
}

/// The cold render of one example.
#[derive(Clone, Debug, PartialEq)]
pub struct ColdRow {
    /// The example's folder name (or the scene file's stem).
    pub example: String,
    /// The execution model.
    pub exec: String,
    /// Wall milliseconds of the child `rtc render`.
    pub first_pixel_ms: f64,
    /// The summary's `pipelines` figure.
    pub pipelines_ms: Option<f64>,
    /// The summary's kernel lines.
    pub kernels: Vec<KernelLine>,
    /// Whether the child's kernels were compiled by a quick JIT (its host line names
    /// `GALLIVM_PERF=nopt`); `None` without a host line.
    pub quick_jit: Option<bool>,
    /// Why the child failed, if it did.
    pub error: Option<String>,
}

/// The material edit under `rtc watch`.
#[derive(Clone, Debug, PartialEq)]
pub struct EditRow {
    /// The execution model.
    pub exec: String,
    /// The first build's "prepare preview (scene, pipelines)" milliseconds.
    pub first_prepare_ms: Option<f64>,
    /// The second build's edit-to-preview milliseconds.
    pub edit_to_preview_ms: Option<f64>,
    /// The second build's kernel lines.
    pub kernels: Vec<KernelLine>,
    /// Why it failed, if it did.
    pub error: Option<String>,
}

/// Everything `rtc bench --compile` measured.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Report {
    /// One row per example and model.
    pub cold: Vec<ColdRow>,
    /// One row per model (none when there is no thesis scene).
    pub edit: Vec<EditRow>,
}

/// The scenes under `path`: each sub-folder's `scene.rt` in name order, or `path` itself when it
/// is a file.
pub fn scenes(path: &Path) -> Result<Vec<(String, PathBuf)>, String> {
    if path.is_file() {
        let name = path
            .file_stem()
            .map_or_else(|| "scene".to_string(), |s| s.to_string_lossy().into_owned());
        return Ok(vec![(name, path.to_path_buf())]);
    }
    let entries = std::fs::read_dir(path)
        .map_err(|e| format!("cannot read the folder `{}`: {e}", path.display()))?;
    let mut out: Vec<(String, PathBuf)> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.join("scene.rt").is_file())
        .map(|p| {
            let name = p
                .file_name()
                .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
            (name, p.join("scene.rt"))
        })
        .collect();
    out.sort();
    if out.is_empty() {
        return Err(format!(
            "`{}` holds no folder with a `scene.rt`",
            path.display()
        ));
    }
    Ok(out)
}

/// A command prefix that runs each child (words split at whitespace), e.g. `bash
/// docs/bench/current_lavapipe.sh` to measure another Mesa release; unset or empty: none.
pub const RUNNER_ENV: &str = "RTC_BENCH_RUNNER";

/// A child `rtc` with the cold-cache environment, started through [`RUNNER_ENV`] when it is set.
fn child(exe: &Path) -> Command {
    let runner = std::env::var(RUNNER_ENV).unwrap_or_default();
    let mut words = runner.split_whitespace();
    let mut cmd = match words.next() {
        Some(program) => {
            let mut c = Command::new(program);
            c.args(words).arg(exe);
            c
        }
        None => Command::new(exe),
    };
    // The child chooses lavapipe's defaults for the driver it runs on (the runner may give it
    // another Mesa release), so what this process set for itself is not passed on.
    for name in rtc_runtime::gpu::lavapipe_defaults_applied() {
        cmd.env_remove(name);
    }
    cmd.env("MESA_SHADER_CACHE_DISABLE", "true")
        .env("__GL_SHADER_DISK_CACHE", "0")
        .env(rtc_runtime::gpu::PIPELINE_CACHE_ENV, "off")
        .args(["--color", "never"]);
    cmd
}

/// Whether `exe`, this process's executable, is a dynamic loader (`ld-linux-x86-64.so.2` and the
/// like) rather than rtc: a process started as `ld.so PROGRAM ARGS`, as
/// docs/bench/current_lavapipe.sh starts one, has the loader as its executable.
fn started_by_a_loader(exe: &Path) -> bool {
    exe.file_name()
        .and_then(|n| n.to_str())
        .is_some_and(|n| n.starts_with("ld-") || n.starts_with("ld.so"))
}

/// `--exec MODEL --cpu-jit JIT` for a child `rtc render`/`watch`.
fn model_args<'a>(exec: &'a str, jit: &'a str) -> [&'a str; 4] {
    ["--exec", exec, "--cpu-jit", jit]
}

/// Whether a summary's `host:` line says the kernels had the quick JIT.
fn host_quick_jit(line: &str) -> Option<bool> {
    let host = line.strip_prefix("host: ")?;
    Some(host.contains(&format!(
        "{}={}",
        rtc_runtime::gpu::JIT_VAR,
        rtc_runtime::gpu::QUICK_JIT
    )))
}

/// Renders `scene` in a child and reads its summary.
pub fn cold(
    exe: &Path,
    name: &str,
    scene: &Path,
    exec: &str,
    jit: &str,
    scratch: &Path,
) -> ColdRow {
    let output = scratch.join(format!("{name}.png"));
    let start = Instant::now();
    let result = child(exe)
        .arg("render")
        .arg(scene)
        .arg("-o")
        .arg(&output)
        .args(["--size", SIZE, "--spp", "1"])
        .args(model_args(exec, jit))
        .output();
    let first_pixel_ms = start.elapsed().as_secs_f64() * 1e3;
    let mut row = ColdRow {
        example: name.to_string(),
        exec: exec.to_string(),
        first_pixel_ms,
        pipelines_ms: None,
        kernels: Vec::new(),
        quick_jit: None,
        error: None,
    };
    match result {
        Err(e) => row.error = Some(format!("cannot run rtc: {e}")),
        Ok(out) => {
            let stdout = String::from_utf8_lossy(&out.stdout);
            if !out.status.success() {
                let stderr = String::from_utf8_lossy(&out.stderr);
                row.error = Some(last_line(&stderr, &out.status.to_string()));
            }
            row.pipelines_ms = stdout.lines().find_map(pipelines_ms);
            row.kernels = stdout.lines().filter_map(kernel_line).collect();
            row.quick_jit = stdout.lines().find_map(host_quick_jit);
        }
    }
    row
}

fn last_line(text: &str, fallback: &str) -> String {
    text.lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .map_or_else(|| fallback.to_string(), |l| l.trim().to_string())
}

/// The figure of a summary's `  pipelines   123.45 ms  (...)` line.
pub fn pipelines_ms(line: &str) -> Option<f64> {
    let rest = line.trim_start().strip_prefix("pipelines")?;
    rest.split_whitespace().next()?.parse().ok()
}

/// A kernel line of `rtc render`'s or `rtc watch`'s report (`render::kernel_lines`).
pub fn kernel_line(line: &str) -> Option<KernelLine> {
    let line = line.trim();
    let driver = line.strip_suffix(" ms)")?;
    let (head, driver) = driver.rsplit_once("(driver ")?;
    let fields: Vec<&str> = head
        .split("  ")
        .map(str::trim)
        .filter(|f| !f.is_empty())
        .collect();
    let [label, origin, total] = fields.as_slice() else {
        return None;
    };
    Some(KernelLine {
        label: (*label).to_string(),
        origin: (*origin).to_string(),
        total_ms: total.strip_suffix(" ms")?.trim().parse().ok()?,
        driver_ms: driver.trim().parse().ok()?,
    })
}

/// Copies the thesis scene and its material to `dir` and makes the scene import the copy.
fn prepare_edit(thesis: &Path, stdlib: &Path, dir: &Path) -> Result<PathBuf, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create `{}`: {e}", dir.display()))?;
    let folder = thesis.parent().unwrap_or(Path::new("."));
    let entries = std::fs::read_dir(folder)
        .map_err(|e| format!("cannot read `{}`: {e}", folder.display()))?;
    for entry in entries.filter_map(Result::ok) {
        let from = entry.path();
        if from.is_file() {
            let to = dir.join(entry.file_name());
            std::fs::copy(&from, &to)
                .map_err(|e| format!("cannot copy `{}`: {e}", from.display()))?;
        }
    }
    let material = stdlib.join("materials").join("blinn_phong.rt");
    let text = std::fs::read_to_string(&material)
        .map_err(|e| format!("cannot read `{}`: {e}", material.display()))?;
    if !text.contains(EDIT.0) {
        return Err(format!(
            "`{}` no longer contains `{}`, the constant the edit changes",
            material.display(),
            EDIT.0
        ));
    }
    write(&dir.join("blinn_phong.rt"), &text)?;
    let scene = dir.join("scene.rt");
    let source = std::fs::read_to_string(&scene)
        .map_err(|e| format!("cannot read `{}`: {e}", scene.display()))?;
    let import = "import \"std/materials/blinn_phong.rt\";";
    if !source.contains(import) {
        return Err(format!("the thesis scene no longer has `{import}`"));
    }
    write(
        &scene,
        &source.replace(import, "import \"blinn_phong.rt\";"),
    )?;
    Ok(scene)
}

fn write(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("cannot write `{}`: {e}", path.display()))
}

/// Runs `rtc watch` on a copy of the thesis scene, edits its material after the first build and
/// reads the second build's report.
pub fn edit(
    exe: &Path,
    thesis: &Path,
    stdlib: &Path,
    exec: &str,
    jit: &str,
    scratch: &Path,
) -> EditRow {
    let mut row = EditRow {
        exec: exec.to_string(),
        first_prepare_ms: None,
        edit_to_preview_ms: None,
        kernels: Vec::new(),
        error: None,
    };
    if let Err(e) = run_edit(exe, thesis, stdlib, exec, jit, scratch, &mut row) {
        row.error = Some(e);
    }
    row
}

fn run_edit(
    exe: &Path,
    thesis: &Path,
    stdlib: &Path,
    exec: &str,
    jit: &str,
    scratch: &Path,
    row: &mut EditRow,
) -> Result<(), String> {
    let dir = scratch.join(format!("edit-{exec}"));
    let scene = prepare_edit(thesis, stdlib, &dir)?;
    let mut proc = child(exe)
        .arg("watch")
        .arg(&scene)
        .arg("--out")
        .arg(dir.join("out"))
        .arg("-o")
        .arg(dir.join("preview.png"))
        .args(["--size", SIZE, "--spp", "1", "--target", "wgsl"])
        .args(["--exit-after", "2"])
        .args(model_args(exec, jit))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot run rtc watch: {e}"))?;
    let (tx, rx) = mpsc::channel::<String>();
    if let Some(out) = proc.stdout.take() {
        let tx = tx.clone();
        std::thread::spawn(move || {
            for line in BufReader::new(out).lines().map_while(Result::ok) {
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
    }
    let mut stderr = String::new();
    let err_reader = proc.stderr.take().map(|mut e| {
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = e.read_to_string(&mut text);
            text
        })
    });
    drop(tx);
    let mut lines = Vec::new();
    let mut edited = false;
    // A cold compile of the thesis kernel takes seconds to minutes on a shared CPU.
    let deadline = Instant::now() + Duration::from_secs(1800);
    loop {
        let wait = deadline.saturating_duration_since(Instant::now());
        match rx.recv_timeout(wait) {
            Ok(line) => {
                if !edited && line.starts_with("[watch] #1 failed") {
                    lines.push(line);
                    let _ = proc.kill();
                    break;
                }
                if !edited && line.starts_with("[watch] #1 ok") {
                    // A later modification time than the first build's files.
                    std::thread::sleep(Duration::from_millis(50));
                    let material = dir.join("blinn_phong.rt");
                    let text = std::fs::read_to_string(&material)
                        .map_err(|e| format!("cannot read `{}`: {e}", material.display()))?;
                    write(&material, &text.replacen(EDIT.0, EDIT.1, 1))?;
                    edited = true;
                }
                lines.push(line);
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => break,
            Err(mpsc::RecvTimeoutError::Timeout) => {
                let _ = proc.kill();
                return Err("rtc watch took more than 30 minutes".to_string());
            }
        }
    }
    let status = proc.wait().map_err(|e| format!("rtc watch: {e}"))?;
    if let Some(handle) = err_reader {
        stderr = handle.join().unwrap_or_default();
    }
    let second = lines
        .iter()
        .position(|l| l.starts_with("[watch] #2 "))
        .unwrap_or(lines.len());
    row.first_prepare_ms = lines[..second]
        .iter()
        .find_map(|l| phase_ms(l, "prepare preview"));
    row.kernels = lines[second..]
        .iter()
        .filter_map(|l| kernel_line(l))
        .collect();
    row.edit_to_preview_ms = lines[second..].iter().find_map(|l| edit_to_preview(l));
    if !status.success() || row.edit_to_preview_ms.is_none() {
        return Err(last_line(
            &stderr,
            &format!("rtc watch ended ({status}) without a second preview"),
        ));
    }
    Ok(())
}

/// The milliseconds of a watch phase line starting with `name`.
fn phase_ms(line: &str, name: &str) -> Option<f64> {
    let rest = line.trim_start().strip_prefix(name)?;
    let figure = rest.trim_end().strip_suffix(" ms")?;
    figure.split_whitespace().last()?.parse().ok()
}

/// The figure of `edit to preview 123.4 ms` in a watch status line.
fn edit_to_preview(line: &str) -> Option<f64> {
    let (_, rest) = line.split_once("edit to preview ")?;
    rest.split_whitespace().next()?.parse().ok()
}

fn jit_name(quick: Option<bool>) -> &'static str {
    match quick {
        Some(true) => "quick",
        Some(false) => "optimized",
        None => "-",
    }
}

fn seconds(ms: Option<f64>) -> String {
    ms.map_or_else(|| "-".to_string(), |ms| format!("{:.2}", ms / 1e3))
}

/// The table printed on stdout.
pub fn table(report: &Report) -> String {
    let mut out = String::from(
        "cold compile (MESA_SHADER_CACHE_DISABLE=true, __GL_SHADER_DISK_CACHE=0, RTC_PIPELINE_CACHE=off, 64x48, 1 spp; \
         jit: the child's, from its host line):\n",
    );
    let width = report
        .cold
        .iter()
        .map(|r| r.example.len())
        .max()
        .unwrap_or(7)
        .max(7);
    out.push_str(&format!(
        "  {:<width$}  {:<10}  {:<9}  {:>13}  {:>13}  {:>8}  {}\n",
        "example",
        "exec",
        "jit",
        "first pixel s",
        "pipelines s",
        "kernels",
        "slowest kernel (driver s)"
    ));
    for r in &report.cold {
        let slowest = r
            .kernels
            .iter()
            .max_by(|a, b| a.driver_ms.total_cmp(&b.driver_ms))
            .map_or_else(String::new, |k| {
                format!("{} {:.2}", k.label, k.driver_ms / 1e3)
            });
        out.push_str(&format!(
            "  {:<width$}  {:<10}  {:<9}  {:>13.2}  {:>13}  {:>8}  {}\n",
            r.example,
            r.exec,
            jit_name(r.quick_jit),
            r.first_pixel_ms / 1e3,
            seconds(r.pipelines_ms),
            r.kernels.len(),
            match &r.error {
                Some(e) => format!("failed: {e}"),
                None => slowest,
            }
        ));
    }
    for e in &report.edit {
        out.push_str(&format!(
            "material edit (thesis scene under rtc watch, {}): first build's preview setup {} s, \
             edit to new preview {} s\n",
            e.exec,
            seconds(e.first_prepare_ms),
            seconds(e.edit_to_preview_ms)
        ));
        for k in &e.kernels {
            out.push_str(&format!(
                "  {}: {} ({:.2} s, driver {:.2} s)\n",
                k.label,
                k.origin,
                k.total_ms / 1e3,
                k.driver_ms / 1e3
            ));
        }
        if let Some(err) = &e.error {
            out.push_str(&format!("  failed: {err}\n"));
        }
    }
    out
}

fn kernels_json(kernels: &[KernelLine]) -> serde_json::Value {
    kernels
        .iter()
        .map(|k| {
            serde_json::json!({
                "label": k.label,
                "origin": k.origin,
                "total_ms": k.total_ms,
                "driver_ms": k.driver_ms,
            })
        })
        .collect()
}

/// Every figure as JSON (`jit`: the `--cpu-jit` the children were given).
pub fn json(report: &Report, adapter_note: &str, jit: &str) -> serde_json::Value {
    serde_json::json!({
        "environment": {
            "MESA_SHADER_CACHE_DISABLE": "true",
            "__GL_SHADER_DISK_CACHE": "0",
            "RTC_PIPELINE_CACHE": "off",
            "size": SIZE,
            "spp": 1,
            "cpu_jit": jit,
            "note": adapter_note,
        },
        "cold": report.cold.iter().map(|r| serde_json::json!({
            "example": r.example,
            "exec": r.exec,
            "first_pixel_ms": r.first_pixel_ms,
            "pipelines_ms": r.pipelines_ms,
            "kernels": kernels_json(&r.kernels),
            "jit": r.quick_jit.is_some().then(|| jit_name(r.quick_jit)),
            "error": r.error,
        })).collect::<Vec<_>>(),
        "material_edit": report.edit.iter().map(|e| serde_json::json!({
            "scene": "thesis_scene",
            "exec": e.exec,
            "edit": format!("{} -> {} in blinn_phong.rt", EDIT.0, EDIT.1),
            "first_prepare_ms": e.first_prepare_ms,
            "edit_to_preview_ms": e.edit_to_preview_ms,
            "kernels": kernels_json(&e.kernels),
            "error": e.error,
        })).collect::<Vec<_>>(),
    })
}

/// Runs `rtc bench --compile`.
pub fn run(args: &super::Args, ctx: &Context) -> Exit {
    if let Some(p) = &args.json {
        if p.extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
            != Some("json")
        {
            return report::usage_error(
                &format!(
                    "cannot write --json `{}`: its name must end in `.json`",
                    p.display()
                ),
                ctx.color,
            );
        }
        if let Err(e) = crate::args::check_output_path(p, "--json") {
            return report::usage_error(&e, ctx.color);
        }
    }
    let models: Vec<&str> = if args.exec.is_empty() {
        EXEC_MODELS.to_vec()
    } else {
        args.exec.iter().map(String::as_str).collect()
    };
    let path = args
        .path
        .clone()
        .unwrap_or_else(|| PathBuf::from("examples"));
    let scenes = match scenes(&path) {
        Ok(s) => s,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => return super::fail(&format!("cannot find this rtc executable: {e}"), ctx),
    };
    if started_by_a_loader(&exe) {
        // `current_lavapipe.sh rtc bench --compile`: the children would be the loader itself.
        return super::fail(
            &format!(
                "this rtc was started through the dynamic loader `{}`, so it cannot start itself \
                 again for each cold render\nhelp: let rtc start it: \
                 `{RUNNER_ENV}=\"bash docs/bench/current_lavapipe.sh\" rtc bench --compile`",
                exe.display()
            ),
            ctx,
        );
    }
    let scratch = std::env::temp_dir().join(format!("rtc-bench-compile-{}", std::process::id()));
    if let Err(e) = std::fs::create_dir_all(&scratch) {
        return super::fail(&format!("cannot create `{}`: {e}", scratch.display()), ctx);
    }
    let jit = args.adapter.cpu_jit.as_str();
    let mut report = Report::default();
    for exec in &models {
        for (name, scene) in &scenes {
            term::eprint(&format!("[bench] cold render of {name} ({exec})\n"));
            report
                .cold
                .push(cold(&exe, name, scene, exec, jit, &scratch));
        }
    }
    let thesis = if path.is_dir() {
        Some(path.join("thesis_scene").join("scene.rt")).filter(|p| p.is_file())
    } else {
        None
    };
    if let Some(thesis) = &thesis {
        for exec in &models {
            term::eprint(&format!("[bench] material edit of thesis_scene ({exec})\n"));
            report.edit.push(edit(
                &exe,
                thesis,
                &ctx.options.stdlib_dir,
                exec,
                jit,
                &scratch,
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&scratch);
    term::print(&table(&report));
    if let Some(p) = &args.json {
        let note = "wall times of child processes; the machine may be shared";
        let text = match serde_json::to_string_pretty(&json(&report, note, jit)) {
            Ok(t) => t,
            Err(e) => return super::fail(&format!("cannot encode the JSON: {e}"), ctx),
        };
        if let Err(e) = std::fs::write(p, text + "\n") {
            return super::fail(&format!("cannot write `{}`: {e}", p.display()), ctx);
        }
    }
    if report.cold.iter().any(|r| r.error.is_some())
        || report.edit.iter().any(|e| e.error.is_some())
    {
        return Exit::Failure;
    }
    Exit::Success
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_loader_is_not_rtc() {
        for loader in [
            "/root/.cache/rtc/sysroot/usr/lib64/ld-linux-x86-64.so.2",
            "/lib/ld-linux-aarch64.so.1",
            "/lib/ld-musl-x86_64.so.1",
            "/usr/libexec/ld.so",
        ] {
            assert!(started_by_a_loader(Path::new(loader)), "{loader}");
        }
        for rtc in ["/work/target/release/rtc", "rtc", "/usr/bin/rtc-ld", "/"] {
            assert!(!started_by_a_loader(Path::new(rtc)), "{rtc}");
        }
    }

    #[test]
    fn a_child_starts_with_every_cache_off() {
        let cmd = child(Path::new("/work/target/release/rtc"));
        let envs: Vec<(String, Option<String>)> = cmd
            .get_envs()
            .map(|(k, v)| {
                let s = |o: &std::ffi::OsStr| o.to_string_lossy().into_owned();
                (s(k), v.map(s))
            })
            .collect();
        for (name, value) in [
            ("MESA_SHADER_CACHE_DISABLE", "true"),
            ("__GL_SHADER_DISK_CACHE", "0"),
            (rtc_runtime::gpu::PIPELINE_CACHE_ENV, "off"),
        ] {
            assert!(
                envs.contains(&(name.to_string(), Some(value.to_string()))),
                "{name}={value} in {envs:?}"
            );
        }
    }

    #[test]
    fn reads_summary_lines() {
        assert_eq!(
            pipelines_ms("  pipelines   10153.77 ms  (kernel creation and the driver's compile)"),
            Some(10153.77)
        );
        let k = kernel_line(
            "    rtc render  compiled                10152.65 ms  (driver 10148.09 ms)",
        )
        .expect("a kernel line");
        assert_eq!(k.label, "rtc render");
        assert_eq!(k.origin, "compiled");
        assert_eq!(k.total_ms, 10152.65);
        assert_eq!(k.driver_ms, 10148.09);
        let k =
            kernel_line("    rtc bounds  reused (memory cache)        0.01 ms  (driver 0.00 ms)")
                .expect("a kernel line");
        assert_eq!(k.origin, "reused (memory cache)");
        assert_eq!(
            kernel_line("  render        0.30 ms  (0.21 M primary rays/s)"),
            None
        );
        assert_eq!(
            host_quick_jit("host: Intel(R) Xeon(R) Processor, 2 threads, AVX2 and AVX-512; GALLIVM_PERF=nopt (rtc's quick JIT for a small render)"),
            Some(true)
        );
        assert_eq!(
            host_quick_jit("host: AMD EPYC 7B13, 2 threads, AVX2 and AVX-512"),
            Some(false)
        );
        assert_eq!(host_quick_jit("adapter: llvmpipe"), None);
        assert_eq!(
            edit_to_preview("[watch] #2 ok (edit to code 12.0 ms, edit to preview 812.5 ms)"),
            Some(812.5)
        );
        assert_eq!(
            phase_ms(
                "  prepare preview (scene, pipelines)   8123.40 ms",
                "prepare preview"
            ),
            Some(8123.40)
        );
    }
}
