//! The subcommands, one module each, and the dispatch from the parsed command line to them.
//!
//! To add a subcommand (`compile`, `render`, `watch`, `bench`, `bvh`, `view` are planned): write
//! `cmd/<name>.rs` with a clap `Args` struct and a `run(&Args, &Context) -> Exit` function, add a
//! variant to [`Command`] and an arm to [`run`]. Printing goes through `crate::report` and
//! `crate::term`; exit codes through [`Exit`].

pub mod bench;
pub mod bvh;
pub mod check;
pub mod compile;
pub mod render;
pub mod view;
pub mod watch;

use crate::args::{Cli, GlobalArgs};
use crate::exit::Exit;
use clap::Subcommand;

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Check `.rt` files (and everything they import) for errors without compiling them.
    Check(check::Args),
    /// Compile a scene's specialised kernel to WGSL, SPIR-V, HLSL, MSL and GLSL, with manifest.json.
    Compile(compile::Args),
    /// Render a scene on the GPU to a PNG or EXR image.
    Render(render::Args),
    /// Error against run time: render at increasing samples per pixel and compare with a reference.
    ///
    /// Prints spp, render ms, RMSE, relative MSE and PSNR per level; writes CSV, JSON and a log-log
    /// SVG plot on request; `--bvh-presets` adds BVH build ms against trace ms per builder preset.
    Bench(bench::Args),
    /// Draw the scene-level and object-level BVH boxes (a colour per level) or a heat map of the
    /// nodes visited and primitives tested per pixel.
    Bvh(bvh::Args),
    /// Compile a scene, then recompile, re-emit and re-render a preview on every save (Ctrl-C stops).
    ///
    /// Watches the scene, everything it imports and the assets it loads. A save that breaks the
    /// scene prints the diagnostics and keeps the last good outputs; each reload prints what
    /// changed and how long each phase took.
    Watch(watch::Args),
    /// Show a scene in a window, refining progressively; orbit (left drag), pan (right drag) and
    /// zoom (scroll); reloads programs and scene on every save, keeping the camera.
    ///
    /// Needs a display (on Linux, `DISPLAY` or `WAYLAND_DISPLAY`); without one it says so and exits
    /// with code 1. The title shows the samples per pixel, the frame time and the rays per second.
    View(view::Args),
}

impl Command {
    /// Whether the command runs kernels on a GPU (and so wants
    /// [`rtc_runtime::gpu::apply_lavapipe_defaults`], which costs an adapter enumeration): every
    /// command but `check`, and `compile` only with `--timings driver`.
    pub fn uses_gpu(&self) -> bool {
        match self {
            Command::Check(_) => false,
            Command::Compile(args) => matches!(args.timings, Some(compile::Timings::Driver)),
            _ => true,
        }
    }

    /// The JIT a CPU driver should give this command's kernels (`--cpu-jit`; `auto` is quick only
    /// for a still `render`, or a `watch` preview, whose `--size` and `--spp` make a small render),
    /// or `None` when `render` chooses it (and the SIMD width) after the compile, from the
    /// scene's own size, samples and frames and its kernels
    /// ([`render::Args::defaults_after_compile`]).
    pub fn cpu_jit(&self) -> Option<rtc_runtime::gpu::CpuJit> {
        Some(match self {
            Command::Check(_) => rtc_runtime::gpu::CpuJit::Optimized,
            Command::Compile(args) => args.adapter.cpu_jit.resolve(None),
            Command::Render(args) if args.defaults_after_compile() => return None,
            Command::Render(args) => args.render.adapter.cpu_jit.resolve(args.still_samples()),
            Command::Bench(args) => args.adapter.cpu_jit.resolve(None),
            Command::Bvh(args) => args.render.adapter.cpu_jit.resolve(None),
            Command::Watch(args) => {
                let samples = args
                    .render
                    .samples_given()
                    .filter(|_| args.output.is_some());
                args.render.adapter.cpu_jit.resolve(samples)
            }
            Command::View(args) => args.render.adapter.cpu_jit.resolve(None),
        })
    }

    /// The samples this command renders when known before its compile (a still `render` whose
    /// `--size` and `--spp` are both given), for lavapipe's SIMD width
    /// ([`rtc_runtime::gpu::WIDE_MIN_SAMPLES`]); `None` for everything else.
    pub fn known_samples(&self) -> Option<u64> {
        match self {
            Command::Render(args) => args.still_samples(),
            _ => None,
        }
    }
}

/// What every subcommand gets besides its own arguments.
pub struct Context {
    /// The shared options as given.
    pub global: GlobalArgs,
    /// Whether to colour stderr.
    pub color: bool,
    /// Compiler options derived from the shared options.
    pub options: rtc_compiler::driver::Options,
}

/// Runs the parsed command line.
pub fn run(cli: Cli) -> Exit {
    let ctx = Context {
        color: crate::term::use_color(cli.global.color),
        options: cli.global.compiler_options(),
        global: cli.global,
    };
    if ctx.global.debug_force_ice {
        // Only reachable with a hidden flag; tests use it to check the internal-error path.
        #[allow(clippy::panic)]
        {
            panic!("forced by --debug-force-ice");
        }
    }
    match &cli.command {
        Command::Check(args) => check::run(args, &ctx),
        Command::Compile(args) => compile::run(args, &ctx),
        Command::Render(args) => render::run(args, &ctx),
        Command::Bench(args) => bench::run(args, &ctx),
        Command::Bvh(args) => bvh::run(args, &ctx),
        Command::Watch(args) => watch::run(args, &ctx),
        Command::View(args) => view::run(args, &ctx),
    }
}
