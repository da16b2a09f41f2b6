//! The command line's clap definitions: the top-level [`Cli`], the options every subcommand shares
//! ([`GlobalArgs`]), the choice of colour, and the option groups several subcommands flatten into
//! their own arguments, so that each such option is declared once with one name, help text, default
//! and validation: [`SceneArgs`] (`--scene`, `--size`), [`SppArgs`] (`--spp`), [`AdapterArgs`]
//! (`--adapter`), [`BvhArgs`] (`--bvh`) and [`AssetArgs`] (`--asset-root`). Each subcommand's own
//! arguments live in its module under `cmd/`.

use crate::cmd::Command;
use clap::{Args, Parser, ValueEnum};
use rtc_compiler::sema::scenes::MAX_IMAGE_SIDE;
use rtc_runtime::gpu::{AdapterChoice, CpuJit};
use rtc_runtime::render::BuildPreset;
use std::path::PathBuf;
use std::str::FromStr;

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

/// The options of every command that renders a scene file to pixels (`render`, `bvh`, `view`,
/// `watch`): which scene and its size, samples per pixel, the GPU, and where assets may come from.
/// (`bench` renders lists of sample counts, so it flattens these groups without [`SppArgs`].)
#[derive(Clone, Debug, Args)]
pub struct RenderArgs {
    /// Which scene, and its image size.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// Samples per pixel.
    #[command(flatten)]
    pub spp: SppArgs,
    /// The GPU.
    #[command(flatten)]
    pub adapter: AdapterArgs,
    /// Where else the scene's assets may come from.
    #[command(flatten)]
    pub assets: AssetArgs,
}

/// `--scene` and `--size`, shared by the commands that render a scene (`render`, `bench`, `bvh`,
/// `view`, `watch`).
#[derive(Clone, Debug, Default, Args)]
pub struct SceneArgs {
    /// Which scene, when the file declares several.
    #[arg(id = "scene", long = "scene", value_name = "NAME")]
    pub name: Option<String>,
    /// Image size instead of the scene's `width` and `height`, as `WIDTHxHEIGHT`.
    #[arg(long, value_name = "WxH")]
    pub size: Option<Size>,
}

impl SceneArgs {
    /// `--size` as `[width, height]`, the runtime's form.
    pub fn image_size(&self) -> Option<[u32; 2]> {
        self.size.map(|s| [s.width, s.height])
    }
}

/// `--spp`, shared by `render`, `bvh`, `view` and `watch` (`bench` measures lists of counts
/// instead).
#[derive(Clone, Copy, Debug, Default, Args)]
pub struct SppArgs {
    /// Samples per pixel instead of the scene's `samples`.
    #[arg(id = "spp", long = "spp", value_name = "N", value_parser = parse_spp)]
    pub samples: Option<u32>,
}

/// `--adapter`, shared by the commands that render on a GPU (`render`, `bench`, `bvh`, `view`,
/// `watch`).
#[derive(Clone, Debug, Args)]
pub struct AdapterArgs {
    /// The GPU: `auto`, `cpu`, a backend (`vulkan`, `metal`, `dx12`, `gl`) and/or part of the
    /// adapter's name, comma-separated (e.g. `gl,llvmpipe`).
    #[arg(long, value_name = "CHOICE", default_value = "auto")]
    pub adapter: String,
    /// How a CPU driver (lavapipe) compiles the kernels: `quick` turns LLVM's optimisation passes
    /// off (a third to a half of the compile time, frames 1.1 to 3.9 times slower, the same
    /// image), `optimized` keeps them; `auto` is quick for a still `rtc render` or `rtc watch`
    /// preview whose `--size` and `--spp` make at most 131,072 samples (e.g. 256x256 at 2 spp),
    /// for a still `rtc render` through a megakernel of at most 393,216 (786,432 when its scene
    /// has no secondary rays) counting the scene's own size and samples (an animation: all its
    /// frames' samples), and optimized otherwise.
    /// `GALLIVM_PERF` in the environment overrides it; GPU drivers ignore it.
    #[arg(long, value_name = "JIT", value_enum, default_value_t = CpuJitChoice::Auto)]
    pub cpu_jit: CpuJitChoice,
}

/// A `--cpu-jit` value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum CpuJitChoice {
    /// Quick for small renders, optimized otherwise.
    Auto,
    /// LLVM's optimisation passes off.
    Quick,
    /// LLVM's optimisation passes on (Mesa's default).
    Optimized,
}

impl CpuJitChoice {
    /// The JIT for a command whose render has `samples` samples in all (`None`: unknown, or work
    /// that goes on: progressive views, benchmarks).
    pub fn resolve(self, samples: Option<u64>) -> CpuJit {
        match self {
            CpuJitChoice::Auto => CpuJit::for_samples(samples),
            CpuJitChoice::Quick => CpuJit::Quick,
            CpuJitChoice::Optimized => CpuJit::Optimized,
        }
    }

