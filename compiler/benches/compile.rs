//! Compile latency: an example scene (with the standard library it imports and the framework kernel)
//! to all five targets, cold (the first compile in a fresh process) and warm (the median of repeated
//! compiles), with the time and share of each phase.
//!
//! `cargo bench -p rtc-compiler --bench compile [-- SCENE.rt …] [--runs N]` (default: every
//! `examples/*/scene.rt`, 30 warm runs). The goal is under 50 ms warm on the project's 2-core machine,
//! because watch mode recompiles on every save. This is a plain timing program, not criterion: phases
//! are what matters, and criterion cannot report them.

use rtc_compiler::back::{self, Target};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{self, RENDER_ENTRY};
use rtc_compiler::link::LinkOptions;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// One compile: the phases of `compile_scene` plus one "write <target>" phase per target.
fn compile_once(scene: &Path) -> Vec<(String, f64)> {
    let c = match kernel::compile_scene(
        &[scene.to_path_buf()],
        None,
        &Options::default(),
        &LinkOptions::default(),
    ) {
        Ok(c) => c,
        Err(f) => {
            eprintln!(
                "{}",
                rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false)
            );
            std::process::exit(1);
        }
    };
    let mut phases: Vec<(String, f64)> = c
        .timings
        .iter()
        .map(|(n, ms)| (n.to_string(), *ms))
        .collect();
    let resources = rtc_compiler::abi::resources(c.bindings.iter().copied());
    for t in Target::ALL {
        let start = Instant::now();
        let out = back::write(&c.render, t, RENDER_ENTRY, &resources);
        let ms = start.elapsed().as_secs_f64() * 1e3;
        if let Err(e) = out {
            eprintln!("{}: {e}", t.name());
            std::process::exit(1);
        }
        phases.push((format!("write {}", t.name()), ms));
    }
    phases
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let mut runs = 30usize;
    let mut scenes: Vec<PathBuf> = Vec::new();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        if a == "--runs" {
            runs = it.next().and_then(|n| n.parse().ok()).unwrap_or(runs);
        } else if a.ends_with(".rt") {
            scenes.push(PathBuf::from(a));
        }
    }
    if scenes.is_empty() {
        let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
        let mut found: Vec<PathBuf> = std::fs::read_dir(examples)
            .into_iter()
            .flatten()
            .flatten()
            .map(|e| e.path().join("scene.rt"))
            .filter(|p| p.is_file())
            .collect();
        found.sort();
        scenes = found;
    }
    for scene in &scenes {
        let cold = compile_once(scene);
        let mut warm: Vec<Vec<(String, f64)>> = Vec::new();
        for _ in 0..runs.max(1) {
            warm.push(compile_once(scene));
        }
        let cold_total: f64 = cold.iter().map(|(_, ms)| ms).sum();
        let totals: Vec<f64> = warm
            .iter()
            .map(|p| p.iter().map(|(_, ms)| ms).sum())
            .collect();
        let warm_total = median(totals);
        println!(
            "\n{} — cold {cold_total:.2} ms, warm {warm_total:.2} ms (median of {runs})",
            scene.display()
        );
        println!(
            "{:<28} {:>10} {:>10} {:>8}",
            "phase", "cold ms", "warm ms", "share"
        );
        for (i, (name, cold_ms)) in cold.iter().enumerate() {
            let w = median(warm.iter().map(|p| p[i].1).collect());
            println!(
                "{name:<28} {cold_ms:>10.3} {w:>10.3} {:>7.1}%",
                100.0 * w / warm_total
            );
        }
    }
}
