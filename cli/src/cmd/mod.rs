//! The subcommands, one module each, and the dispatch from the parsed command line to them.
//!
//! To add a subcommand (`compile`, `render`, `watch`, `bench`, `bvh`, `view` are planned): write
//! `cmd/<name>.rs` with a clap `Args` struct and a `run(&Args, &Context) -> Exit` function, add a
//! variant to [`Command`] and an arm to [`run`]. Printing goes through `crate::report` and
//! `crate::term`; exit codes through [`Exit`].

pub mod check;
pub mod compile;
pub mod render;

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
    }
}