    /// The value as written on a command line.
    pub fn as_str(self) -> &'static str {
        match self {
            CpuJitChoice::Auto => "auto",
            CpuJitChoice::Quick => "quick",
            CpuJitChoice::Optimized => "optimized",
        }
    }
}

impl RenderArgs {
    /// Pixels times samples per pixel when `--size` and `--spp` both give them (the scene's own
    /// size or samples are not known before its compile, and count as unknown).
    pub fn samples_given(&self) -> Option<u64> {
        let [w, h] = self.scene.image_size()?;
        let spp = self.spp.samples?;
        Some(u64::from(w) * u64::from(h) * u64::from(spp))
    }
}

impl AdapterArgs {
    /// The adapter asked for, else a message for a usage error. Parsed here rather than by clap so
    /// that each command checks it at its own step (`watch` only when it renders a preview).
    pub fn choice(&self) -> Result<AdapterChoice, String> {
        AdapterChoice::from_str(&self.adapter).map_err(|e| e.to_string())
    }
}

/// `--bvh`, shared by the commands that build BVHs for a render (`render`, `bench`, `bvh`).
#[derive(Clone, Copy, Debug, Args)]
pub struct BvhArgs {
    /// BVH builder preset: `fast` builds quickly; `quality` traces faster on large triangles.
    #[arg(
        id = "bvh",
        long = "bvh",
        value_name = "BVH",
        value_enum,
        default_value_t = BvhPreset::Fast
    )]
    pub preset: BvhPreset,
    /// Keep one BVH per object. By default the static objects whose meshes are their own (or
    /// small) are flattened into one world-space BVH, which traces faster in scenes of many small
    /// objects.
    #[arg(long = "no-flatten")]
    pub no_flatten: bool,
}

/// `--exec`, shared by the commands that render (`render`, `bench`, `view`, `watch`).
#[derive(Clone, Copy, Debug, Default, Args)]
pub struct ExecArgs {
    /// Execution model: `megakernel` traces each pixel's samples in one kernel; `wavefront` runs
    /// stage kernels (count, compact, trace, which also makes a new sample's camera ray, shade,
    /// finish, and shadow when the shade stage replays its shadow rays) in rounds over each tile,
    /// the middle ones over the paths still running.
    #[arg(long = "exec", value_name = "MODEL", value_enum)]
    pub exec: Option<ExecChoice>,
}

impl ExecArgs {
    /// The model asked for (`None`: the scene's `exec` setting decides).
    pub fn model(&self) -> Option<rtc_compiler::kernel::ExecModel> {
        self.exec.map(|e| match e {
            ExecChoice::Wavefront => rtc_compiler::kernel::ExecModel::Wavefront,
            ExecChoice::Megakernel => rtc_compiler::kernel::ExecModel::Megakernel,
        })
    }
}

/// An `--exec` value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ExecChoice {
    /// One kernel per pixel's samples.
    Megakernel,
    /// Stage kernels in rounds.
    Wavefront,
}

/// A `--bvh` value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum BvhPreset {
    /// Binned SAH.
    Fast,
    /// Finer binning and spatial splits.
    Quality,
}

impl From<BvhPreset> for BuildPreset {
    fn from(p: BvhPreset) -> Self {
        match p {
            BvhPreset::Fast => BuildPreset::Fast,
            BvhPreset::Quality => BuildPreset::Quality,
        }
    }
}

/// `--size WxH`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

impl FromStr for Size {
    type Err = String;

