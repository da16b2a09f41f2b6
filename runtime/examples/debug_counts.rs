//! Traversal statistics of a scene's camera rays from the debug kernel (`DebugMode::Counts`): mean
//! and maximum BVH nodes visited and primitives tested per camera ray, and the fraction of rays
//! that hit, and the mean over 8-pixel batches of their slowest lane's node count (what a CPU
//! driver running 8 lanes in lockstep pays). A performance aid: `cargo run --release -p rtc-runtime --example debug_counts --
//! examples/thesis_scene/scene.rt [WIDTHxHEIGHT]`.

use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene_with, DebugMode, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::gpu::{AdapterChoice, Gpu};
use rtc_runtime::render::{RenderOptions, Renderer};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        eprintln!("usage: debug_counts SCENE.rt [WIDTHxHEIGHT]");
        std::process::exit(2);
    };
    let size = args.get(2).and_then(|s| {
        let (w, h) = s.split_once('x')?;
        Some([w.parse().ok()?, h.parse().ok()?])
    });
    let compiled = match compile_scene_with(
        &[std::path::PathBuf::from(path)],
        None,
        &Options::default(),
        &LinkOptions::default(),
        &KernelOptions {
            debug: Some(DebugMode::Counts),
            ..KernelOptions::default()
        },
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
    let result = Gpu::new(&AdapterChoice::default())
        .map_err(|e| e.to_string())
        .and_then(|gpu| {
            let mut r = Renderer::new(
                &gpu,
                &compiled,
                RenderOptions {
                    size,
                    ..RenderOptions::default()
                },
            )
            .map_err(|e| e.to_string())?;
            let start = std::time::Instant::now();
            let p = r.render_debug().map_err(|e| e.to_string())?;
            Ok((p, start.elapsed().as_secs_f64() * 1e3, r.size()[0]))
        });
    let (pixels, ms, width) = match result {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    let n = pixels.len().max(1) as f64;
    // SIMD view: lavapipe runs 8 consecutive invocations of an 8 x 8 workgroup (one row of 8
    // pixels) as one batch, so a batch costs what its slowest lane costs.
    let width = (width as usize).max(1);
    let mut batch_max = 0.0f64;
    let mut batches = 0.0f64;
    for row in pixels.chunks(width) {
        for group in row.chunks(8) {
            batch_max += group.iter().map(|p| f64::from(p[0])).fold(0.0, f64::max);
            batches += 1.0;
        }
    }
    let batch_max = batch_max / batches.max(1.0);
    let mean = |c: usize| pixels.iter().map(|p| f64::from(p[c])).sum::<f64>() / n;
    let max = |c: usize| pixels.iter().map(|p| p[c]).fold(0.0f32, f32::max);
    let hits = pixels.iter().filter(|p| p[3] >= 0.0).count() as f64 / n;
    println!(
        "{} camera rays in {ms:.0} ms (upload, one pass, read-back): nodes visited mean {:.1} max {}, primitives tested mean {:.1} max {}, hit fraction {:.3} (channel means: z {:.2}, w {:.2}); nodes per 8-pixel batch (its slowest lane) mean {batch_max:.1}",
        pixels.len(),
        mean(0),
        max(0),
        mean(1),
        max(1),
        hits,
        mean(2),
        mean(3)
    );
}
