//! `rtc bench <scene.rt>`: error against run time.
//!
//! Renders the scene at each sample count of `--spp-list` (default 1, 4, 16, 64, 256) and compares
//! each image with a reference: an EXR/PNG file (`--reference`), or the scene itself rendered at
//! `--reference-spp` samples (default 1024). Prints a table (spp, ms, RMSE, relative MSE, PSNR),
//! and on request writes it as CSV (`--csv`) and JSON (`--json`, with the setup figures) and draws
//! the log-log error-against-time plot as SVG (`--plot`).
//!
//! How it is timed: each level is a **separate render** that starts at pass 0, so the samples of
//! a level are the first samples of every larger level (and of a reference rendered here), and
//! its time is the whole render's: the GPU dispatches of all its passes. One render of one pass
//! runs first, untimed (a process's first render can pay a warm-up the later ones do not). With
//! `--runs N` every level is rendered `N` times, in `N` rounds over all levels (so a slow spell of
//! the machine falls on every level alike), and `ms` is the median (the JSON also has the least
//! and the most); the images of a level's runs must be identical, and a difference is a warning.
//! Pipeline creation (with the driver's compile and the warm-up dispatch), BVH build and upload
//! are setup, measured by the runtime separately, printed apart and never included in `ms`.
//!
//! Because a reference rendered here shares the first `n` samples of each level, the expected
//! measured MSE is `σ²(1/n − 1/N)` rather than `σ²/n` (`N` the reference's samples); the output
//! says so. An independent reference file has no such bias.
//!
//! `--against FILE` reads another renderer's error-against-time curve (CSV or JSON; the format is
//! in [`against`]) and prints the equal-error time ratio, rtc's time over the other's at the same
//! RMSE, interpolated on the log-log curves; `--plot` draws both curves.
//!
//! `--bvh-presets` adds the BVH knob: for each builder preset (`fast`, `quality`) it builds the
//! scene and renders `--preset-spp` samples, and reports BVH build ms, trace (render) ms, and the
//! SAH cost of the scene-level BVH and of the object-level BVHs (their mean weighted by
//! triangles).
//!
//! `--compile` measures compile times instead (time to first pixel of every example with a cold
//! driver cache, and a material edit under `rtc watch`): [`compile_time`].
//!
//! Errors (a missing or unreadable reference, a reference of another size, a bad output name)
//! are one `error:` line and exit code 1 (2 for usage errors), found before the long renders
//! where possible; nothing here panics on user input.

use super::render::{fail, render_failure, warn};
use super::Context;
use crate::args::{AdapterArgs, AssetArgs, BvhArgs, BvhPreset, MessageFormat, SceneArgs};
use crate::exit::Exit;
use crate::{report, term};
use rtc_compiler::kernel::{compile_scene_with, CompiledScene, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_runtime::bvh_view::sah_cost;
use rtc_runtime::gpu::Gpu;
use rtc_runtime::image_out::{compare, read_image};
use rtc_runtime::render::{RenderError, RenderOptions, RenderResult, Renderer};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The reference's sample count when neither `--reference` nor `--reference-spp` is given.
pub const DEFAULT_REFERENCE_SPP: u32 = 1024;

pub mod against;
pub mod compile_time;

/// Arguments of `rtc bench`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scene file (with `--compile`: a scene file, or a folder of examples each holding a
    /// `scene.rt`; default `examples`).
    #[arg(value_name = "SCENE", required_unless_present = "compile")]
    pub path: Option<PathBuf>,
    /// Measure compile times instead: time to first pixel of every example with a cold driver
    /// cache, and a material edit's time to the new preview (see `compile_time`).
    #[arg(long)]
    pub compile: bool,
    /// With `--compile`: the execution models to measure, comma-separated (default: all).
    #[arg(long, value_name = "MODEL", value_delimiter = ',', requires = "compile",
          value_parser = clap::builder::PossibleValuesParser::new(compile_time::EXEC_MODELS))]
    pub exec: Vec<String>,
    /// The reference image (EXR for linear values; a PNG is decoded from sRGB).
    #[arg(long, value_name = "FILE", conflicts_with = "reference_spp")]
    pub reference: Option<PathBuf>,
    /// Render the reference from the scene at this many samples per pixel (default 1024).
    #[arg(long, value_name = "N", value_parser = crate::args::parse_spp)]
    pub reference_spp: Option<u32>,
    /// The sample counts to measure, comma-separated.
    #[arg(
        long,
        value_name = "LIST",
        value_delimiter = ',',
        default_value = "1,4,16,64,256",
        value_parser = crate::args::parse_spp
    )]
    pub spp_list: Vec<u32>,
    /// Which scene, and its image size.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The GPU.
    #[command(flatten)]
    pub adapter: AdapterArgs,
    /// The BVH builder.
    #[command(flatten)]
    pub bvh: BvhArgs,
    /// Write the table as CSV.
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Write the table and the setup figures as JSON.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// Draw RMSE against render time (log-log) as SVG.
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    /// Another renderer's error-against-time curve (CSV with a header naming `rmse` and `ms` or
    /// `seconds`, optionally `spp`; or JSON rows with those keys, as `--json` writes): prints the
    /// equal-error time ratio (rtc's time over the other's at the same RMSE, interpolated on the
    /// log-log curves) and draws the curve in `--plot`. Measure both against the same reference.
    /// The format: docs/bench/README.md, "The `--against` curve format".
    #[arg(long, value_name = "FILE")]
    pub against: Option<PathBuf>,
    /// Also report BVH build ms against trace ms and SAH cost for each builder preset.
    #[arg(long)]
    pub bvh_presets: bool,
    /// Render every level this many times (in rounds over all levels) and report the median time.
    #[arg(long, value_name = "N", default_value_t = 1,
          value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub runs: u32,
    /// Samples per pixel of the `--bvh-presets` renders.
    #[arg(long, value_name = "N", default_value_t = 16, value_parser = crate::args::parse_spp)]
    pub preset_spp: u32,
    /// Where else the scene's assets may come from.
    #[command(flatten)]
    pub assets: AssetArgs,
}

