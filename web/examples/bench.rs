//! Native edit → WGSL latency of examples/hello through the same in-memory [`rtc_web::Compiler`]
//! the WebAssembly build runs, for docs/bench/wasm_compile.sh to set beside the Node figures.
//!
//!   cargo run --release -p rtc-web --example bench -- [ITERATIONS]
//!
//! Prints one line of JSON: the first compile with a new compiler (`cold_ms`) and the median and
//! minimum of `ITERATIONS` (default 20) compiles after an edit of the scene file (`warm_*`).

use rtc_web::{with_stdlib, CompileOptions, Compiler};
use std::path::Path;
use std::time::Instant;

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20);
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let entry = "examples/hello/scene.rt".to_string();
    let read = |p: &str| std::fs::read(repo.join(p)).unwrap_or_default();
    let scene = read(&entry);
    let registry = read("examples/hello/rtc.registry.json");
    let files = |edit: usize| {
        let mut text = scene.clone();
        text.extend_from_slice(format!("// edit {edit}\n").as_bytes());
        with_stdlib([
            (entry.clone(), text),
            (
                "examples/hello/rtc.registry.json".to_string(),
                registry.clone(),
            ),
        ])
    };
    let options = CompileOptions::default();
    let compiler = Compiler::new();
    let t = Instant::now();
    let first = compiler.compile(files(0), std::slice::from_ref(&entry), &options);
    let cold = t.elapsed().as_secs_f64() * 1e3;
    assert!(first.ok, "{}", first.rendered);
    let mut warm: Vec<f64> = (1..=n)
        .map(|i| {
            let t = Instant::now();
            let out = compiler.compile(files(i), std::slice::from_ref(&entry), &options);
            assert!(out.ok);
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    warm.sort_by(f64::total_cmp);
    println!(
        "{{\"cold_ms\": {cold:.2}, \"warm_median_ms\": {:.2}, \"warm_min_ms\": {:.2}, \"iterations\": {n}}}",
        warm[warm.len() / 2],
        warm[0]
    );
}
