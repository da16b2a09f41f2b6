//! `rtc compile <scene.rt> [--target wgsl,spirv,hlsl,msl,glsl] [--out DIR]`: compiles one scene's
//! specialised kernel to every requested target and writes `kernel.wgsl`, `kernel.spv`, `kernel.hlsl`,
//! `kernel.metal`, `kernel.comp` (and `bounds.*` when the scene has custom geometry) plus
//! `manifest.json`.
//!
//! `--all-programs` builds the unspecialised kernel (every program of the loaded modules, every
//! feature) for comparison. `--emit ast|hir|naga` prints an intermediate form instead of writing files.

use super::Context;
use crate::args::MessageFormat;
use crate::exit::Exit;
use crate::{report, term};
use rtc_compiler::back::{self, Target};
use rtc_compiler::kernel::{self, manifest, BOUNDS_ENTRY, RENDER_ENTRY};
use rtc_compiler::link::LinkOptions;
use std::path::PathBuf;

/// An intermediate form `--emit` prints.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Emit {
    /// The parsed syntax tree of each root file.
    Ast,
    /// The typed high-level IR of the whole program.
    Hir,
    /// The naga IR module of the render kernel.
    Naga,
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
    /// Print an intermediate form instead of writing the outputs.
    #[arg(long, value_enum)]
    pub emit: Option<Emit>,
    /// How to print diagnostics.
    #[arg(long, value_enum, default_value_t = MessageFormat::Human)]
    pub message_format: MessageFormat,
}

fn parse_target(s: &str) -> Result<Target, String> {
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
    };
    let compiled =
        match kernel::compile_scene(&args.paths, args.scene.as_deref(), &ctx.options, &link) {
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
            term::print(&format!("{:#?}\n", compiled.checked.program));
            return Exit::Success;
        }
        Some(Emit::Naga) => {
            term::print(&format!("{:#?}\n", compiled.render));
            return Exit::Success;
        }
        _ => {}
    }
    if let Err(e) = kernel::save_registry(&compiled) {
        term::eprint(&format!("warning: cannot save the program registry: {e}\n"));
    }
    let targets = if args.target.is_empty() {
        Target::ALL.to_vec()
    } else {
        args.target.clone()
    };
    if let Err(e) = std::fs::create_dir_all(&args.out) {
        return report::usage_error(
            &format!("cannot create `{}`: {e}", args.out.display()),
            ctx.color,
        );
    }
    let resources = rtc_compiler::abi::resources(compiled.bindings.iter().copied());
    let mut modules = vec![("kernel", &compiled.render, RENDER_ENTRY)];
    if let Some(b) = &compiled.bounds {
        modules.push(("bounds", b, BOUNDS_ENTRY));
    }
    for (stem, module, entry) in modules {
        for &t in &targets {
            let bytes = match back::write(module, t, entry, &resources) {
                Ok(b) => b,
                Err(e) => {
                    term::eprint(&format!(
                        "error[ICE]: {e}\nnote: this is a bug in rtc; please report it\n"
                    ));
                    return Exit::Failure;
                }
            };
            let ext = t.file_name().rsplit('.').next().unwrap_or("out");
            let path = args.out.join(format!("{stem}.{ext}"));
            if let Err(e) = std::fs::write(&path, bytes) {
                return report::usage_error(
                    &format!("cannot write `{}`: {e}", path.display()),
                    ctx.color,
                );
            }
        }
    }
    let manifest_path = args.out.join("manifest.json");
    if let Err(e) = std::fs::write(&manifest_path, manifest::manifest_json(&compiled)) {
        return report::usage_error(
            &format!("cannot write `{}`: {e}", manifest_path.display()),
            ctx.color,
        );
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
    Exit::Success
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
