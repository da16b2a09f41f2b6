//! `rtc render <scene.rt> -o out.png|out.exr`: compiles a scene for this GPU, renders it and writes
//! the image.
//!
//! Order of work: the output format and the flags are checked first (a usage error, exit code 2,
//! before anything is compiled); then the scene is compiled (errors are diagnostics, exit code 1,
//! without touching the GPU); then the adapter is chosen and printed; then the runtime builds the
//! scene (assets, BVHs, uploads, pipelines) and renders, with a progress bar on stderr when there
//! are more than a few tiles. At the end it prints the adapter, BVH build, upload and render times
//! and rays per second (primary rays, and every ray traced) on stdout, with one line per kernel
//! (compiled or reused, and its driver compile time) and the state of the on-disk pipeline cache.
//!
//! `--frames A..B` renders frames of the scene's animation through one renderer (built once; per
//! frame the animation's state at `frame / fps` is applied, then the frame is rendered and written
//! to `-o` with its number in place of `%04d`); `--shard I/N` renders every N-th of them (see
//! [`frames`] and docs/animation.md). A still image of an animated scene is its frame 0.
//!
//! A `.gltf` or `.glb` file instead of a scene is rendered through a scene written for it with
//! sensible defaults (a camera framing it, a light, a background; see [`model`]), and the defaults
//! chosen are printed before rendering. `--report` prints, before rendering, the import report of
//! each glTF file (`rtc_runtime::assets::model::report`): what was imported and what was not.
//!
//! Failures of the runtime (no adapter, an asset that cannot be loaded, a device limit) are printed
//! as one `error:` line (an unreadable asset as an E0902 diagnostic at the scene's string) and exit
//! with code 1. Nothing here panics on bad input; the process is never exited from here.

pub mod frames;
pub mod model;

use super::Context;
use crate::args::{BvhArgs, CpuJitChoice, ExecArgs, MessageFormat, RenderArgs};
use crate::exit::Exit;
use crate::{report, term};
use rtc_compiler::kernel::{compile_scene_with, CompiledScene, ExecModel, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_compiler::sema::hir::SceneDesc;
use rtc_runtime::animation;
use rtc_runtime::assets::confine::resolve_scene_path;
use rtc_runtime::assets::model::report;
use rtc_runtime::assets::{load_gltf_with, AssetRoots};
use rtc_runtime::gpu::{Gpu, KernelReport};
use rtc_runtime::image_out::{write_exr, write_png, ToneMap};
use rtc_runtime::render::{RenderError, RenderOptions, RenderStats, Renderer};
use rtc_runtime::scene::TablePlacement;
use std::path::{Path, PathBuf};

/// More tiles than this get a progress bar.
const PROGRESS_MIN_TILES: u64 = 4;

/// Arguments of `rtc render`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scene file (the files it imports are read too), or a glTF file (`.gltf`, `.glb`) to
    /// render with default camera, light and background where it has none.
    #[arg(value_name = "SCENE")]
    pub path: PathBuf,
    /// The image to write: `.png` (8-bit sRGB, values clipped to 1) or `.exr` (linear float).
    #[arg(short, long, value_name = "FILE")]
    pub output: PathBuf,
    /// Scene, size, samples, GPU and asset folders.
    #[command(flatten)]
    pub render: RenderArgs,
    /// The BVH builder.
    #[command(flatten)]
    pub bvh: BvhArgs,
    /// The execution model.
    #[command(flatten)]
    pub exec: ExecArgs,
    /// Render frames of the scene's animation: `A..B` (A to B-1), `A..=B`, `N` or `all` (the
    /// scene's `frames`); `-o` then names each frame with `%d` or `%04d`.
    #[arg(long, value_name = "RANGE")]
    pub frames: Option<String>,
    /// Frames per second of the animation instead of the scene's `fps`: frame `n` is at
    /// `n / fps` seconds.
    #[arg(long, value_name = "F", value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub fps: Option<u32>,
    /// Render only frames I, I+N, I+2N, … of the range (frames are identical to an unsharded
    /// run's); `auto/N` reads I from JOB_COMPLETION_INDEX (Kubernetes Indexed Jobs) or
    /// SLURM_ARRAY_TASK_ID (Slurm job arrays).
    #[arg(long, value_name = "I/N")]
    pub shard: Option<String>,
    /// Before rendering, print the import report of each glTF model (the file itself, or the
    /// scene's `model` entries): its meshes, materials and their textures, lights, cameras and
    /// animation, and everything it holds that was not imported, named with what it affects.
    #[arg(long)]
    pub report: bool,
}

