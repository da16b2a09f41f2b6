//! `rtc compile <scene.rt> [--target wgsl,spirv,hlsl,msl,glsl] [--out DIR]`: compiles one scene's
//! specialised kernel to every requested target and writes `kernel.wgsl`, `kernel.spv`, `kernel.hlsl`,
//! `kernel.metal`, `kernel.comp` (and `bounds.*` when the scene has custom geometry) plus
//! `manifest.json`. The compile, targets included, is `rtc_compiler::pipeline::compile`; this
//! command only writes its outputs to files.
//!
//! `--timings` prints how long each phase of the compiler took (`CompiledScene::timings`);
//! `--timings driver` then creates the scene's kernels on the GPU (`--adapter`) as `rtc render`
//! does and prints, per kernel, whether it was compiled or reused and the driver's compile time.
//! Without an adapter it says so and still exits 0.
//!
//! `--all-programs` builds the unspecialised kernel (every program of the loaded modules, every
//! feature) for comparison. `--emit ast|hir|naga` prints an intermediate form instead of writing files:
//! the syntax tree, the typed HIR as source-like text (`rtc_compiler::sema::hir::print`), or the
//! render kernel as WGSL with naga handles (`rtc_compiler::back::naga_listing`).

use super::Context;
use crate::args::{AdapterArgs, MessageFormat};
use crate::exit::Exit;
use crate::{report, term};
use rtc_compiler::back::{self, Target};
use rtc_compiler::kernel::{self, KernelOptions};
use rtc_compiler::link::LinkOptions;
use rtc_compiler::pipeline::{self, Compiled};
use rtc_runtime::gpu::{Gpu, KernelReport};
use rtc_runtime::render::create_scene_kernels;
use rtc_runtime::scene::{TablePlacement, UniformTables, UNIFORM_TABLE_BYTES};
use std::path::PathBuf;

/// An intermediate form `--emit` prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Emit {
    /// The parsed syntax tree of each root file (Rust debug form).
    Ast,
    /// The typed high-level IR of the whole program (user files, standard library, kernel) as
    /// source-like text: every local with its type, literals typed, conversions and defaults
    /// explicit, scenes evaluated.
    Hir,
    /// The render kernel's naga module as WGSL, each struct, constant, global and function under
    /// a `// kind [i]` comment naming its naga handle.
    Naga,
}

/// What `--timings` prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Timings {
    /// The compiler's phases.
    Compiler,
    /// The compiler's phases, then each kernel created on the GPU (`--adapter`): compiled or
    /// reused, and the driver's compile time.
    Driver,
}

/// Arguments of `rtc compile`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The file(s) declaring the scene (and what they import).
    #[arg(required = true, value_name = "SCENE.rt")]
    pub paths: Vec<PathBuf>,
    /// Targets, comma-separated: wgsl, spirv, hlsl, msl, glsl (default: all).
    #[arg(long, value_delimiter = ',', value_parser = parse_target)]
    pub target: Vec<Target>,
    /// Output folder (created if missing).
    #[arg(long, short, default_value = "out", value_name = "DIR")]
    pub out: PathBuf,
    /// Which scene, when the files declare several.
    #[arg(long, value_name = "NAME")]
    pub scene: Option<String>,
    /// Build the unspecialised kernel: every program and feature, not only what the scene uses.
    #[arg(long)]
    pub all_programs: bool,
    /// Also write the wavefront model's stage kernels (`--exec wavefront`: `wf_trace.wgsl`, …).
    #[command(flatten)]
    pub exec: crate::args::ExecArgs,
    /// Print an intermediate form instead of writing the outputs.
    #[arg(long, value_enum)]
    pub emit: Option<Emit>,
    /// How to print diagnostics.
    #[arg(long, value_enum, default_value_t = MessageFormat::Human)]
    pub message_format: MessageFormat,
    /// Print how long each phase of the compile took (`--timings` alone: `compiler`); `driver`
    /// also creates the kernels on the GPU and prints each one's driver compile time.
    #[arg(long, value_enum, value_name = "WHAT", num_args = 0..=1, default_missing_value = "compiler")]
    pub timings: Option<Timings>,
    /// The GPU for `--timings driver`.
    #[command(flatten)]
    pub adapter: AdapterArgs,
}

pub fn parse_target(s: &str) -> Result<Target, String> {
    Target::from_name(s)
        .ok_or_else(|| format!("unknown target `{s}` (expected wgsl, spirv, hlsl, msl or glsl)"))
}