/// One measured level.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// Samples per pixel asked for.
    pub spp: u32,
    /// Samples per pixel taken (rounded up to the camera's samples per pass).
    pub samples: u32,
    /// Render time, ms (GPU dispatches of all passes; the median of `--runs`).
    pub ms: f64,
    /// The least and the most render time of the runs (both `ms` for one run).
    pub ms_range: (f64, f64),
    /// Root-mean-square error against the reference.
    pub rmse: f64,
    /// Relative MSE against the reference.
    pub rel_mse: f64,
    /// PSNR for a peak of 1, dB.
    pub psnr: f64,
}

/// Setup figures of one renderer (not part of any row's `ms`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Setup {
    /// Pipeline creation including the driver's compile and the warm-up dispatch.
    pub pipeline_ms: f64,
    /// BVH builds.
    pub bvh_build_ms: f64,
    /// Uploads.
    pub upload_ms: f64,
}

/// One BVH preset's figures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PresetRow {
    /// The preset.
    pub preset: BvhPreset,
    /// BVH build, ms.
    pub build_ms: f64,
    /// Render at `--preset-spp`, ms.
    pub trace_ms: f64,
    /// SAH cost of the scene-level BVH.
    pub tlas_sah: f64,
    /// Triangle-weighted mean SAH cost of the object-level BVHs.
    pub blas_sah: f64,
    /// Nodes in the node buffer (all BVHs).
    pub nodes: usize,
}

/// Compiles `path` (the normal kernel, or a debug kernel per `kernel`), printing diagnostics; the
/// error is the exit code to return. Shared by `rtc bench` and `rtc bvh`.
pub fn compile(
    path: &Path,
    scene: Option<&str>,
    kernel: &KernelOptions,
    ctx: &Context,
    verb: &str,
) -> Result<CompiledScene, Exit> {
    match compile_scene_with(
        std::slice::from_ref(&path.to_path_buf()),
        scene,
        &ctx.options,
        &LinkOptions::default(),
        kernel,
    ) {
        Ok(c) => Ok(c),
        Err(failure) => {
            let exit = report::diagnostics(
                &failure.checked.sources,
                &failure.diagnostics,
                MessageFormat::Human,
                ctx.color,
                verb,
            );
            if exit == Exit::Success {
                return Err(fail(
                    &format!("`{}` could not be compiled", path.display()),
                    ctx,
                ));
            }
            Err(Exit::Failure)
        }
    }
}

