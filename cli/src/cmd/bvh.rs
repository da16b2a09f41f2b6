//! `rtc bvh <scene.rt> -o out.png`: the BVH visualizer (thesis 4.2.4, Figs. 17–18).
//!
//! Without `--heatmap` it draws the boxes of the scene-level BVH and, below its leaves, the
//! object-level BVHs, one colour per level (red, orange, yellow, green, …), over the rendered
//! scene (or over black with `--boxes-only`). `--level N` draws one level, otherwise levels 0 to
//! `--max-level` (default 5) are drawn; `--object NAME` draws that object's BVH only (level 0 is
//! its root), its boxes transformed to world space. The boxes are drawn on the CPU against the
//! camera's own rays, which two debug kernels return (`DebugMode::RayOrigin`, `RayDirection`),
//! so any camera program works: see `rtc_runtime::bvh_view::wireframe`.
//!
//! With `--heatmap` it draws, from the `DebugMode::Counts` debug kernel, the BVH nodes visited and
//! the primitives tested by each pixel's camera ray (closest hit, no secondary rays), as two
//! false-colour panels scaled from 0 to their maximum, with a colour bar, and prints the maximum
//! and the means.
//!
//! Errors: an unknown `--object` lists the scene's objects; a `--level` deeper than the tree names
//! the deepest level; more than 8192 boxes at the chosen levels are refused (each box is tested
//! against each pixel); all are found before anything is rendered. Nothing here panics on user
//! input.

use super::bench::{compile, print_warnings};
use super::render::{fail, render_failure, warn, write_image};
use super::Context;
use crate::args::{BvhArgs, RenderArgs};
use crate::exit::Exit;
use crate::{report, term};
use rtc_compiler::kernel::{CompiledScene, DebugMode, KernelOptions};
use rtc_runtime::bvh_view::{
    collect_boxes, heatmap, level_colour_name, overlay, wireframe, CameraRays, HeatStats, Levels,
};
use rtc_runtime::gpu::Gpu;
use rtc_runtime::render::{RenderError, RenderOptions, Renderer};
use std::path::PathBuf;

/// The most boxes one picture draws (the drawing tests each box against each pixel's ray).
const MAX_BOXES: usize = 8192;

/// Arguments of `rtc bvh`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scene file.
    #[arg(value_name = "SCENE")]
    pub path: PathBuf,
    /// The image to write (`.png` or `.exr`).
    #[arg(short, long, value_name = "FILE")]
    pub output: PathBuf,
    /// Draw only this level (0 = the root).
    #[arg(long, value_name = "N", conflicts_with = "max_level")]
    pub level: Option<u32>,
    /// Draw levels 0 to this one.
    #[arg(long, value_name = "N", default_value_t = 5)]
    pub max_level: u32,
    /// Draw this object's BVH only (boxes in world space).
    #[arg(long, value_name = "NAME")]
    pub object: Option<String>,
    /// Draw nodes visited and primitives tested per pixel instead of boxes.
    #[arg(long, conflicts_with_all = ["level", "object", "boxes_only"])]
    pub heatmap: bool,
    /// Draw the boxes over black instead of over the render.
    #[arg(long)]
    pub boxes_only: bool,
    /// Line width of the box edges, pixels.
    #[arg(long, value_name = "PX", default_value_t = 1.5)]
    pub line_width: f32,
    /// Scene, size, samples, GPU and asset folders.
    #[command(flatten)]
    pub render: RenderArgs,
    /// The BVH builder.
    #[command(flatten)]
    pub bvh: BvhArgs,
}