/// Runs `rtc compile`.
pub fn run(args: &Args, ctx: &Context) -> Exit {
    if args.emit == Some(Emit::Ast) {
        return emit_ast(args, ctx);
    }
    let link = LinkOptions {
        all_programs: args.all_programs,
        ..LinkOptions::default()
    };
    let targets = if args.emit.is_some() {
        Vec::new()
    } else if args.target.is_empty() {
        Target::ALL.to_vec()
    } else {
        args.target.clone()
    };
    let request = pipeline::Request {
        paths: &args.paths,
        scene: args.scene.as_deref(),
        options: &ctx.options,
        link: &link,
        kernel: &KernelOptions {
            exec: args.exec.model(),
            ..KernelOptions::default()
        },
        targets: &targets,
    };
    let Compiled {
        scene: compiled,
        outputs,
    } = match pipeline::compile(&request) {
        Ok(c) => c,
        Err(f) => {
            return report::diagnostics(
                &f.checked.sources,
                &f.diagnostics,
                args.message_format,
                ctx.color,
                "compile",
            )
        }
    };
    // Warnings of a successful compile are still shown.
    let _ = report::diagnostics(
        &compiled.checked.sources,
        &compiled.checked.diagnostics,
        args.message_format,
        ctx.color,
        "compile",
    );
    match args.emit {
        Some(Emit::Hir) => {
            if let Some(program) = &compiled.checked.program {
                term::print(&rtc_compiler::sema::hir::print::program(program));
            }
            return Exit::Success;
        }
        Some(Emit::Naga) => {
            return match back::naga_listing(&compiled.render) {
                Ok(text) => {
                    term::print(&text);
                    Exit::Success
                }
                Err(e) => {
                    term::eprint(&format!(
                        "error[ICE]: {e}\nnote: this is a bug in rtc; please report it\n"
                    ));
                    Exit::Failure
                }
            };
        }
        _ => {}
    }
    if let Err(e) = kernel::save_registry(&compiled) {
        term::eprint(&format!("warning: cannot save the program registry: {e}\n"));
    }
    if let Err(e) = std::fs::create_dir_all(&args.out) {
        return report::usage_error(
            &format!("cannot create `{}`: {e}", args.out.display()),
            ctx.color,
        );
    }
    match outputs
        .map_err(OutputError::Backend)
        .and_then(|outputs| write_files(&outputs, &args.out))
    {
        Ok(_) => {}
        Err(OutputError::Backend(e)) => {
            if let Some(d) = e.limit_diagnostic(&compiled.checked.sources) {
                return report::diagnostics(
                    &compiled.checked.sources,
                    &[d],
                    args.message_format,
                    ctx.color,
                    "compile",
                );
            }
            term::eprint(&format!(
                "error[ICE]: {e}\nnote: this is a bug in rtc; please report it\n"
            ));
            return Exit::Failure;
        }
        Err(OutputError::Write(e)) => return report::usage_error(&e, ctx.color),
    }
    term::eprint(&format!(
        "compiled scene `{}` for {} into {}\n",
        compiled
            .checked
            .program
            .as_ref()
            .map(|p| p.scenes[compiled.scene].name.as_str())
            .unwrap_or("?"),
        targets
            .iter()
            .map(|t| t.name())
            .collect::<Vec<_>>()
            .join(", "),
        args.out.display()
    ));
    if let Some(what) = args.timings {
        term::print(&compiler_timings(&compiled.timings));
        term::print(&kernel_weights(&compiled));
        if what == Timings::Driver {
            return driver_timings(&compiled, &args.adapter, ctx);
        }
    }
    Exit::Success
}