/// Prints a compiled scene's warnings, if any.
pub fn print_warnings(compiled: &CompiledScene, ctx: &Context, verb: &str) {
    if !compiled.checked.diagnostics.is_empty() {
        report::diagnostics(
            &compiled.checked.sources,
            &compiled.checked.diagnostics,
            MessageFormat::Human,
            ctx.color,
            verb,
        );
    }
}

/// Renders `compiled` once with `options`, returning the result and the renderer's setup.
fn render_once<'g>(
    gpu: &'g Gpu,
    compiled: &CompiledScene,
    options: RenderOptions,
) -> Result<(RenderResult, Renderer<'g>), RenderError> {
    let mut renderer = Renderer::new(gpu, compiled, options)?;
    let result = renderer.render(&mut |_, _| {})?;
    Ok((result, renderer))
}

/// The compiled scene's own image size (`None` when the compile kept no program).
fn scene_size(compiled: &CompiledScene) -> Option<[u32; 2]> {
    let program = compiled.checked.program.as_ref()?;
    let settings = &program.scenes[compiled.scene].settings;
    Some([settings.width, settings.height])
}

/// One line of the table; `extra` is appended.
fn print_row(row: &Row, extra: &str) {
    term::print(&format!(
        "{:>7} {:>12.2} {:>12.6} {:>12.6} {:>9.2}{extra}\n",
        row.samples, row.ms, row.rmse, row.rel_mse, row.psnr
    ));
}

/// The median of `values` (the mean of the middle two for an even count; NaN for none).
fn median(values: &[f64]) -> f64 {
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    match v.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => v[n / 2],
        n => 0.5 * (v[n / 2 - 1] + v[n / 2]),
    }
}

fn setup_of(r: &RenderResult) -> Setup {
    Setup {
        pipeline_ms: r.stats.pipeline_ms,
        bvh_build_ms: r.stats.bvh_build_ms,
        upload_ms: r.stats.upload_ms,
    }
}