    fn from_str(text: &str) -> Result<Size, String> {
        let bad = || format!("`{text}` is not a size; write WIDTHxHEIGHT, e.g. 640x480");
        let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
        let parse = |s: &str| {
            s.trim()
                .parse::<u32>()
                .ok()
                .filter(|&n| (1..=MAX_IMAGE_SIDE).contains(&n))
        };
        match (parse(w), parse(h)) {
            (Some(width), Some(height)) => Ok(Size { width, height }),
            _ => Err(format!(
                "`{text}`: width and height must be whole numbers from 1 to {MAX_IMAGE_SIDE}"
            )),
        }
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

/// The format of the image `path` names, checked before any work: it ends in `.png` or `.exr` and
/// [`check_output_path`] accepts it (else a message for a usage error). `what` names it in the
/// message ("the image", "the screenshot", "the preview").
pub fn image_output(
    path: &std::path::Path,
    what: &str,
) -> Result<crate::cmd::render::Format, String> {
    let Some(format) = crate::cmd::render::output_format(path) else {
        return Err(format!(
            "cannot write `{}`: {what} must end in `.png` or `.exr`",
            path.display()
        ));
    };
    check_output_path(path, what)?;
    Ok(format)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_and_bad_ones_say_why() {
        assert_eq!(
            "640x480".parse::<Size>(),
            Ok(Size {
                width: 640,
                height: 480
            })
        );
        assert_eq!(
            "2X3".parse::<Size>().map(|s| (s.width, s.height)),
            Ok((2, 3))
        );
        assert!("640".parse::<Size>().unwrap_err().contains("WIDTHxHEIGHT"));
        assert!("0x5".parse::<Size>().unwrap_err().contains("1 to 16384"));
        assert!("axb".parse::<Size>().is_err());
    }

    /// The JIT `rtc ARGS…` asks a CPU driver for before anything runs (`None`: `render` chooses
    /// it after the compile).
    fn jit(args: &[&str]) -> Option<CpuJit> {
        let cli = Cli::try_parse_from(std::iter::once("rtc").chain(args.iter().copied()))
            .expect("the arguments parse");
        cli.command.cpu_jit()
    }

    #[test]
    fn only_small_still_renders_and_previews_get_the_quick_jit() {
        let small = ["--size", "64x48", "--spp", "1"];
        let render = |extra: &[&str]| {
            let mut a = vec!["render", "s.rt", "-o", "s.png"];
            a.extend_from_slice(extra);
            jit(&a)
        };
        assert_eq!(render(&small), Some(CpuJit::Quick));
        assert_eq!(
            render(&["--size", "256x256", "--spp", "2"]),
            Some(CpuJit::Quick)
        );
        // Larger ones, and the scene's own size or samples, which are not known before its
        // compile: `render` chooses after it, from the scene and its kernels.
        assert_eq!(render(&["--size", "256x256", "--spp", "3"]), None);
        assert_eq!(render(&["--size", "64x48"]), None);
        assert_eq!(render(&["--spp", "1"]), None);
        assert_eq!(render(&[]), None);
        // Animations too (their frames may be the scene's); the flag decides over `auto`, after
        // the compile when the scene's size or samples decide the SIMD width.
        assert_eq!(render(&[&small[..], &["--frames", "0..2"]].concat()), None);
        assert_eq!(
            render(&[&small[..], &["--cpu-jit", "optimized"]].concat()),
            Some(CpuJit::Optimized)
        );
        assert_eq!(
            render(&[&small[..], &["--cpu-jit", "quick"]].concat()),
            Some(CpuJit::Quick)
        );
        assert_eq!(render(&["--cpu-jit", "quick"]), None);
        // A watch gets it for a small preview only; views and benchmarks run on.
        assert_eq!(
            jit(&[&["watch", "s.rt", "-o", "p.png"][..], &small[..]].concat()),
            Some(CpuJit::Quick)
        );
        assert_eq!(
            jit(&[&["watch", "s.rt"][..], &small[..]].concat()),
            Some(CpuJit::Optimized)
        );
        assert_eq!(
            jit(&[&["view", "s.rt"][..], &small[..]].concat()),
            Some(CpuJit::Optimized)
        );
        assert_eq!(jit(&["bench", "s.rt"]), Some(CpuJit::Optimized));
        assert_eq!(
            jit(&["bench", "--compile", "--cpu-jit", "quick"]),
            Some(CpuJit::Quick)
        );
        assert_eq!(jit(&["check", "s.rt"]), Some(CpuJit::Optimized));
    }

    #[test]
    fn only_still_renders_with_size_and_samples_know_their_samples_before_the_compile() {
        let known = |args: &[&str]| {
            Cli::try_parse_from(std::iter::once("rtc").chain(args.iter().copied()))
                .expect("the arguments parse")
                .command
                .known_samples()
        };
        let render = ["render", "s.rt", "-o", "s.png"];
        let long = ["--size", "4096x4096", "--spp", "2"];
        assert_eq!(
            known(&[&render[..], &long[..]].concat()),
            Some(rtc_runtime::gpu::WIDE_MIN_SAMPLES)
        );
        assert_eq!(
            known(&[&render[..], &long[..], &["--cpu-jit", "optimized"]].concat()),
            Some(1 << 25)
        );
        // The scene's own size or samples, an animation and other commands: not known here.
        assert_eq!(
            known(&[&render[..], &["--size", "4096x4096"]].concat()),
            None
        );
        assert_eq!(
            known(&[&render[..], &long[..], &["--frames", "0..2"]].concat()),
            None
        );
        assert_eq!(known(&[&["view", "s.rt"][..], &long[..]].concat()), None);
        assert_eq!(known(&["bench", "s.rt"]), None);
    }
}