impl Args {
    /// The samples (pixels times samples per pixel) of a still render whose `--size` and `--spp`
    /// are both given; `None` for an animation (`--frames`, `--fps` or `--shard`) or when the
    /// scene's own size or samples decide, which are not known before its compile.
    pub fn still_samples(&self) -> Option<u64> {
        self.render.samples_given().filter(|_| self.is_still())
    }

    /// Whether this is a still render (no `--frames`, `--fps` or `--shard`).
    fn is_still(&self) -> bool {
        self.frames.is_none() && self.shard.is_none() && self.fps.is_none()
    }

    /// Whether rtc's settings for a CPU driver (its JIT and SIMD width,
    /// [`rtc_runtime::gpu::apply_lavapipe_defaults`]) are chosen after the compile, from what the
    /// compiled scene says: for an animation (its frames, and without `--size` and `--spp` their
    /// size and samples, are the scene's), for a still render without both `--size` and `--spp`,
    /// and for `--cpu-jit auto` on a still render that they do not make small enough for the
    /// quick JIT whatever its kernels ([`rtc_runtime::gpu::CpuJit::for_render`]).
    pub fn defaults_after_compile(&self) -> bool {
        self.still_samples().is_none_or(|n| {
            self.render.adapter.cpu_jit == CpuJitChoice::Auto
                && n > rtc_runtime::gpu::QUICK_JIT_MAX_SAMPLES
        })
    }
}

/// What `--frames`, `--fps` and `--shard` asked for, checked before compiling.
struct FrameArgs {
    range: frames::FrameRange,
    shard: frames::Shard,
    fps: Option<u32>,
}

/// `--frames`/`--shard`/`--fps`, or `None` for a still image (usage errors as messages).
fn frame_args(args: &Args) -> Result<Option<FrameArgs>, String> {
    if args.frames.is_none() && args.shard.is_none() && args.fps.is_none() {
        return Ok(None);
    }
    let range = match &args.frames {
        Some(f) => frames::parse_frames(f)?,
        None => frames::FrameRange::All,
    };
    let shard = match &args.shard {
        Some(s) => frames::parse_shard(s, &|v| std::env::var(v).ok())?,
        None => frames::Shard { index: 0, count: 1 },
    };
    let single = matches!(range, frames::FrameRange::Span { start, end } if end - start == 1);
    if !single && !frames::has_placeholder(&args.output) {
        return Err(format!(
            "-o `{}` has no frame number: with several frames, write `%d` or `%04d` in the \
             file name (e.g. `out/frame_%04d.png`)",
            args.output.display()
        ));
    }
    Ok(Some(FrameArgs {
        range,
        shard,
        fps: args.fps,
    }))
}

/// The output formats, by extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// `.png`
    Png,
    /// `.exr`
    Exr,
}

/// The format of an output file, by its extension (`None`: neither `.png` nor `.exr`).
pub fn output_format(path: &Path) -> Option<Format> {
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    match ext.as_str() {
        "png" => Some(Format::Png),
        "exr" => Some(Format::Exr),
        _ => None,
    }
}

