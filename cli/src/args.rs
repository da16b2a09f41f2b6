//! The command line's clap definitions: the top-level [`Cli`], the options every subcommand shares
//! ([`GlobalArgs`]) and the choice of colour. Each subcommand's own arguments live in its module under
//! `cmd/`.

use crate::cmd::Command;
use clap::{Args, Parser, ValueEnum};
use std::path::PathBuf;

/// rtc: a compiler and runtime for programmable ray tracing on any GPU.
#[derive(Debug, Parser)]
#[command(name = "rtc", version, propagate_version = true)]
#[command(subcommand_required = true, arg_required_else_help = true)]
pub struct Cli {
    /// Options shared by every subcommand.
    #[command(flatten)]
    pub global: GlobalArgs,
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// Options shared by every subcommand.
#[derive(Debug, Args)]
pub struct GlobalArgs {
    /// When to colour the output: `auto` colours when stderr is a terminal and `NO_COLOR` is unset.
    #[arg(long, value_enum, default_value_t = ColorChoice::Auto, global = true)]
    pub color: ColorChoice,
    /// The standard library folder (`std/…` imports); defaults to `RTC_STDLIB` or the built-in one.
    #[arg(long, value_name = "DIR", global = true)]
    pub stdlib: Option<PathBuf>,
    /// Panic on purpose after parsing the arguments, to test the internal-error path.
    #[arg(long, global = true, hide = true)]
    pub debug_force_ice: bool,
}

/// `--asset-root DIR`, shared by the commands that load a scene's assets (`render`, `bench`,
/// `bvh`, `view`, `watch`).
#[derive(Clone, Debug, Default, Args)]
pub struct AssetArgs {
    /// A folder the scene's meshes, images and glTF files (and the files a glTF file names) may
    /// also come from, besides the scene's own folder; repeatable, searched in order after it.
    /// Paths in scenes stay relative: `--asset-root models` lets a scene write
    /// `load_mesh("bunny.obj")` for `models/bunny.obj`.
    #[arg(long = "asset-root", value_name = "DIR")]
    pub asset_roots: Vec<PathBuf>,
}

impl AssetArgs {
    /// The folders, each checked to be an existing folder (else a message for a usage error).
    pub fn roots(&self) -> Result<rtc_runtime::assets::AssetRoots, String> {
        for dir in &self.asset_roots {
            if !dir.is_dir() {
                return Err(format!("--asset-root `{}`: no such folder", dir.display()));
            }
        }
        Ok(rtc_runtime::assets::AssetRoots::new(
            self.asset_roots.iter().cloned(),
        ))
    }
}

/// `--color`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    /// Colour when writing to a terminal and `NO_COLOR` is not set.
    Auto,
    /// Always colour.
    Always,
    /// Never colour.
    Never,
}

/// `--message-format`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MessageFormat {
    /// rustc-style text on stderr.
    Human,
    /// One JSON object per diagnostic and line, on stdout.
    Json,
}

impl GlobalArgs {
    /// The compiler options these arguments ask for.
    pub fn compiler_options(&self) -> rtc_compiler::driver::Options {
        let mut options = rtc_compiler::driver::Options::default();
        if let Some(dir) = &self.stdlib {
            options.stdlib_dir = dir.clone();
        }
        options
    }
}

/// Parses a samples-per-pixel count (`--spp`, bench's lists), bounded like a scene's `samples`:
/// from 1 to [`MAX_SAMPLES`](rtc_compiler::sema::scenes::MAX_SAMPLES), so an absurd count is
/// refused at once instead of rendering for hours.
pub fn parse_spp(text: &str) -> Result<u32, String> {
    let max = rtc_compiler::sema::scenes::MAX_SAMPLES;
    match text.trim().parse::<u64>() {
        Ok(n) if (1..=u64::from(max)).contains(&n) => Ok(n as u32),
        Ok(0) => Err("the samples per pixel must be at least 1".to_string()),
        Ok(_) => Err(format!(
            "`{text}` samples per pixel is more than rtc renders: at most {max}, the limit of a \
             scene's `samples`"
        )),
        Err(_) => Err(format!(
            "`{text}` is not a sample count; write a whole number from 1 to {max}"
        )),
    }
}

/// Checks, before any work, that `path` can be written as an output file: its folder exists and
/// is a folder, and `path` itself is not a folder. `what` names the option in the message
/// (e.g. "`-o`"). The extension is the caller's business.
pub fn check_output_path(path: &std::path::Path, what: &str) -> Result<(), String> {
    let shown = path.display();
    if path.as_os_str().is_empty() {
        return Err(format!("{what} is empty: name the file to write"));
    }
    if path.is_dir() {
        return Err(format!(
            "cannot write {what} `{shown}`: it is a folder; name a file in it"
        ));
    }
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => std::path::Path::new("."),
    };
    match std::fs::metadata(parent) {
        Ok(m) if m.is_dir() => {
            if m.permissions().readonly() {
                Err(format!(
                    "cannot write {what} `{shown}`: the folder `{}` is read-only",
                    parent.display()
                ))
            } else {
                Ok(())
            }
        }
        Ok(_) => Err(format!(
            "cannot write {what} `{shown}`: `{}` is not a folder",
            parent.display()
        )),
        Err(_) => Err(format!(
            "cannot write {what} `{shown}`: the folder `{}` does not exist (rtc does not create \
             it)",
            parent.display()
        )),
    }
}
