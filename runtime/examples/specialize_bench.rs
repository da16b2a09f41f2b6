//! Specialised kernels against `--all-programs` kernels, measured in one run: for each example scene
//! (`examples/hello`, `examples/lambert_only`, `examples/glass_mirror` by default, or the scene files
//! given as arguments) the render kernel's size (WGSL lines, SPIR-V words), the compute pipeline's
//! creation time as the runtime reports it, and the render time, both ways.
//!
//! `cargo run --release -p rtc-runtime --example specialize_bench`; set
//! `MESA_SHADER_CACHE_DISABLE=true` for cold pipeline numbers on Mesa drivers (lavapipe caches
//! compiled shaders on disk, so a second run is otherwise warm). Each render is the scene's own
//! settings; the best of three renders is reported.

use std::path::PathBuf;

use rtc_compiler::back::{self, Target};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{compile_scene, CompiledScene, RENDER_ENTRY};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::gpu::{AdapterChoice, Gpu};
use rtc_runtime::render::{RenderOptions, Renderer};

struct Row {
    scene: String,
    kernel: &'static str,
    wgsl_lines: usize,
    spirv_words: usize,
    pipeline_ms: f64,
    render_ms: f64,
}

fn sizes(c: &CompiledScene) -> Result<(usize, usize), String> {
    let resources = rtc_compiler::abi::resources(c.bindings.iter().copied());
    let wgsl = back::write(&c.render, Target::Wgsl, RENDER_ENTRY, &resources)
        .map_err(|e| e.to_string())?;
    let spirv = back::write(&c.render, Target::SpirV, RENDER_ENTRY, &resources)
        .map_err(|e| e.to_string())?;
    let lines = wgsl.iter().filter(|&&b| b == b'\n').count();
    Ok((lines, spirv.len() / 4))
}

fn measure(gpu: &Gpu, path: &PathBuf, all_programs: bool) -> Result<Row, String> {
    let c = compile_scene(
        std::slice::from_ref(path),
        None,
        &Options::default(),
        &LinkOptions {
            all_programs,
            ..LinkOptions::default()
        },
    )
    .map_err(|f| rtc_compiler::diag::render_human(&f.checked.sources, &f.diagnostics, false))?;
    let (wgsl_lines, spirv_words) = sizes(&c)?;
    let mut renderer =
        Renderer::new(gpu, &c, RenderOptions::default()).map_err(|e| e.to_string())?;
    let mut pipeline_ms = 0.0;
    let mut render_ms = f64::INFINITY;
    for i in 0..3 {
        let r = renderer.render(&mut |_, _| {}).map_err(|e| e.to_string())?;
        if i == 0 {
            pipeline_ms = r.stats.pipeline_ms;
        }
        render_ms = render_ms.min(r.stats.render_ms);
    }
    let scene = path.parent().and_then(|p| p.file_name()).map_or_else(
        || path.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    Ok(Row {
        scene,
        kernel: if all_programs {
            "all-programs"
        } else {
            "specialised"
        },
        wgsl_lines,
        spirv_words,
        pipeline_ms,
        render_ms,
    })
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let args: Vec<PathBuf> = std::env::args().skip(1).map(PathBuf::from).collect();
    let scenes = if args.is_empty() {
        ["hello", "lambert_only", "glass_mirror"]
            .iter()
            .map(|n| root.join("examples").join(n).join("scene.rt"))
            .collect()
    } else {
        args
    };
    let gpu = match Gpu::new(&AdapterChoice::default()) {
        Ok(g) => g,
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    };
    let cache = match std::env::var("MESA_SHADER_CACHE_DISABLE") {
        Ok(v) if v == "true" || v == "1" => "disabled (cold pipelines)",
        _ => "enabled (pipelines may be warm from an earlier run)",
    };
    println!("adapter: {}", gpu.description());
    println!("Mesa shader cache: {cache}");
    println!(
        "{:<14} {:<13} {:>10} {:>11} {:>13} {:>11}",
        "scene", "kernel", "WGSL lines", "SPIR-V words", "pipeline ms", "render ms"
    );
    let mut failed = false;
    for path in &scenes {
        for all in [false, true] {
            match measure(&gpu, path, all) {
                Ok(r) => println!(
                    "{:<14} {:<13} {:>10} {:>11} {:>13.1} {:>11.2}",
                    r.scene, r.kernel, r.wgsl_lines, r.spirv_words, r.pipeline_ms, r.render_ms
                ),
                Err(e) => {
                    eprintln!("{}: {e}", path.display());
                    failed = true;
                }
            }
        }
    }
    if failed {
        std::process::exit(1);
    }
}