/// Runs `rtc render`.
pub fn run(args: &Args, ctx: &Context) -> Exit {
    let format = match crate::args::image_output(&args.output, "the image") {
        Ok(f) => f,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let choice = match args.render.adapter.choice() {
        Ok(c) => c,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let roots = match args.render.assets.roots() {
        Ok(r) => r,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let animate = match frame_args(args) {
        Ok(a) => a,
        Err(e) => return report::usage_error(&e, ctx.color),
    };

    // A bare glTF file: render a scene written for it, saying which defaults it got.
    let synth = if model::is_model(&args.path) {
        if args.render.scene.name.is_some() {
            return report::usage_error(
                "--scene chooses among the scenes of a .rt file; a glTF file has one",
                ctx.color,
            );
        }
        match model::synthesize(&args.path, &roots) {
            Ok(s) => {
                for d in &s.defaults {
                    term::print(&format!("default {d}\n"));
                }
                Some(s)
            }
            Err(e) => return fail(&e.to_string(), ctx),
        }
    } else {
        None
    };
    let scene_path = synth.as_ref().map_or(&args.path, |s| &s.path);
    // A bare glTF file's scene names it relative to its folder, searched first. The link step
    // reads the scene's model files with the same roots, to link only what they hold.
    let asset_roots = match &synth {
        Some(s) => s.asset_roots(&roots),
        None => roots,
    };
    let link = LinkOptions {
        asset_roots: asset_roots.clone(),
        ..LinkOptions::default()
    };

    let exec = args.exec.model();
    // A small still render's time is its kernels' compile: on a CPU adapter, a scene left at
    // `EXEC_AUTO` then runs the wavefront model, whose stage kernels compile faster (with uniform
    // tables, only for a heavy megakernel or a large BVH: `wavefront_min_weight`). The adapter
    // is asked for before the compile only then (a failure here is reported after the compile's
    // diagnostics, as always).
    let small = exec.is_none()
        && args
            .still_samples()
            .is_some_and(|n| n <= rtc_runtime::gpu::WAVEFRONT_PREVIEW_MAX_SAMPLES);
    let early_gpu = if small { Gpu::new(&choice).ok() } else { None };
    // With uniform tables (lavapipe whose loads are per-lane code) a light megakernel compiles
    // faster than the stage kernels, so only a heavier one gives way to them.
    let (auto, wavefront_min_weight) = match early_gpu
        .as_ref()
        .map(|g| g.description())
        .filter(|d| d.device_type == wgpu::DeviceType::Cpu)
    {
        Some(d) if TablePlacement::Auto.wants_uniform(d) => (
            ExecModel::Wavefront,
            rtc_runtime::gpu::WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES,
        ),
        Some(_) => (ExecModel::Wavefront, 0),
        None => (ExecModel::Megakernel, 0),
    };
    let compiled = match compile_scene_with(
        std::slice::from_ref(scene_path),
        args.render.scene.name.as_deref(),
        &ctx.options,
        &link,
        &KernelOptions {
            exec,
            auto,
            wavefront_min_weight,
            render_size: args.render.scene.image_size(),
            render_spp: args.render.spp.samples,
            ..KernelOptions::default()
        },
    ) {
        Ok(c) => c,
        Err(failure) => {
            let exit = report::diagnostics(
                &failure.checked.sources,
                &failure.diagnostics,
                MessageFormat::Human,
                ctx.color,
                "render",
            );
            if exit == Exit::Success {
                // No error was reported, yet nothing was compiled: never exit 0 for that.
                return fail(
                    &format!("`{}` could not be compiled", args.path.display()),
                    ctx,
                );
            }
            return Exit::Failure;
        }
    };
    let render_weight = compiled.render_weight;
    let left_to_auto = compiled
        .checked
        .program
        .as_ref()
        .is_some_and(|p| p.scenes[compiled.scene].settings.exec == 0);
    if !compiled.checked.diagnostics.is_empty() {
        // Warnings only (errors would have failed the compile).
        report::diagnostics(
            &compiled.checked.sources,
            &compiled.checked.diagnostics,
            MessageFormat::Human,
            ctx.color,
            "render",
        );
    }

    if args.report {
        if let Some(desc) = scene_of(&compiled) {
            print_model_reports(desc, scene_path, &asset_roots, ctx);
        }
    }

    if args.defaults_after_compile() {
        // Nothing has touched a GPU yet, and the compile's threads are done.
        let samples = render_samples(args, animate.as_ref(), &compiled);
        let jit = match args.render.adapter.cpu_jit {
            CpuJitChoice::Auto => rtc_runtime::gpu::CpuJit::for_render(
                // Unknown: larger than any bound, so the optimising JIT.
                samples.unwrap_or(u64::MAX),
                compiled.exec == ExecModel::Wavefront,
                compiled.linked.config.has_secondary_rays,
            ),
            chosen => chosen.resolve(samples),
        };
        rtc_runtime::gpu::apply_lavapipe_defaults(jit, samples);
    }
    let gpu = match early_gpu.map_or_else(|| Gpu::new(&choice), Ok) {
        Ok(gpu) => gpu,
        Err(e) => return fail(&e.to_string(), ctx),
    };

    let options = RenderOptions {
        size: args.render.scene.image_size(),
        samples: args.render.spp.samples,
        bvh: args.bvh.preset.into(),
        flatten: !args.bvh.no_flatten,
        asset_roots,
        exec,
        // A profile of the wavefront stages (README, `rtc render`): any value but empty or `0`.
        stage_times: std::env::var("RTC_STAGE_TIMES").is_ok_and(|v| !v.is_empty() && v != "0"),
        ..RenderOptions::default()
    };
    if let Some(frame_args) = animate {
        return render_frames(args, format, &frame_args, &gpu, &compiled, options, ctx);
    }
    let rendered = Renderer::new(&gpu, &compiled, options).and_then(|mut renderer| {
        // An animated scene's still image is its frame 0.
        if let Some(desc) = scene_of(&compiled) {
            let state = animation::evaluate(desc, 0.0);
            animation::apply(&mut renderer, &state)?;
        }
        let total = renderer.total_tiles();
        let bar = progress_bar(total);
        let result = renderer.render(&mut |done, total| {
            if let Some(bar) = &bar {
                bar.set_length(total);
                bar.set_position(done);
            }
        });
        if let Some(bar) = bar {
            bar.finish_and_clear();
        }
        result
    });
    let result = match rendered {
        Ok(r) => r,
        Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
    };

    let write_report = match write_image(&args.output, format, &result.image) {
        Ok(r) => r,
        Err(e) => return fail(&e.to_string(), ctx),
    };
    for w in &result.stats.warnings {
        warn(w, ctx);
    }
    if result.stats.nonfinite_samples > 0 {
        warn(
            &format!(
                "{} samples were NaN or infinite and counted as zero",
                result.stats.nonfinite_samples
            ),
            ctx,
        );
    }
    if write_report.nonfinite_pixels > 0 {
        warn(
            &format!(
                "{} pixels were not finite and were written as black",
                write_report.nonfinite_pixels
            ),
            ctx,
        );
    }
    if auto == ExecModel::Wavefront && left_to_auto && result.stats.exec == ExecModel::Wavefront {
        term::print(&format!(
            "exec: wavefront (a render of at most {} samples on a CPU adapter: its stage kernels \
             compile faster than the megakernel; `--exec megakernel` keeps the megakernel)\n",
            rtc_runtime::gpu::WAVEFRONT_PREVIEW_MAX_SAMPLES
        ));
    } else if auto == ExecModel::Wavefront
        && left_to_auto
        && result.stats.exec == ExecModel::Megakernel
    {
        // The compiler kept the megakernel by its rule for light kernels of small geometry
        // (`compiler/src/pipeline.rs`); the weight says how light.
        term::print(&format!(
            "exec: megakernel (a render of at most {} samples on lavapipe with uniform tables: a \
             megakernel of weight {render_weight}, below {wavefront_min_weight}, compiles faster \
             than the stage kernels; `--exec wavefront` runs them)\n",
            rtc_runtime::gpu::WAVEFRONT_PREVIEW_MAX_SAMPLES
        ));
    }
    term::print(&summary(&result.stats, &args.output));
    Exit::Success
}

/// `--report`: the import report of each glTF file the scene's `model` entries name (each once),
/// found as the render finds it (next to the scene file `scene_path`, else in `roots`); a file
/// that cannot be read is a warning here (the render then fails on it with its diagnostic).
fn print_model_reports(desc: &SceneDesc, scene_path: &Path, roots: &AssetRoots, ctx: &Context) {
    if desc.models.is_empty() {
        warn(
            "--report: the scene has no `model` entry; nothing to report",
            ctx,
        );
        return;
    }
    let scene_dir = scene_path.parent().unwrap_or(Path::new(""));
    let mut seen: Vec<&Path> = Vec::new();
    for model in &desc.models {
        if seen.contains(&model.path.as_path()) {
            continue;
        }
        seen.push(&model.path);
        let file = match resolve_scene_path(&model.path, scene_dir, roots) {
            Ok(f) => f,
            Err((written, problem)) => {
                warn(&format!("--report: `{written}`: {problem}"), ctx);
                continue;
            }
        };
        match load_gltf_with(&file, roots) {
            Ok(scene) => {
                let name = file.file_name().map_or_else(
                    || file.display().to_string(),
                    |n| n.to_string_lossy().into_owned(),
                );
                term::print(&report(&name, &scene));
            }
            Err(e) => warn(&format!("--report: {e}"), ctx),
        }
    }
}

/// The samples (pixels times samples per pixel) a render of `compiled` takes: `--size` and
/// `--spp` where given, else the scene's settings, times the frames of an animation (`animate`;
/// the whole range, not a shard's share, so that every shard chooses as the unsharded render
/// does). `None` if the compiled program had no scene description to read them from, or when the
/// frames are the length of its glTF models' animations, known only once they are loaded.
fn render_samples(
    args: &Args,
    animate: Option<&FrameArgs>,
    compiled: &CompiledScene,
) -> Option<u64> {
    let Some(desc) = scene_of(compiled) else {
        return args.still_samples();
    };
    let settings = &desc.settings;
    let [w, h] = args
        .render
        .scene
        .image_size()
        .unwrap_or([settings.width, settings.height]);
    let spp = args.render.spp.samples.unwrap_or(settings.samples);
    let frames = match animate.map(|a| a.range) {
        None => 1,
        Some(frames::FrameRange::Span { start, end }) => end - start,
        Some(frames::FrameRange::All) => animation::frame_count_of(desc)?,
    };
    Some(u64::from(w) * u64::from(h) * u64::from(spp) * u64::from(frames))
}

/// The scene description of a compiled scene.
fn scene_of(compiled: &CompiledScene) -> Option<&SceneDesc> {
    let program = compiled.checked.program.as_ref()?;
    Some(&program.scenes[compiled.scene])
}

/// `rtc render --frames`: every frame of the shard through one renderer, built once; each frame
/// sets the animation's state at its time, renders and writes its image.
fn render_frames(
    args: &Args,
    format: Format,
    fa: &FrameArgs,
    gpu: &Gpu,
    compiled: &CompiledScene,
    options: RenderOptions,
    ctx: &Context,
) -> Exit {
    let Some(desc) = scene_of(compiled) else {
        return fail("the scene was not compiled", ctx);
    };
    let fps = fa.fps.unwrap_or(desc.settings.fps);
    let started = std::time::Instant::now();
    let mut renderer = match Renderer::new(gpu, compiled, options) {
        Ok(r) => r,
        Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
    };
    let (start, end) = match fa.range {
        frames::FrameRange::All => (0, animation::frame_count(desc, &renderer, fps)),
        frames::FrameRange::Span { start, end } => (start, end),
    };
    if end - start > 1 && !frames::has_placeholder(&args.output) {
        return report::usage_error(
            &format!(
                "-o `{}` has no frame number: the scene has {} frames; write `%d` or `%04d` in \
                 the file name (e.g. `out/frame_%04d.png`)",
                args.output.display(),
                end - start
            ),
            ctx.color,
        );
    }
    let list = frames::shard_frames(start, end, fa.shard);
    if !animation::is_animated_with(desc, &renderer) {
        warn(
            "the scene has no `animate` entry and its models no animation: every frame is the same image",
            ctx,
        );
    }
    let bar = frame_bar(list.len() as u64);
    let mut first: Option<RenderStats> = None;
    let mut last: Option<RenderStats> = None;
    let loop_start = std::time::Instant::now();
    for (n, &frame) in list.iter().enumerate() {
        let state = animation::evaluate(desc, animation::frame_time(frame, fps));
        let result =
            animation::apply(&mut renderer, &state).and_then(|()| renderer.render(&mut |_, _| {}));
        let result = match result {
            Ok(r) => r,
            Err(e) => {
                if let Some(bar) = &bar {
                    bar.finish_and_clear();
                }
                return render_failure(&e, &compiled.checked.sources, ctx);
            }
        };
        let path = frames::frame_path(&args.output, frame);
        if let Err(e) = write_image(&path, format, &result.image) {
            if let Some(bar) = &bar {
                bar.finish_and_clear();
            }
            return fail(&e.to_string(), ctx);
        }
        if let Some(bar) = &bar {
            bar.set_position(n as u64 + 1);
        }
        if first.is_none() {
            for w in &result.stats.warnings {
                warn(w, ctx);
            }
            first = Some(result.stats.clone());
        }
        last = Some(result.stats);
    }
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    let (Some(first), Some(last)) = (first, last) else {
        term::print(&format!(
            "shard {}/{} of frames {start}..{end}: no frame to render\n",
            fa.shard.index, fa.shard.count
        ));
        return Exit::Success;
    };
    let secs = loop_start.elapsed().as_secs_f64();
    let mut out = summary(&first, &frames::frame_path(&args.output, list[0]));
    out.push_str(&format!(
        "frames: {} of {start}..{end} (shard {}/{}) at {fps} fps to {}\n",
        list.len(),
        fa.shard.index,
        fa.shard.count,
        args.output.display()
    ));
    out.push_str(&format!(
        "  frames    {:>10.2} ms  ({:.2} frames/s; {:.2} s with setup)\n",
        secs * 1e3,
        list.len() as f64 / secs.max(1e-9),
        started.elapsed().as_secs_f64()
    ));
    out.push_str(&format!(
        "  bvh       {} BLAS builds at setup, {} over the frames after it; {} TLAS builds\n",
        first.blas_builds,
        last.blas_builds - first.blas_builds,
        last.tlas_builds
    ));
    term::print(&out);
    Exit::Success
}

/// A progress bar over frames on stderr (hidden when stderr is not a terminal, by indicatif).
fn frame_bar(total: u64) -> Option<indicatif::ProgressBar> {
    if total <= 1 {
        return None;
    }
    let bar = indicatif::ProgressBar::with_draw_target(
        Some(total),
        indicatif::ProgressDrawTarget::stderr(),
    );
    if let Ok(style) = indicatif::ProgressStyle::with_template(
        "rendering {bar:40} {pos}/{len} frames  {elapsed_precise} (eta {eta})",
    ) {
        bar.set_style(style);
    }
    Some(bar)
}

/// Writes `image` to `path` in `format` (PNG with the default tone map, or EXR). Shared by
/// `rtc render` and `rtc watch`.
pub fn write_image(
    path: &Path,
    format: Format,
    image: &rtc_runtime::image_out::LinearImage,
) -> Result<rtc_runtime::image_out::WriteReport, rtc_runtime::image_out::ImageError> {
    match format {
        Format::Png => write_png(path, image, &ToneMap::default()),
        Format::Exr => write_exr(path, image),
    }
}

/// A progress bar on stderr for renders of more than a few tiles (hidden when stderr is not a
/// terminal, by indicatif).
fn progress_bar(total: u64) -> Option<indicatif::ProgressBar> {
    if total <= PROGRESS_MIN_TILES {
        return None;
    }
    let bar = indicatif::ProgressBar::with_draw_target(
        Some(total),
        indicatif::ProgressDrawTarget::stderr(),
    );
    if let Ok(style) = indicatif::ProgressStyle::with_template(
        "rendering {bar:40} {pos}/{len} tiles  {elapsed_precise} (eta {eta})",
    ) {
        bar.set_style(style);
    }
    Some(bar)
}

/// The closing report, one figure per line.
pub fn summary(s: &RenderStats, output: &Path) -> String {
    let mut out = String::new();
    out.push_str(&format!("adapter: {}\n", s.adapter));
    out.push_str(&format!("host: {}\n", rtc_runtime::gpu::HostCpu::detect()));
    out.push_str(&format!(
        "rendered {}x{} at {} spp ({} pass{} of {}{}) to {}\n",
        s.width,
        s.height,
        s.samples,
        s.passes,
        if s.passes == 1 { "" } else { "es" },
        s.samples_per_pass,
        if s.passes_per_dispatch > 1 {
            format!(", {} a dispatch", s.passes_per_dispatch)
        } else {
            String::new()
        },
        output.display()
    ));
    let flattened = match s.flattened {
        (0, _) => String::new(),
        (objects, bvhs) => format!(
            "; {objects} static objects flattened into {bvhs} world-space BVH{}",
            if bvhs == 1 { "" } else { "s" }
        ),
    };
    out.push_str(&format!(
        "  bvh build {:>10.2} ms  ({} mesh{}, {} triangles, {} objects; {} object BVH{} built, {} scene-level{flattened})\n",
        s.bvh_build_ms,
        s.meshes,
        if s.meshes == 1 { "" } else { "es" },
        s.triangles,
        s.objects,
        s.blas_builds,
        if s.blas_builds == 1 { "" } else { "s" },
        s.tlas_builds
    ));
    out.push_str(&format!(
        "  pipelines {:>10.2} ms  (kernel creation and the driver's compile)\n",
        s.pipeline_ms
    ));
    out.push_str(&kernel_lines(&s.kernels, "    "));
    if !s.uniform_tables.is_empty() {
        out.push_str(&format!(
            "    uniform tables: {}\n",
            s.uniform_tables.join(", ")
        ));
    }
    if let Some(cache) = &s.pipeline_cache {
        out.push_str(&format!("    pipeline cache: {cache}\n"));
    }
    let decoded = match s.decoded_textures {
        0 => String::new(),
        n => format!(
            "; {n} sRGB texture{} stored decoded, as linear half floats",
            if n == 1 { "" } else { "s" }
        ),
    };
    out.push_str(&format!(
        "  upload    {:>10.2} ms  ({:.2} MB{decoded})\n",
        s.upload_ms,
        s.bytes_uploaded as f64 / 1e6
    ));
    out.push_str(&format!(
        "  render    {:>10.2} ms  ({:.2} M primary rays/s, {:.2} M rays/s in all: {} rays traced)\n",
        s.render_ms,
        s.rays_per_second / 1e6,
        s.traced_rays_per_second / 1e6,
        s.rays_traced
    ));
    if s.rounds > 0 {
        // The wavefront model: how busy compaction kept the listed stages' lanes.
        out.push_str(&format!(
            "    rounds: {}, running paths listed {} of the tiles' {} slots over those rounds ({:.1} %)\n",
            s.rounds,
            s.listed_slots,
            s.slot_rounds,
            100.0 * s.listed_slots as f64 / s.slot_rounds.max(1) as f64
        ));
    }
    if !s.stage_ms.is_empty() {
        // `RenderOptions::stage_times` (`RTC_STAGE_TIMES`): each wavefront dispatch timed alone.
        let stages: Vec<String> = s
            .stage_ms
            .iter()
            .map(|(label, ms)| format!("{} {ms:.2} ms", label.trim_start_matches("rtc ")))
            .collect();
        out.push_str(&format!(
            "    stages (each dispatch waited for): {} in {} rounds\n",
            stages.join(", "),
            s.rounds
        ));
    }
    out
}

/// One line per kernel: its name, compiled or reused, and milliseconds in all and of the driver
/// (`create_compute_pipeline` and the warm-up dispatch where lavapipe compiles). Shared by
/// `rtc render`, `rtc watch` and `rtc compile --timings`.
pub fn kernel_lines(kernels: &[KernelReport], indent: &str) -> String {
    let width = kernels.iter().map(|k| k.label.len()).max().unwrap_or(0);
    let mut out = String::new();
    for k in kernels {
        out.push_str(&format!(
            "{indent}{:<width$}  {:<21}  {:>10.2} ms  (driver {:.2} ms)\n",
            k.label,
            k.origin.to_string(),
            k.total_ms(),
            k.driver_ms(),
        ));
    }
    out
}

/// Prints `error: message` and returns [`Exit::Failure`].
pub fn fail(message: &str, ctx: &Context) -> Exit {
    term::eprint(&format!(
        "{}: {message}\n",
        term::paint("error", 31, ctx.color)
    ));
    Exit::Failure
}

/// Prints `warning: message`.
pub fn warn(message: &str, ctx: &Context) {
    term::eprint(&format!(
        "{}: {message}\n",
        term::paint("warning", 33, ctx.color)
    ));
}

/// A runtime failure: a diagnostic when it points into the scene (E0902), else one line.
pub fn render_failure(e: &RenderError, sources: &rtc_compiler::SourceMap, ctx: &Context) -> Exit {
    if let RenderError::Scene(scene) = e {
        if let Some(d) = scene.to_diagnostic() {
            return report::diagnostics(
                sources,
                std::slice::from_ref(&d),
                MessageFormat::Human,
                ctx.color,
                "render",
            );
        }
    }
    fail(&e.to_string(), ctx)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn output_formats_by_extension() {
        assert_eq!(output_format(Path::new("a.png")), Some(Format::Png));
        assert_eq!(output_format(Path::new("a.EXR")), Some(Format::Exr));
        assert_eq!(output_format(Path::new("a.jpg")), None);
        assert_eq!(output_format(Path::new("a")), None);
    }

    #[test]
    fn an_animation_counts_the_samples_of_all_its_frames_whatever_the_shard() {
        let path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/thesis_scene/animated.rt");
        let compiled = compile_scene_with(
            std::slice::from_ref(&path),
            None,
            &rtc_compiler::driver::Options::default(),
            &LinkOptions::default(),
            &KernelOptions::default(),
        )
        .unwrap_or_else(|_| panic!("the animated thesis scene compiles"));
        let samples = |extra: &[&str]| {
            let mut argv = vec!["rtc", "render", "animated.rt", "-o", "f_%04d.png"];
            argv.extend_from_slice(extra);
            let cli = <crate::args::Cli as clap::Parser>::try_parse_from(argv).expect("parses");
            let crate::cmd::Command::Render(args) = cli.command else {
                panic!("a render");
            };
            let animate = frame_args(&args).expect("valid frame arguments");
            (
                args.defaults_after_compile(),
                render_samples(&args, animate.as_ref(), &compiled),
            )
        };
        // 24 frames of 1920x1080 at 1 spp: from 2^25 samples lavapipe keeps its own SIMD width
        // on a CPU without AVX-512, so every shard must count the whole animation.
        let all = Some(24 * 1920 * 1080);
        assert_eq!(samples(&["--frames", "all"]), (true, all));
        assert_eq!(samples(&["--frames", "all", "--shard", "2/3"]), (true, all));
        assert_eq!(samples(&["--shard", "0/3"]), (true, all));
        assert_eq!(
            samples(&["--frames", "0..4", "--size", "64x48", "--spp", "2"]),
            (true, Some(4 * 64 * 48 * 2))
        );
        assert_eq!(samples(&["--frames", "5"]), (true, Some(1920 * 1080)));
        // A still render: the scene's own size and samples, once.
        assert_eq!(samples(&[]), (true, Some(1920 * 1080)));
        assert_eq!(
            samples(&["--size", "64x48", "--spp", "1"]),
            (false, Some(64 * 48))
        );
    }
}