/// The compiler's phases, one per line, and their sum.
fn compiler_timings(phases: &[(&'static str, f64)]) -> String {
    let mut out = String::from("compiler phases:\n");
    for (name, ms) in phases {
        out.push_str(&format!("  {name:<32} {ms:>10.2} ms\n"));
    }
    let total: f64 = phases.iter().map(|(_, ms)| ms).sum();
    out.push_str(&format!("  {:<32} {total:>10.2} ms\n", "total"));
    out
}

/// The size of each kernel as a driver compiles it ([`kernel::weight::inlined_weight`]).
fn kernel_weights(compiled: &kernel::CompiledScene) -> String {
    let mut out = format!(
        "kernel weights (expressions with every call inlined):\n  {:<32} {:>10}\n",
        kernel::RENDER_ENTRY,
        compiled.render_weight
    );
    for s in compiled.stages.iter().flatten() {
        let entry = s.stage.entry();
        let w = kernel::weight::inlined_weight(&s.module, entry).unwrap_or(0);
        out.push_str(&format!("  {entry:<32} {w:>10}\n"));
    }
    out
}

/// Creates the scene's kernels on the chosen adapter and prints what each cost; without an
/// adapter, says so (and still succeeds: the compile did).
fn driver_timings(compiled: &kernel::CompiledScene, adapter: &AdapterArgs, ctx: &Context) -> Exit {
    let choice = match adapter.choice() {
        Ok(c) => c,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let gpu = match Gpu::new(&choice) {
        Ok(gpu) => gpu,
        Err(e) => {
            term::print(&format!(
                "driver: no per-kernel compile times: no GPU adapter could be had ({e})\n"
            ));
            return Exit::Success;
        }
    };
    // What `rtc render` does on this adapter for a scene whose small tables fit a uniform buffer.
    let tables = UniformTables::for_adapter(TablePlacement::from_env(), gpu.description());
    let kernels = match create_scene_kernels(
        &gpu,
        compiled,
        compiled.exec,
        compiled.bounds.is_some(),
        tables,
    ) {
        Ok(k) => k,
        Err(e) => return super::render::fail(&e.to_string(), ctx),
    };
    let reports: Vec<KernelReport> = kernels
        .render
        .iter()
        .chain(kernels.bounds.as_ref().map(|(k, _)| k))
        .map(|k| k.report())
        .collect();
    let mut out = format!("driver ({}):\n", gpu.description());
    out.push_str(&super::render::kernel_lines(&reports, "  "));
    if !tables.is_empty() {
        out.push_str(&format!(
            "  uniform tables: {} (as `rtc render` places them on this adapter when they fit in {} KiB)\n",
            tables.names().join(", "),
            UNIFORM_TABLE_BYTES >> 10
        ));
    }
    out.push_str(&format!(
        "  pipeline cache: {}\n",
        gpu.pipeline_cache_status()
    ));
    term::print(&out);
    for w in gpu.take_warnings() {
        super::render::warn(&w, ctx);
    }
    Exit::Success
}

/// Why [`write_outputs`] stopped.
#[derive(Debug)]
pub enum OutputError {
    /// A backend could not write a module: a bug in rtc (the module was validated), or a
    /// function too large for a target ([`back::BackendError::TooLarge`], a user error).
    Backend(back::BackendError),
    /// A file could not be written; the message names it.
    Write(String),
}

/// Writes the kernel (and the bounds kernel, if any) for every target, then `manifest.json`, into
/// `out` (which must exist): phase 7 of the pipeline ([`pipeline::write_targets`]), then the files.
/// Returns the files written, in order. Used by `rtc watch`.
pub fn write_outputs(
    compiled: &kernel::CompiledScene,
    targets: &[Target],
    out: &std::path::Path,
) -> Result<Vec<PathBuf>, OutputError> {
    let outputs = pipeline::write_targets(compiled, targets).map_err(OutputError::Backend)?;
    write_files(&outputs, out)
}

/// Writes each output into `out` under its name; returns the paths, in order.
fn write_files(
    outputs: &[pipeline::Output],
    out: &std::path::Path,
) -> Result<Vec<PathBuf>, OutputError> {
    let mut written = Vec::new();
    for o in outputs {
        let path = out.join(&o.name);
        std::fs::write(&path, &o.bytes)
            .map_err(|e| OutputError::Write(format!("cannot write `{}`: {e}", path.display())))?;
        written.push(path);
    }
    Ok(written)
}

fn emit_ast(args: &Args, ctx: &Context) -> Exit {
    let mut map = rtc_compiler::SourceMap::new();
    for p in &args.paths {
        let text = match std::fs::read_to_string(p) {
            Ok(t) => t,
            Err(e) => {
                return report::usage_error(
                    &format!("cannot read `{}`: {e}", p.display()),
                    ctx.color,
                )
            }
        };
        let file = map.add(p.display().to_string(), Some(p.clone()), text);
        let (ast, diags) = rtc_compiler::syntax::parse(file, &map.get(file).text);
        term::print(&format!("{ast:#?}\n"));
        if !diags.is_empty() {
            return report::diagnostics(&map, &diags, args.message_format, ctx.color, "parse");
        }
    }
    Exit::Success
}