/// Runs `rtc bench`.
pub fn run(args: &Args, ctx: &Context) -> Exit {
    if args.compile {
        return compile_time::run(args, ctx);
    }
    let Some(path) = &args.path else {
        return report::usage_error("a scene file is required", ctx.color);
    };
    // Every output is checked before anything is compiled or rendered.
    let outputs = [
        (&args.csv, "--csv", "csv", "CSV"),
        (&args.json, "--json", "json", "JSON"),
        (&args.plot, "--plot", "svg", "SVG"),
    ];
    for (path, option, extension, format) in outputs {
        let Some(path) = path else { continue };
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        if ext.as_deref() != Some(extension) {
            return report::usage_error(
                &format!(
                    "cannot write {option} `{}`: it is written as {format}, so its name must end \
                     in `.{extension}`",
                    path.display()
                ),
                ctx.color,
            );
        }
        if let Err(e) = crate::args::check_output_path(path, option) {
            return report::usage_error(&e, ctx.color);
        }
    }
    let choice = match args.adapter.choice() {
        Ok(c) => c,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let roots = match args.assets.roots() {
        Ok(r) => r,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let mut levels = args.spp_list.clone();
    levels.sort_unstable();
    levels.dedup();
    if levels.is_empty() {
        return report::usage_error("--spp-list needs at least one sample count", ctx.color);
    }

    // A reference file is read before anything is compiled or rendered.
    let reference_file = match &args.reference {
        Some(path) => match read_image(path) {
            Ok(image) => Some(image),
            Err(e) => {
                return fail(
                    &format!("cannot use the reference `{}`: {e}", path.display()),
                    ctx,
                )
            }
        },
        None => None,
    };

    let against = match &args.against {
        Some(file) => match against::read(file) {
            Ok(c) => Some(c),
            Err(e) => {
                return fail(
                    &format!("cannot use the curve `{}` (--against): {e}", file.display()),
                    ctx,
                )
            }
        },
        None => None,
    };

    let compiled = match compile(
        path,
        args.scene.name.as_deref(),
        &KernelOptions::default(),
        ctx,
        "bench",
    ) {
        Ok(c) => c,
        Err(exit) => return exit,
    };
    print_warnings(&compiled, ctx, "bench");
    let gpu = match Gpu::new(&choice) {
        Ok(gpu) => gpu,
        Err(e) => return fail(&e.to_string(), ctx),
    };
    term::print(&format!("adapter: {}\n", gpu.description()));
    term::print(&format!("host: {}\n", rtc_runtime::gpu::HostCpu::detect()));
    let base = RenderOptions {
        size: args.scene.image_size(),
        bvh: args.bvh.preset.into(),
        flatten: !args.bvh.no_flatten,
        asset_roots: roots,
        ..RenderOptions::default()
    };

    // The reference: from the file (its size checked against the render's), or rendered here.
    let (reference, reference_spp) = match reference_file {
        Some(image) => {
            let size = match (base.size, scene_size(&compiled)) {
                (Some(size), _) | (None, Some(size)) => size,
                (None, None) => match Renderer::new(&gpu, &compiled, base.clone()) {
                    Ok(r) => r.size(),
                    Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
                },
            };
            if [image.width(), image.height()] != size {
                return fail(
                    &format!(
                        "the reference `{}` is {}x{} but the bench renders {}x{}; give \
                         --size {}x{} or a reference of the render's size",
                        args.reference.as_deref().unwrap_or(Path::new("")).display(),
                        image.width(),
                        image.height(),
                        size[0],
                        size[1],
                        image.width(),
                        image.height()
                    ),
                    ctx,
                );
            }
            (image, None)
        }
        None => {
            let spp = args.reference_spp.unwrap_or(DEFAULT_REFERENCE_SPP);
            term::eprint(&format!("rendering the reference at {spp} spp...\n"));
            let options = RenderOptions {
                samples: Some(spp),
                ..base.clone()
            };
            match render_once(&gpu, &compiled, options) {
                Ok((r, _)) => {
                    term::print(&format!(
                        "reference: the scene at {} spp, rendered in {:.1} ms\n",
                        r.stats.samples, r.stats.render_ms
                    ));
                    (r.image, Some(r.stats.samples))
                }
                Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
            }
        }
    };
    if let Some(path) = &args.reference {
        term::print(&format!("reference: {}\n", path.display()));
    }

    term::print(&format!(
        "{:>7} {:>12} {:>12} {:>12} {:>9}\n",
        "spp", "ms", "RMSE", "rel MSE", "PSNR dB"
    ));
    let mut rows: Vec<Row> = Vec::new();
    let mut setup = Setup::default();
    let mut size = [0, 0];
    // A warm-up render of one pass, not timed: the first render of a process sometimes took
    // 50 ms more than the same render later (lavapipe, 512x512), which only the first level
    // paid. (Mitsuba's side of `docs/bench/cornell_vs_mitsuba.sh` warms up the same way.)
    let warm_up_ms = match render_once(
        &gpu,
        &compiled,
        RenderOptions {
            samples: Some(1),
            ..base.clone()
        },
    ) {
        Ok((r, _)) => r.stats.render_ms,
        Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
    };
    let mut times: Vec<Vec<f64>> = vec![Vec::new(); levels.len()];
    for run in 0..args.runs {
        if args.runs > 1 {
            term::eprint(&format!("run {} of {}...\n", run + 1, args.runs));
        }
        for (i, &spp) in levels.iter().enumerate() {
            let options = RenderOptions {
                samples: Some(spp),
                ..base.clone()
            };
            let r = match render_once(&gpu, &compiled, options) {
                Ok((r, _)) => r,
                Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
            };
            times[i].push(r.stats.render_ms);
            if run > 0 {
                if let Some(first) = rows.get(i) {
                    let m = compare(&r.image, &reference).ok();
                    if m.is_some_and(|m| m.rmse.to_bits() != first.rmse.to_bits()) {
                        warn(
                            &format!(
                                "run {} at {spp} spp rendered another image than run 1 (RMSE \
                                 {:.6} against {:.6})",
                                run + 1,
                                m.map_or(f64::NAN, |m| m.rmse),
                                first.rmse
                            ),
                            ctx,
                        );
                    }
                }
                continue;
            }
            if rows.is_empty() {
                setup = setup_of(&r);
                size = [r.stats.width, r.stats.height];
                for w in &r.stats.warnings {
                    warn(w, ctx);
                }
            }
            let m = match compare(&r.image, &reference) {
                Ok(m) => m,
                Err(e) => return fail(&format!("cannot compare with the reference: {e}"), ctx),
            };
            if m.nonfinite_test > 0 {
                warn(
                    &format!(
                        "{} pixels at {spp} spp are not finite and were left out of the error",
                        m.nonfinite_test
                    ),
                    ctx,
                );
            }
            let row = Row {
                spp,
                samples: r.stats.samples,
                ms: r.stats.render_ms,
                ms_range: (r.stats.render_ms, r.stats.render_ms),
                rmse: m.rmse,
                rel_mse: m.rel_mse,
                psnr: m.psnr,
            };
            if args.runs == 1 {
                print_row(&row, "");
            }
            rows.push(row);
        }
    }
    for (row, t) in rows.iter_mut().zip(&times) {
        row.ms = median(t);
        row.ms_range = (
            t.iter().copied().fold(f64::INFINITY, f64::min),
            t.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        );
    }
    if args.runs > 1 {
        for row in &rows {
            print_row(
                row,
                &format!("  ({:.2} to {:.2})", row.ms_range.0, row.ms_range.1),
            );
        }
        term::print(&format!(
            "ms = median of {} runs (least to most in brackets), in rounds over all levels\n",
            args.runs
        ));
    }
    term::print(&format!(
        "{}x{}; ms = GPU render time of all passes of that level (a separate render from pass \
         0, after an untimed warm-up render of one pass, {warm_up_ms:.1} ms); not included, per \
         render: pipelines {:.1} ms, BVH build {:.2} ms, upload {:.2} ms\n",
        size[0], size[1], setup.pipeline_ms, setup.bvh_build_ms, setup.upload_ms
    ));
    if let Some(n) = reference_spp {
        term::print(&format!(
            "note: the reference shares each level's first samples, so the expected MSE is \
             sigma^2 (1/n - 1/{n}), not sigma^2/n\n"
        ));
    }
    if let Some(slope) = loglog_slope(&rows) {
        term::print(&format!(
            "log-log slope of RMSE against ms: {slope:.3} (Monte Carlo: -0.5)\n"
        ));
    }

    let compared = against.as_ref().map(|curve| {
        let ours: Vec<(u32, f64, f64)> = rows.iter().map(|r| (r.samples, r.ms, r.rmse)).collect();
        let levels = against::levels(curve, &ours);
        term::print(&against::report(curve, &levels));
        (curve, levels)
    });

    let mut presets = Vec::new();
    if args.bvh_presets {
        term::print(&format!(
            "\nBVH presets ({} spp):\n{:>8} {:>10} {:>10} {:>10} {:>10} {:>9}\n",
            args.preset_spp, "preset", "build ms", "trace ms", "TLAS SAH", "BLAS SAH", "nodes"
        ));
        for preset in [BvhPreset::Fast, BvhPreset::Quality] {
            let options = RenderOptions {
                samples: Some(args.preset_spp),
                bvh: preset.into(),
                ..base.clone()
            };
            let (r, renderer) = match render_once(&gpu, &compiled, options) {
                Ok(x) => x,
                Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
            };
            let row = preset_row(preset, &r, &renderer);
            term::print(&format!(
                "{:>8} {:>10.2} {:>10.2} {:>10.3} {:>10.3} {:>9}\n",
                preset_name(preset),
                row.build_ms,
                row.trace_ms,
                row.tlas_sah,
                row.blas_sah,
                row.nodes
            ));
            presets.push(row);
        }
    }

    let reference_desc = match (&args.reference, reference_spp) {
        (Some(p), _) => format!("file {}", p.display()),
        (None, Some(n)) => format!("scene at {n} spp"),
        (None, None) => String::new(),
    };
    let mut outputs: Vec<(&Path, String)> = Vec::new();
    if let Some(p) = &args.csv {
        outputs.push((p, csv(&rows)));
    }
    if let Some(p) = &args.json {
        let mut value = json(
            path,
            size,
            &reference_desc,
            setup,
            &rows,
            &presets,
            args.preset_spp,
        );
        value["runs"] = serde_json::json!(args.runs);
        value["adapter"] = serde_json::json!(gpu.description().to_string());
        value["host"] = serde_json::json!(rtc_runtime::gpu::HostCpu::detect().to_string());
        if let Some((curve, levels)) = &compared {
            value["against"] = against::json(curve, levels);
        }
        outputs.push((p, format!("{value:#}\n")));
    }
    if let Some(p) = &args.plot {
        outputs.push((
            p,
            svg_plot(&rows, path, size, &reference_desc, against.as_ref()),
        ));
    }
    for (path, text) in outputs {
        if let Err(e) = std::fs::write(path, text) {
            return fail(&format!("cannot write `{}`: {e}", path.display()), ctx);
        }
        term::print(&format!("wrote {}\n", path.display()));
    }
    Exit::Success
}

fn preset_name(p: BvhPreset) -> &'static str {
    match p {
        BvhPreset::Fast => "fast",
        BvhPreset::Quality => "quality",
    }
}

fn preset_row(preset: BvhPreset, r: &RenderResult, renderer: &Renderer<'_>) -> PresetRow {
    let e = renderer.entities();
    let nodes = e.nodes();
    let (mut sum, mut weight) = (0.0f64, 0.0f64);
    for m in e.meshes() {
        let w = f64::from(m.triangles);
        sum += w * sah_cost(nodes, m.node_base);
        weight += w;
    }
    PresetRow {
        preset,
        build_ms: r.stats.bvh_build_ms,
        trace_ms: r.stats.render_ms,
        tlas_sah: sah_cost(nodes, e.tlas_root()),
        blas_sah: if weight > 0.0 { sum / weight } else { 0.0 },
        nodes: nodes.len(),
    }
}

/// Least-squares slope of `ln RMSE` against `ln ms` over rows with positive finite values;
/// `None` with fewer than two.
pub fn loglog_slope(rows: &[Row]) -> Option<f64> {
    let pts: Vec<(f64, f64)> = rows
        .iter()
        .filter(|r| r.ms > 0.0 && r.rmse > 0.0 && r.ms.is_finite() && r.rmse.is_finite())
        .map(|r| (r.ms.ln(), r.rmse.ln()))
        .collect();
    if pts.len() < 2 {
        return None;
    }
    let n = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
    let sxx: f64 = pts.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

/// The table as CSV (header `spp,ms,rmse,rel_mse,psnr_db`).
pub fn csv(rows: &[Row]) -> String {
    let mut out = String::from("spp,ms,rmse,rel_mse,psnr_db\n");
    for r in rows {
        let _ = writeln!(
            out,
            "{},{:.3},{:.8},{:.8},{:.4}",
            r.samples, r.ms, r.rmse, r.rel_mse, r.psnr
        );
    }
    out
}

fn finite(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::json!(x)
    } else {
        serde_json::Value::Null
    }
}

fn json(
    scene: &Path,
    size: [u32; 2],
    reference: &str,
    setup: Setup,
    rows: &[Row],
    presets: &[PresetRow],
    preset_spp: u32,
) -> serde_json::Value {
    serde_json::json!({
        "scene": scene.display().to_string(),
        "width": size[0],
        "height": size[1],
        "reference": reference,
        "timing": "ms = GPU render time of all passes of a separate render from pass 0, after an untimed one-pass warm-up render; setup excluded; with runs > 1 the median, ms_min and ms_max the least and the most",
        "setup": {
            "pipeline_ms": setup.pipeline_ms,
            "bvh_build_ms": setup.bvh_build_ms,
            "upload_ms": setup.upload_ms,
        },
        "rows": rows.iter().map(|r| serde_json::json!({
            "spp": r.samples,
            "ms": r.ms,
            "ms_min": r.ms_range.0,
            "ms_max": r.ms_range.1,
            "rmse": finite(r.rmse),
            "rel_mse": finite(r.rel_mse),
            "psnr_db": finite(r.psnr),
        })).collect::<Vec<_>>(),
        "loglog_slope": loglog_slope(rows).map_or(serde_json::Value::Null, finite),
        "bvh_presets": presets.iter().map(|p| serde_json::json!({
            "preset": preset_name(p.preset),
            "spp": preset_spp,
            "build_ms": p.build_ms,
            "trace_ms": p.trace_ms,
            "tlas_sah": p.tlas_sah,
            "blas_sah": p.blas_sah,
            "nodes": p.nodes,
        })).collect::<Vec<_>>(),
    })
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The decades (powers of ten) covering `[lo, hi]`, widened to at least one decade.
fn decades(lo: f64, hi: f64) -> (f64, f64) {
    let a = lo.log10().floor();
    let mut b = hi.log10().ceil();
    if b <= a {
        b = a + 1.0;
    }
    (a, b)
}

/// RMSE against ms on log-log axes, points labelled with their spp, and a dashed `ms^-1/2` line
/// through the first point (the Monte Carlo rate), as a standalone SVG document; with `other`,
/// that renderer's curve too (blue, with a legend).
pub fn svg_plot(
    rows: &[Row],
    scene: &Path,
    size: [u32; 2],
    reference: &str,
    other: Option<&against::Curve>,
) -> String {
    let pts: Vec<&Row> = rows
        .iter()
        .filter(|r| r.ms > 0.0 && r.rmse > 0.0 && r.ms.is_finite() && r.rmse.is_finite())
        .collect();
    let other_pts: &[against::Point] = other.map_or(&[], |c| &c.points);
    let (w, h) = (640.0, 440.0);
    let (left, right, top, bottom) = (80.0, 20.0, 50.0, 60.0);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
         viewBox=\"0 0 {w} {h}\" font-family=\"sans-serif\" font-size=\"12\">"
    );
    let _ = writeln!(s, "<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>");
    let _ = writeln!(
        s,
        "<text x=\"{}\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">RMSE against render \
         time: {} ({}x{})</text>",
        w / 2.0,
        escape(&scene.display().to_string()),
        size[0],
        size[1]
    );
    let _ = writeln!(
        s,
        "<text x=\"{}\" y=\"38\" text-anchor=\"middle\" fill=\"#555\">reference: {}</text>",
        w / 2.0,
        escape(reference)
    );
    if pts.is_empty() {
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">no finite, positive error to \
             plot</text>",
            w / 2.0,
            h / 2.0
        );
        s.push_str("</svg>\n");
        return s;
    }
    let all_ms = || {
        pts.iter()
            .map(|r| r.ms)
            .chain(other_pts.iter().map(|p| p.ms))
    };
    let all_rmse = || {
        pts.iter()
            .map(|r| r.rmse)
            .chain(other_pts.iter().map(|p| p.rmse))
    };
    let (x0, x1) = decades(
        all_ms().fold(f64::INFINITY, f64::min),
        all_ms().fold(0.0, f64::max),
    );
    let (y0, y1) = decades(
        all_rmse().fold(f64::INFINITY, f64::min),
        all_rmse().fold(0.0, f64::max),
    );
    let (pw, ph) = (w - left - right, h - top - bottom);
    let px = |ms: f64| left + (ms.log10() - x0) / (x1 - x0) * pw;
    let py = |e: f64| top + (1.0 - (e.log10() - y0) / (y1 - y0)) * ph;
    // Grid and decade labels.
    for d in (x0 as i32)..=(x1 as i32) {
        let x = px(10f64.powi(d));
        let _ = writeln!(
            s,
            "<line x1=\"{x:.1}\" y1=\"{top}\" x2=\"{x:.1}\" y2=\"{:.1}\" stroke=\"#ddd\"/>\
             <text x=\"{x:.1}\" y=\"{:.1}\" text-anchor=\"middle\">1e{d}</text>",
            top + ph,
            top + ph + 18.0
        );
    }
    for d in (y0 as i32)..=(y1 as i32) {
        let y = py(10f64.powi(d));
        let _ = writeln!(
            s,
            "<line x1=\"{left}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"#ddd\"/>\
             <text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">1e{d}</text>",
            left + pw,
            left - 6.0,
            y + 4.0
        );
    }
    let _ = writeln!(
        s,
        "<rect x=\"{left}\" y=\"{top}\" width=\"{pw}\" height=\"{ph}\" fill=\"none\" \
         stroke=\"black\"/>"
    );
    let _ = writeln!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">render time, ms (log)</text>",
        left + pw / 2.0,
        h - 14.0
    );
    let _ = writeln!(
        s,
        "<text x=\"18\" y=\"{:.1}\" text-anchor=\"middle\" transform=\"rotate(-90 18 {:.1})\">\
         RMSE (log)</text>",
        top + ph / 2.0,
        top + ph / 2.0
    );
    // The Monte Carlo rate through the first point, clipped to the plot.
    let first = pts[0];
    let last_ms = pts.iter().map(|r| r.ms).fold(0.0, f64::max);
    let ideal = |ms: f64| first.rmse * (ms / first.ms).powf(-0.5);
    let _ = writeln!(
        s,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#888\" \
         stroke-dasharray=\"6 4\"/>",
        px(first.ms),
        py(ideal(first.ms)),
        px(last_ms),
        py(ideal(last_ms))
    );
    let line: Vec<String> = pts
        .iter()
        .map(|r| format!("{:.1},{:.1}", px(r.ms), py(r.rmse)))
        .collect();
    let _ = writeln!(
        s,
        "<polyline points=\"{}\" fill=\"none\" stroke=\"#c0392b\" stroke-width=\"2\"/>",
        line.join(" ")
    );
    for r in &pts {
        // Labels near the right edge go to the left of their point.
        let (x, anchor) = if px(r.ms) > left + pw - 70.0 {
            (px(r.ms) - 7.0, "end")
        } else {
            (px(r.ms) + 7.0, "start")
        };
        let _ = writeln!(
            s,
            "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"4\" fill=\"#c0392b\"/><text x=\"{x:.1}\" \
             y=\"{:.1}\" text-anchor=\"{anchor}\">{} spp</text>",
            px(r.ms),
            py(r.rmse),
            py(r.rmse) - 7.0,
            r.samples
        );
    }
    if let Some(c) = other {
        let line: Vec<String> = other_pts
            .iter()
            .map(|p| format!("{:.1},{:.1}", px(p.ms), py(p.rmse)))
            .collect();
        let _ = writeln!(
            s,
            "<polyline points=\"{}\" fill=\"none\" stroke=\"#2e6da4\" stroke-width=\"2\"/>",
            line.join(" ")
        );
        for p in other_pts {
            let label = p.spp.map_or(String::new(), |n| format!("{n} spp"));
            let _ = writeln!(
                s,
                "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"7\" height=\"7\" fill=\"#2e6da4\"/>\
                 <text x=\"{:.1}\" y=\"{:.1}\" fill=\"#2e6da4\">{label}</text>",
                px(p.ms) - 3.5,
                py(p.rmse) - 3.5,
                px(p.ms) + 7.0,
                py(p.rmse) + 16.0
            );
        }
        let _ = writeln!(
            s,
            "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#c0392b\" \
             stroke-width=\"2\"/><text x=\"{:.1}\" y=\"{:.1}\">rtc</text>\
             <line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#2e6da4\" \
             stroke-width=\"2\"/><text x=\"{:.1}\" y=\"{:.1}\">{}</text>",
            left + pw - 190.0,
            top + 34.0,
            left + pw - 160.0,
            top + 34.0,
            left + pw - 154.0,
            top + 38.0,
            left + pw - 190.0,
            top + 52.0,
            left + pw - 160.0,
            top + 52.0,
            left + pw - 154.0,
            top + 56.0,
            escape(&c.label)
        );
    }
    let _ = writeln!(
        s,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#888\" \
         stroke-dasharray=\"6 4\"/><text x=\"{:.1}\" y=\"{:.1}\" fill=\"#555\">slope -1/2 \
         (Monte Carlo)</text>",
        left + pw - 190.0,
        top + 16.0,
        left + pw - 160.0,
        top + 16.0,
        left + pw - 154.0,
        top + 20.0
    );
    s.push_str("</svg>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(spp: u32, ms: f64, rmse: f64) -> Row {
        Row {
            spp,
            samples: spp,
            ms,
            ms_range: (ms, ms),
            rmse,
            rel_mse: rmse * rmse,
            psnr: -20.0 * rmse.log10(),
        }
    }

    #[test]
    fn slope_of_a_monte_carlo_series_is_minus_a_half() {
        let rows: Vec<Row> = [1u32, 4, 16, 64]
            .iter()
            .map(|&n| row(n, 2.0 * f64::from(n), 0.3 / f64::from(n).sqrt()))
            .collect();
        let slope = loglog_slope(&rows).expect("four points");
        assert!((slope + 0.5).abs() < 1e-9, "{slope}");
        assert_eq!(loglog_slope(&rows[..1]), None);
    }

    #[test]
    fn median_of_odd_even_and_no_runs() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert_eq!(median(&[7.5]), 7.5);
        assert!(median(&[]).is_nan());
    }

    #[test]
    fn csv_and_svg_have_one_entry_per_row() {
        let rows = vec![row(1, 10.0, 0.2), row(4, 40.0, 0.1)];
        let text = csv(&rows);
        assert_eq!(text.lines().count(), 3);
        assert!(text.starts_with("spp,ms,rmse,rel_mse,psnr_db\n1,10.000,0.2"));
        let svg = svg_plot(&rows, Path::new("a<b>.rt"), [8, 8], "scene at 64 spp", None);
        assert_eq!(svg.matches("<circle").count(), 2);
        assert!(svg.contains("a&lt;b&gt;.rt"));
        assert!(svg.trim_end().ends_with("</svg>"));
    }
}
