//! Benchmark of `check`, warm: every `.rt` file of `stdlib/` as the roots of one compilation, and every
//! `.rt` file of `examples/` (each example is its own compilation; the group's time is for all of
//! them). The goal is under 5 ms for the shipped stdlib on the 2-core CI machine.
//!
//! "Warm" means the files are in the OS cache and the allocator has been exercised by earlier
//! iterations; the checker itself keeps nothing between calls, so every iteration reads, parses and
//! checks from scratch, as `rtc check` does.
//!
//! Run with `cargo bench -p rtc-compiler --bench check` (criterion reports ns/µs/ms per iteration).

use criterion::{criterion_group, criterion_main, Criterion};
use rtc_compiler::driver::{check_paths, Options};
use std::hint::black_box;
use std::path::{Path, PathBuf};

fn rt_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    if let Ok(entries) = std::fs::read_dir(dir) {
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                out.extend(rt_files(&path));
            } else if path.extension().is_some_and(|e| e == "rt") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn bench_check(c: &mut Criterion) {
    let options = Options::default();

    let stdlib = rt_files(&repo().join("stdlib"));
    let first = check_paths(&stdlib, &options);
    eprintln!(
        "stdlib: {} root files, {} files read, {} diagnostics ({} errors)",
        stdlib.len(),
        first.sources.len(),
        first.diagnostics.len(),
        first.diagnostics.iter().filter(|d| d.is_error()).count()
    );
    c.bench_function("check/stdlib", |b| {
        b.iter(|| black_box(check_paths(black_box(&stdlib), &options)))
    });

    let examples = rt_files(&repo().join("examples"));
    if examples.is_empty() {
        eprintln!("examples: none yet, skipping check/examples");
    } else {
        c.bench_function("check/examples", |b| {
            b.iter(|| {
                for example in &examples {
                    black_box(check_paths(std::slice::from_ref(example), &options));
                }
            })
        });
    }
}

criterion_group!(benches, bench_check);
criterion_main!(benches);