/// Runs `rtc bvh`.
pub fn run(args: &Args, ctx: &Context) -> Exit {
    let format = match crate::args::image_output(&args.output, "the image") {
        Ok(f) => f,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    if !(args.line_width.is_finite() && args.line_width > 0.0) {
        return report::usage_error(
            "--line-width must be a positive number of pixels",
            ctx.color,
        );
    }
    let choice = match args.render.adapter.choice() {
        Ok(c) => c,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let roots = match args.render.assets.roots() {
        Ok(r) => r,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let debug = |mode| KernelOptions {
        debug: Some(mode),
        ..KernelOptions::default()
    };
    let scene = args.render.scene.name.as_deref();
    let normal = match compile(&args.path, scene, &KernelOptions::default(), ctx, "draw") {
        Ok(c) => c,
        Err(exit) => return exit,
    };
    print_warnings(&normal, ctx, "draw");
    let gpu = match Gpu::new(&choice) {
        Ok(gpu) => gpu,
        Err(e) => return fail(&e.to_string(), ctx),
    };
    term::print(&format!("adapter: {}\n", gpu.description()));
    term::print(&format!("host: {}\n", rtc_runtime::gpu::HostCpu::detect()));
    let options = RenderOptions {
        size: args.render.scene.image_size(),
        samples: args.render.spp.samples,
        bvh: args.bvh.preset.into(),
        flatten: !args.bvh.no_flatten,
        asset_roots: roots,
        ..RenderOptions::default()
    };

    if args.heatmap {
        let counts = match compile(&args.path, scene, &debug(DebugMode::Counts), ctx, "draw") {
            Ok(c) => c,
            Err(exit) => return exit,
        };
        let (values, [w, h]) = match debug_pass(&gpu, &counts, options) {
            Ok(x) => x,
            Err(e) => return render_failure(&e, &counts.checked.sources, ctx),
        };
        let (image, nodes, prims) = heatmap(&values, w, h);
        if let Err(e) = write_image(&args.output, format, &image) {
            return fail(&e.to_string(), ctx);
        }
        term::print(&format!(
            "heat map of {w}x{h} camera rays (closest hit, no secondary rays) to {}\n{}{}\
             left panel: nodes visited, right panel: primitives tested; colour bar from 0 (dark) \
             to the maximum (light)\n",
            args.output.display(),
            heat_line("nodes visited", &nodes),
            heat_line("primitives tested", &prims),
        ));
        return Exit::Success;
    }

    // The boxes first (an unknown object or level is reported before anything is rendered).
    let mut renderer = match Renderer::new(&gpu, &normal, options.clone()) {
        Ok(r) => r,
        Err(e) => return render_failure(&e, &normal.checked.sources, ctx),
    };
    let levels = match args.level {
        Some(l) => Levels::One(l),
        None => Levels::UpTo(args.max_level),
    };
    let set = match collect_boxes(renderer.entities(), args.object.as_deref(), levels) {
        Ok(s) => s,
        Err(e) => return fail(&e.to_string(), ctx),
    };
    if let Some(l) = args.level {
        if l > set.deepest {
            return fail(
                &format!(
                    "level {l} is deeper than the BVH{}: its deepest level is {}",
                    args.object
                        .as_deref()
                        .map(|o| format!(" of `{o}`"))
                        .unwrap_or_default(),
                    set.deepest
                ),
                ctx,
            );
        }
    }
    if set.boxes.len() > MAX_BOXES {
        return fail(
            &format!(
                "{} boxes at the chosen levels are too many to draw (at most {MAX_BOXES}: the \
                 drawing tests every box against every pixel); choose one level with --level N \
                 or fewer with --max-level N",
                set.boxes.len()
            ),
            ctx,
        );
    }
    let base = if args.boxes_only {
        None
    } else {
        match renderer.render(&mut |_, _| {}) {
            Ok(r) => {
                for w in &r.stats.warnings {
                    warn(w, ctx);
                }
                Some(r.image)
            }
            Err(e) => return render_failure(&e, &normal.checked.sources, ctx),
        }
    };
    let [w, h] = renderer.size();
    drop(renderer);
    let mut rays = Vec::new();
    for mode in [DebugMode::RayOrigin, DebugMode::RayDirection] {
        let compiled = match compile(&args.path, scene, &debug(mode), ctx, "draw") {
            Ok(c) => c,
            Err(exit) => return exit,
        };
        match debug_pass(&gpu, &compiled, options.clone()) {
            Ok((values, _)) => rays.push(values),
            Err(e) => return render_failure(&e, &compiled.checked.sources, ctx),
        }
    }
    let (origins, dirs) = match rays.as_slice() {
        [o, d] => (o.as_slice(), d.as_slice()),
        _ => return fail("internal error: the camera rays are missing", ctx),
    };
    let camera = CameraRays {
        origins,
        dirs,
        width: w,
        height: h,
    };
    let edges = match wireframe(&camera, &set.boxes, args.line_width) {
        Ok(e) => e,
        Err(e) => return fail(&e.to_string(), ctx),
    };
    let image = overlay(base.as_ref(), &edges, w, h);
    if let Err(e) = write_image(&args.output, format, &image) {
        return fail(&e.to_string(), ctx);
    }
    let edge_pixels = edges.iter().filter(|e| e.is_some()).count();
    let shown: Vec<u32> = match levels {
        Levels::One(l) => vec![l],
        Levels::UpTo(m) => (0..=m.min(set.deepest)).collect(),
    };
    let legend: Vec<String> = shown
        .iter()
        .map(|&l| format!("{l} {}", level_colour_name(l)))
        .collect();
    term::print(&format!(
        "drew {} boxes of {} ({} nodes, deepest level {}) to {}: {edge_pixels} edge pixels\n\
         levels: {}\n",
        set.boxes.len(),
        match &args.object {
            Some(o) => format!("the object-level BVH of `{o}`"),
            None => "the scene-level BVH and the object-level BVHs below it".to_string(),
        },
        set.nodes,
        set.deepest,
        args.output.display(),
        legend.join(", ")
    ));
    if set.boxes.is_empty() {
        warn("no box at the chosen levels", ctx);
    }
    Exit::Success
}

/// One pass of a debug kernel: its raw per-pixel values and the image size.
fn debug_pass(
    gpu: &Gpu,
    compiled: &CompiledScene,
    options: RenderOptions,
) -> Result<(Vec<[f32; 4]>, [u32; 2]), RenderError> {
    let mut r = Renderer::new(gpu, compiled, options)?;
    let values = r.render_debug()?;
    Ok((values, r.size()))
}

fn heat_line(what: &str, s: &HeatStats) -> String {
    format!(
        "  {what:<18} max {:>8}  mean {:>9.2} per pixel  mean {:>9.2} over the {} pixels that hit\n",
        s.max, s.mean, s.mean_hit, s.hit_pixels
    )
}
