//! `rtc watch <scene.rt> [--out DIR] [-o preview.png]`: compiles a scene, then recompiles it on every
//! save, re-emitting the targets and re-rendering a preview, until Ctrl-C.
//!
//! What is watched is found from the last compile, not from a folder: every file the compiler read
//! (the scene, its imports, the standard-library files it reaches) and every asset the scene names
//! (`load_mesh`, `load_image`, `model`). The folders holding them are watched (not the files, so an
//! editor that saves by writing a new file and renaming it is seen too), and events for other files
//! are ignored, except new `.rt` files after a failed build (the missing import may just have been
//! created). Events are debounced: a reload starts once no event came for `--debounce-ms`. A folder
//! is watched only after a build named a file in it, so what was written there in between sent no
//! event: right after registering a folder, its watched files are hashed again and, while the build
//! fails, its `.rt` files written since the build began are looked at ([`Session::missed`]); any
//! such change starts a reload at once.
//!
//! What a reload does, as a list ([`Session::reload`]):
//! 1. hash every watched file whose length or modification time changed since it was last read
//!    (any file written within two seconds of that read: [`Seen`]); when no content changed (a
//!    `touch`, an editor writing the same text), nothing else happens;
//! 2. when only assets changed, the compile is skipped and only the preview is rendered again (the
//!    kernel code does not depend on the contents of meshes and images; a glTF `model` file counts
//!    as a source, since the link step reads which light types and alpha modes it holds);
//! 3. otherwise the scene is compiled, with parsed modules cached by content hash
//!    ([`rtc_compiler::cache`]): only the files whose text changed are parsed again;
//! 4. the targets and `manifest.json` are written (the same code as `rtc compile`);
//! 5. the preview, when asked for, is rendered and written (the same code as `rtc render`).
//!
//! Guarantees: a user error (a diagnostic, an asset that cannot be read) is printed and the watch
//! goes on; the outputs of the last good build are left as they were (nothing is written before the
//! compile succeeded). Each reload prints what changed, how long each phase took and the latency
//! from the edit (the newest modification time of the changed files) to the emitted code and to the
//! new preview, and which of the preview's kernels were compiled and which reused. Ctrl-C ends
//! the watch with exit code 0. A GPU that cannot be had disables the preview
//! (with an error line), not the watch.

use super::compile::{parse_target, write_outputs, OutputError};
use super::render::{write_image, Format};
use super::Context;
use crate::args::RenderArgs;
use crate::exit::Exit;
use crate::{report, term};
use rtc_compiler::back::Target;
use rtc_compiler::cache::{content_hash, ModuleCache};
use rtc_compiler::diag::{self, Diagnostic, Severity};
use rtc_compiler::driver::Options;
use rtc_compiler::kernel::{
    compile_scene_with, save_registry, CompiledScene, ExecModel, KernelOptions, ShadowRays,
};
use rtc_compiler::link::LinkOptions;
use rtc_compiler::sema::hir::SceneDesc;
use rtc_compiler::SourceMap;
use rtc_runtime::assets::AssetRoots;
use rtc_runtime::gpu::{AdapterChoice, Gpu, KernelOrigin, KernelReport};
use rtc_runtime::render::{RenderOptions, Renderer};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::sync::Arc;
use std::time::{Duration, Instant, SystemTime};

/// Arguments of `rtc watch`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The scene file (its imports and assets are watched too).
    #[arg(value_name = "SCENE.rt")]
    pub path: PathBuf,
    /// Output folder of the kernel code and `manifest.json` (created if missing).
    #[arg(long, default_value = "out", value_name = "DIR")]
    pub out: PathBuf,
    /// Also render a preview to this `.png` or `.exr` after every good build (`--size`, `--spp`
    /// and `--adapter` apply to it).
    #[arg(short, long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Targets, comma-separated: wgsl, spirv, hlsl, msl, glsl (default: all).
    #[arg(long, value_delimiter = ',', value_parser = parse_target)]
    pub target: Vec<Target>,
    /// Scene, size, samples, GPU and asset folders.
    #[command(flatten)]
    pub render: RenderArgs,
    /// The execution model of the preview (and of the kernels written).
    #[command(flatten)]
    pub exec: crate::args::ExecArgs,
    /// A reload starts once no file event came for this long.
    #[arg(long, value_name = "MS", default_value_t = 15, value_parser = clap::value_parser!(u64).range(0..=60_000))]
    pub debounce_ms: u64,
    /// Stop after this many builds, counting the first (for tests and benchmarks).
    #[arg(long, value_name = "N", hide = true)]
    pub exit_after: Option<u32>,
}

/// The preview a session renders after each good build.
#[derive(Clone, Debug)]
pub struct Preview {
    /// Where to write it.
    pub path: PathBuf,
    /// Its format.
    pub format: Format,
    /// Size instead of the scene's.
    pub size: Option<[u32; 2]>,
    /// Samples per pixel instead of the scene's.
    pub samples: Option<u32>,
    /// The adapter to render on.
    pub adapter: AdapterChoice,
    /// Where else the scene's assets may come from (`--asset-root`).
    pub asset_roots: AssetRoots,
}

/// The GPU of the previews: made at the first preview, kept for the next ones (for the life of
/// the process, so the preview's renderer can borrow it across reloads).
enum GpuSlot {
    NotYet,
    Ready(&'static Gpu),
    /// It could not be had (the reason was printed once); previews are off.
    Failed,
}

/// How a reload ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Compiled and written (and the preview rendered, when asked for).
    Built,
    /// Only assets changed: the preview was rendered again.
    Rerendered,
    /// No watched file changed its content.
    Unchanged,
    /// A user error: printed; the previous outputs were kept.
    Failed,
}

/// What one reload did, for printing.
#[derive(Debug)]
pub struct Reload {
    /// The build's number (the first build is 1); unchanged reloads do not count.
    pub number: u32,
    /// How it ended.
    pub status: Status,
    /// The watched files whose content changed (or that appeared or went away).
    pub changed: Vec<PathBuf>,
    /// Files that joined and left the watched set.
    pub watch_added: Vec<PathBuf>,
    /// Files that left the watched set.
    pub watch_removed: Vec<PathBuf>,
    /// Every phase and its time in milliseconds, in order.
    pub phases: Vec<(String, f64)>,
    /// Rendered diagnostics and error lines (warnings too), ready to print on stderr.
    pub messages: String,
    /// Milliseconds from the edit to the written kernel code.
    pub edit_to_code_ms: Option<f64>,
    /// Milliseconds from the edit to the written preview.
    pub edit_to_preview_ms: Option<f64>,
    /// Modules parsed again and modules taken from the cache.
    pub parsed: (u32, u32),
    /// The preview's kernels: compiled or reused, and their cost.
    pub kernels: Vec<KernelReport>,
}

/// A watched scene: what the last build read and produced. Used by `rtc watch` and `rtc view`.
pub struct Session {
    roots: Vec<PathBuf>,
    scene: Option<String>,
    options: Options,
    cache: Arc<ModuleCache>,
    targets: Vec<Target>,
    /// Where the code goes; `None` writes no code (`rtc view`).
    out: Option<PathBuf>,
    preview: Option<Preview>,
    gpu: GpuSlot,
    color: bool,
    /// Every watched file as last read ([`Seen`]).
    hashes: BTreeMap<PathBuf, Seen>,
    /// The watched files that are sources (the rest are assets).
    sources: BTreeSet<PathBuf>,
    /// The last good compile.
    last: Option<CompiledScene>,
    /// Whether the last build failed.
    failing: bool,
    builds: u32,
    /// The execution model asked for (`--exec`); `None` leaves it to the scene's `exec` setting.
    exec: Option<ExecModel>,
    /// The model of a scene left at `EXEC_AUTO` (`KernelOptions::auto`): the wavefront model for
    /// `rtc watch`, where an edit to a material recompiles only the shade stage.
    auto: ExecModel,
    /// The preview's renderer, kept across reloads: a reload replaces its kernels and keeps every
    /// asset, object-level BVH and buffer that did not change.
    renderer: Option<Renderer<'static>>,
}

impl Session {
    /// A session for `path`; nothing is compiled before the first [`Session::reload`].
    pub fn new(
        path: &Path,
        scene: Option<String>,
        options: &Options,
        targets: Vec<Target>,
        out: Option<PathBuf>,
        preview: Option<Preview>,
        color: bool,
    ) -> Session {
        let cache = Arc::new(ModuleCache::new());
        let mut options = options.clone();
        options.cache = Some(Arc::clone(&cache));
        Session {
            roots: vec![path.to_path_buf()],
            scene,
            options,
            cache,
            targets,
            out,
            preview,
            gpu: GpuSlot::NotYet,
            color,
            hashes: BTreeMap::new(),
            sources: BTreeSet::new(),
            last: None,
            failing: false,
            builds: 0,
            exec: None,
            auto: ExecModel::Wavefront,
            renderer: None,
        }
    }

    /// The session with the execution model `exec` (`--exec`) instead of the scene's setting.
    pub fn with_exec(mut self, exec: Option<ExecModel>) -> Session {
        self.exec = exec;
        self
    }

    /// The session running a scene left at `EXEC_AUTO` with `auto` (the wavefront model unless
    /// set: `rtc view` sets the megakernel, whose every frame is faster).
    pub fn with_auto(mut self, auto: ExecModel) -> Session {
        self.auto = auto;
        self
    }

    /// The files to watch (canonical paths).
    pub fn watched(&self) -> impl Iterator<Item = &PathBuf> {
        self.hashes.keys()
    }

    /// The last good compile.
    pub fn last(&self) -> Option<&CompiledScene> {
        self.last.as_ref()
    }

    /// The last good compile, to change before rendering it (`rtc view` moves its camera).
    pub fn last_mut(&mut self) -> Option<&mut CompiledScene> {
        self.last.as_mut()
    }

    /// Whether an event for `path` may need a reload: a watched file, or a new `.rt` file while the
    /// build is failing (perhaps the import it lacked).
    pub fn is_relevant(&self, path: &Path) -> bool {
        let canon = canonical(path);
        self.hashes.contains_key(&canon)
            || (self.failing && path.extension().is_some_and(|e| e == "rt"))
    }

    /// What changed in the folders `new_dirs` while they were not yet watched: their watched files
    /// whose content differs from what the last build read, and, while the build fails, `.rt` files
    /// there written since `build_started` (perhaps the import it lacked). `rtc watch` registers a
    /// folder only after a build named a file in it, so a write in between sends no event; the
    /// caller reloads with these paths when there are any.
    pub fn missed(&self, new_dirs: &[PathBuf], build_started: SystemTime) -> Vec<PathBuf> {
        if new_dirs.is_empty() {
            return Vec::new();
        }
        let in_new = |p: &Path| p.parent().is_some_and(|d| new_dirs.iter().any(|n| n == d));
        let mut missed: Vec<PathBuf> = self
            .hashes
            .iter()
            .filter(|(p, old)| in_new(p) && Seen::of(p, Some(old)).hash != old.hash)
            .map(|(p, _)| p.clone())
            .collect();
        if self.failing {
            // File times lag the clock by up to a tick: look a little before the build began.
            let since = build_started
                .checked_sub(Duration::from_secs(1))
                .unwrap_or(build_started);
            for dir in new_dirs {
                let Ok(entries) = std::fs::read_dir(dir) else {
                    continue;
                };
                for entry in entries.flatten() {
                    let path = canonical(&entry.path());
                    let written = entry.metadata().and_then(|m| m.modified());
                    if path.extension().is_some_and(|e| e == "rt")
                        && written.is_ok_and(|t| t >= since)
                        && !self.hashes.contains_key(&path)
                        && !missed.contains(&path)
                    {
                        missed.push(path);
                    }
                }
            }
        }
        missed
    }

    /// Builds again if anything changed. `trigger` is the paths the events named (empty for the
    /// first build, which always runs).
    pub fn reload(&mut self, trigger: &[PathBuf]) -> Reload {
        let start = Instant::now();
        let first = self.builds == 0;
        let mut changed = Vec::new();
        let mut touched = Vec::new();
        for (path, old) in &self.hashes {
            let now = Seen::of(path, Some(old));
            if now.hash != old.hash {
                changed.push(path.clone());
            } else if now != *old {
                touched.push((path.clone(), now));
            }
        }
        // Same content under a new stamp: remember the stamp, so the file is not read again.
        self.hashes.extend(touched);
        if self.failing {
            for p in trigger {
                let canon = canonical(p);
                if !self.hashes.contains_key(&canon)
                    && p.extension().is_some_and(|e| e == "rt")
                    && !changed.contains(&canon)
                {
                    changed.push(canon);
                }
            }
        }
        let mut reload = Reload {
            number: self.builds,
            status: Status::Unchanged,
            changed,
            watch_added: Vec::new(),
            watch_removed: Vec::new(),
            phases: vec![("hash watched files".to_owned(), ms_since(start))],
            messages: String::new(),
            edit_to_code_ms: None,
            edit_to_preview_ms: None,
            parsed: (0, 0),
            kernels: Vec::new(),
        };
        if !first && reload.changed.is_empty() {
            return reload;
        }
        self.builds += 1;
        reload.number = self.builds;
        let edit_time = reload
            .changed
            .iter()
            .filter_map(|p| std::fs::metadata(p).and_then(|m| m.modified()).ok())
            .max();

        let assets_only = !first
            && self.last.is_some()
            && !self.failing
            && reload.changed.iter().all(|p| !self.sources.contains(p));
        if assets_only {
            for p in &reload.changed {
                self.hashes.insert(p.clone(), Seen::of(p, None));
            }
            reload.status = Status::Rerendered;
        } else if !self.compile_and_emit(&mut reload, edit_time) {
            self.failing = true;
            reload.status = Status::Failed;
            return reload;
        } else {
            reload.status = Status::Built;
        }
        self.failing = false;
        if self.preview.is_some() && !self.render_preview(&mut reload) {
            reload.status = Status::Failed;
            return reload;
        }
        reload.edit_to_preview_ms = self.preview.as_ref().and(edit_time).map(since_edit);
        reload
    }

    /// Phases 3 and 4. Returns whether the build succeeded.
    fn compile_and_emit(&mut self, reload: &mut Reload, edit_time: Option<SystemTime>) -> bool {
        let t = Instant::now();
        let compiled = compile_scene_with(
            &self.roots,
            self.scene.as_deref(),
            &self.options,
            &LinkOptions {
                asset_roots: self
                    .preview
                    .as_ref()
                    .map(|p| p.asset_roots.clone())
                    .unwrap_or_default(),
                ..LinkOptions::default()
            },
            // The preview's time after an edit is the compile: the shade stage does not take on a
            // traversal of the shadow rays it could leave to the shadow stage.
            &KernelOptions {
                exec: self.exec,
                auto: self.auto,
                shadow_rays: ShadowRays::AutoFastCompile,
                ..KernelOptions::default()
            },
        );
        let stats = self.cache.take_stats();
        reload.parsed = (stats.misses, stats.hits);
        let compiled = match compiled {
            Ok(c) => c,
            Err(failure) => {
                reload
                    .phases
                    .push(("compile (failed)".to_owned(), ms_since(t)));
                // Watch what was read too, so that fixing any of it reloads. A failed build stops
                // early (before the kernel is checked): the set only grows until the next good one.
                let (mut sources, _) = source_files(&failure.checked.sources);
                sources.extend(self.sources.iter().cloned());
                self.update_watched(reload, sources, None);
                reload.messages =
                    render_diagnostics(&failure.checked.sources, &failure.diagnostics, self.color);
                if !diag::has_errors(&failure.diagnostics) {
                    reload.messages.push_str(&format!(
                        "{}: the scene could not be compiled\n",
                        term::paint("error", 31, self.color)
                    ));
                }
                return false;
            }
        };
        reload.phases.extend(
            compiled
                .timings
                .iter()
                .map(|(name, ms)| ((*name).to_owned(), *ms)),
        );
        if !compiled.checked.diagnostics.is_empty() {
            reload.messages = render_diagnostics(
                &compiled.checked.sources,
                &compiled.checked.diagnostics,
                self.color,
            );
        }
        if let Some(out) = &self.out {
            let t = Instant::now();
            if let Err(e) = save_registry(&compiled) {
                reload.messages.push_str(&format!(
                    "{}: cannot save the program registry: {e}\n",
                    term::paint("warning", 33, self.color)
                ));
            }
            let written = std::fs::create_dir_all(out)
                .map_err(|e| OutputError::Write(format!("cannot create `{}`: {e}", out.display())))
                .and_then(|()| write_outputs(&compiled, &self.targets, out));
            reload
                .phases
                .push((format!("write {} targets", self.targets.len()), ms_since(t)));
            if let Err(e) = written {
                let text = match e {
                    OutputError::Backend(e @ rtc_compiler::back::BackendError::TooLarge { .. }) => {
                        e.to_string()
                    }
                    OutputError::Backend(e) => {
                        format!("internal compiler error: {e} (a bug in rtc; please report it)")
                    }
                    OutputError::Write(e) => e,
                };
                reload.messages.push_str(&format!(
                    "{}: {text}\n",
                    term::paint("error", 31, self.color)
                ));
                return false;
            }
            reload.edit_to_code_ms = edit_time.map(since_edit);
        }
        let (sources, assets) = match compiled.checked.program.as_ref() {
            Some(p) => {
                // A glTF `model` file decides what the kernel links (the link step reads it), so
                // an edit to it compiles again, like an edit to a source.
                let desc = &p.scenes[compiled.scene];
                let mut sources = source_files(&compiled.checked.sources).0;
                sources.extend(desc.models.iter().map(|m| canonical(&m.path)));
                (sources, Some(asset_paths(desc)))
            }
            None => (BTreeSet::new(), None),
        };
        self.update_watched(reload, sources, assets);
        self.last = Some(compiled);
        true
    }

    /// Replaces the watched set: `sources` as read now, `assets` (or the previous assets when
    /// `None`); records the files that joined and left.
    fn update_watched(
        &mut self,
        reload: &mut Reload,
        sources: BTreeSet<PathBuf>,
        assets: Option<BTreeSet<PathBuf>>,
    ) {
        let assets: BTreeSet<PathBuf> = match assets {
            Some(a) => a,
            None => self
                .hashes
                .keys()
                .filter(|p| !self.sources.contains(*p))
                .cloned()
                .collect(),
        };
        let mut hashes = BTreeMap::new();
        for p in sources.iter().chain(&assets) {
            hashes.insert(p.clone(), Seen::of(p, self.hashes.get(p)));
        }
        // The root is always watched, even when it could not be read.
        for r in &self.roots {
            let canon = canonical(r);
            let h = Seen::of(&canon, self.hashes.get(&canon));
            hashes.entry(canon).or_insert(h);
        }
        if self.builds > 1 {
            reload.watch_added = hashes
                .keys()
                .filter(|p| !self.hashes.contains_key(*p))
                .cloned()
                .collect();
            reload.watch_removed = self
                .hashes
                .keys()
                .filter(|p| !hashes.contains_key(*p))
                .cloned()
                .collect();
        }
        self.hashes = hashes;
        self.sources = sources;
    }

    /// Phase 5. Returns whether the preview was written (or is off because no GPU could be had).
    fn render_preview(&mut self, reload: &mut Reload) -> bool {
        let (Some(preview), Some(compiled)) = (&self.preview, &self.last) else {
            return true;
        };
        let t = Instant::now();
        if let GpuSlot::NotYet = self.gpu {
            self.gpu = match Gpu::new(&preview.adapter) {
                Ok(gpu) => {
                    reload
                        .messages
                        .push_str(&format!("preview adapter: {}\n", gpu.description()));
                    reload
                        .messages
                        .push_str(&format!("host: {}\n", rtc_runtime::gpu::HostCpu::detect()));
                    GpuSlot::Ready(Box::leak(Box::new(gpu)))
                }
                Err(e) => {
                    reload.messages.push_str(&format!(
                        "{}: no preview: {e}\n",
                        term::paint("error", 31, self.color)
                    ));
                    GpuSlot::Failed
                }
            };
            reload.phases.push(("open the GPU".to_owned(), ms_since(t)));
        }
        let GpuSlot::Ready(gpu) = self.gpu else {
            return true;
        };
        let t = Instant::now();
        let options = RenderOptions {
            size: preview.size,
            samples: preview.samples,
            asset_roots: preview.asset_roots.clone(),
            ..RenderOptions::default()
        };
        // The first preview builds the renderer; later ones replace its kernels, which keeps
        // assets, BLASes and unchanged buffers (the scene's size or samples may have changed:
        // then it is built afresh).
        let reusable = self.renderer.as_ref().is_some_and(|r| {
            let settings = compiled
                .checked
                .program
                .as_ref()
                .map(|p| p.scenes[compiled.scene].settings);
            let size = preview
                .size
                .or(settings.map(|s| [s.width, s.height]))
                .unwrap_or_default();
            size == r.size()
                && preview.samples.or(settings.map(|s| s.samples)) == Some(r.total_samples())
        });
        let prepared = match (&mut self.renderer, reusable) {
            (Some(r), true) => r.replace_kernel(compiled),
            _ => Renderer::new(gpu, compiled, options).map(|r| {
                self.renderer = Some(r);
            }),
        };
        let prepare_ms = ms_since(t);
        let result = prepared.and_then(|()| match &mut self.renderer {
            Some(r) => r.render(&mut |_, _| {}),
            None => Err(rtc_runtime::render::RenderError::KernelSet),
        });
        let result = match result {
            Ok(r) => r,
            Err(e) => {
                let diagnostic = match &e {
                    rtc_runtime::render::RenderError::Scene(s) => s.to_diagnostic(),
                    _ => None,
                };
                match diagnostic {
                    Some(d) => reload.messages.push_str(&render_diagnostics(
                        &compiled.checked.sources,
                        std::slice::from_ref(&d),
                        self.color,
                    )),
                    None => reload.messages.push_str(&format!(
                        "{}: preview: {e}\n",
                        term::paint("error", 31, self.color)
                    )),
                }
                self.failing = true;
                return false;
            }
        };
        reload
            .phases
            .push(("prepare preview (scene, pipelines)".to_owned(), prepare_ms));
        reload.kernels = result.stats.kernels.clone();
        for w in gpu.take_warnings().iter().chain(&result.stats.warnings) {
            reload.messages.push_str(&format!(
                "{}: {w}\n",
                term::paint("warning", 33, self.color)
            ));
        }
        reload.phases.push((
            format!(
                "render preview {}x{} at {} spp",
                result.stats.width, result.stats.height, result.stats.samples
            ),
            ms_since(t) - prepare_ms,
        ));
        let t = Instant::now();
        if let Err(e) = write_image(&preview.path, preview.format, &result.image) {
            reload
                .messages
                .push_str(&format!("{}: {e}\n", term::paint("error", 31, self.color)));
            return false;
        }
        reload
            .phases
            .push(("write preview".to_owned(), ms_since(t)));
        true
    }
}

/// The canonical form of a path when it exists, else the path made absolute.
fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| {
        std::env::current_dir()
            .map(|d| d.join(path))
            .unwrap_or_else(|_| path.to_path_buf())
    })
}

/// What a watched file was when last read: its length and modification time, when it was read,
/// and its content hash (`None`: it could not be read). A reload reads again only the files whose
/// length or time changed, so an edit to a scene is not slowed down by hashing its large assets
/// (a 14.5 MB PNG took 135 ms an edit); a file whose time was less than [`SETTLE`] before it was
/// read is read again whatever its stamp, since a second write in the same tick of the file
/// system's clock would leave the stamp as it was (git's "racily clean" rule).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Seen {
    stamp: Option<(u64, SystemTime)>,
    read_at: SystemTime,
    hash: Option<u64>,
}

/// How long before it was read a file must have been written for its stamp to be trusted.
const SETTLE: Duration = Duration::from_secs(2);

impl Seen {
    /// `path` now: `known` when the file's stamp is the one `known` was read with and that read
    /// was settled, else the file read and hashed again.
    fn of(path: &Path, known: Option<&Seen>) -> Seen {
        let stamp = std::fs::metadata(path)
            .ok()
            .and_then(|m| Some((m.len(), m.modified().ok()?)));
        if let Some(known) = known {
            let settled = known
                .stamp
                .is_some_and(|(_, written)| written + SETTLE <= known.read_at);
            if settled && stamp == known.stamp {
                return *known;
            }
        }
        Seen {
            stamp,
            read_at: SystemTime::now(),
            hash: hash_file(path),
        }
    }
}

/// The content hash of a file; `None` when it cannot be read.
fn hash_file(path: &Path) -> Option<u64> {
    let bytes = std::fs::read(path).ok()?;
    Some(match std::str::from_utf8(&bytes) {
        Ok(text) => content_hash(text),
        Err(_) => content_hash(&String::from_utf8_lossy(&bytes)) ^ bytes.len() as u64,
    })
}

fn ms_since(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// Milliseconds from `edit` to now (0 when the clock says the edit is in the future).
fn since_edit(edit: SystemTime) -> f64 {
    SystemTime::now()
        .duration_since(edit)
        .map(|d| d.as_secs_f64() * 1e3)
        .unwrap_or(0.0)
}

/// The files on disk a compile read (canonical paths), and the generated ones it did not.
fn source_files(sources: &SourceMap) -> (BTreeSet<PathBuf>, usize) {
    let mut out = BTreeSet::new();
    let mut generated = 0;
    for (_, f) in sources.files() {
        match &f.path {
            Some(p) if p.is_file() => {
                out.insert(canonical(p));
            }
            _ => generated += 1,
        }
    }
    (out, generated)
}

/// Every file a scene loads at render time: meshes, images and glTF models (canonical paths).
pub fn asset_paths(desc: &SceneDesc) -> BTreeSet<PathBuf> {
    desc.asset_files().iter().map(|p| canonical(p)).collect()
}

/// Diagnostics as rustc-style text, with the summary line.
fn render_diagnostics(sources: &SourceMap, diags: &[Diagnostic], color: bool) -> String {
    let mut text = diag::render_human(sources, diags, color);
    let count = |s: Severity| diags.iter().filter(|d| d.severity == s).count();
    if let Some(line) = report::summary(
        "compile",
        count(Severity::Error),
        count(Severity::Warning),
        color,
    ) {
        text.push_str(&line);
    }
    text
}

/// A path for printing: relative to the working folder when inside it.
fn show(path: &Path) -> String {
    let cwd = std::env::current_dir()
        .ok()
        .and_then(|d| d.canonicalize().ok());
    match cwd.as_deref().and_then(|d| path.strip_prefix(d).ok()) {
        Some(rel) => rel.display().to_string(),
        None => path.display().to_string(),
    }
}

fn list(paths: &[PathBuf]) -> String {
    paths.iter().map(|p| show(p)).collect::<Vec<_>>().join(", ")
}

/// The report of one reload: what changed, each phase's time, the outcome.
pub fn describe(r: &Reload, color: bool) -> String {
    let mut out = String::new();
    let tag = format!("[watch] #{}", r.number);
    if r.number == 1 {
        out.push_str(&format!("{tag} first build\n"));
    } else {
        out.push_str(&format!("{tag} changed: {}\n", list(&r.changed)));
    }
    if !r.watch_added.is_empty() {
        out.push_str(&format!("{tag} now watching: {}\n", list(&r.watch_added)));
    }
    if !r.watch_removed.is_empty() {
        out.push_str(&format!(
            "{tag} no longer watching: {}\n",
            list(&r.watch_removed)
        ));
    }
    if r.parsed != (0, 0) {
        out.push_str(&format!(
            "  parse: {} module(s) parsed, {} from the cache\n",
            r.parsed.0, r.parsed.1
        ));
    }
    for (name, ms) in &r.phases {
        out.push_str(&format!("  {name:<32} {ms:>9.2} ms\n"));
    }
    if !r.kernels.is_empty() {
        let compiled = r
            .kernels
            .iter()
            .filter(|k| k.origin == KernelOrigin::Compiled)
            .count();
        out.push_str(&format!(
            "  kernels: {compiled} compiled, {} reused\n",
            r.kernels.len() - compiled
        ));
        out.push_str(&super::render::kernel_lines(&r.kernels, "    "));
    }
    match r.status {
        Status::Built | Status::Rerendered => {
            let what = match (r.status, r.edit_to_preview_ms.is_some()) {
                (Status::Built, _) => "ok",
                (_, true) => {
                    "ok (only assets changed: the code stays, the preview was rendered again)"
                }
                (_, false) => "ok (only assets changed: the code stays)",
            };
            out.push_str(&format!("{tag} {what}"));
            let mut figures = Vec::new();
            if let Some(ms) = r.edit_to_code_ms {
                figures.push(format!("edit to code {ms:.1} ms"));
            }
            if let Some(ms) = r.edit_to_preview_ms {
                figures.push(format!("edit to preview {ms:.1} ms"));
            }
            if !figures.is_empty() && r.number > 1 {
                out.push_str(&format!(" ({})", figures.join(", ")));
            }
            out.push('\n');
        }
        Status::Failed if r.edit_to_code_ms.is_some() => out.push_str(&format!(
            "{tag} {}: the code was written, the preview failed and the last one was kept; \
             waiting for the next change\n",
            term::paint("failed", 31, color)
        )),
        Status::Failed => out.push_str(&format!(
            "{tag} {}: kept the last good outputs; waiting for the next change\n",
            term::paint("failed", 31, color)
        )),
        Status::Unchanged => {}
    }
    out
}

/// What the watcher thread and the Ctrl-C handler send to the main loop.
enum Msg {
    Paths(Vec<PathBuf>),
    WatchError(String),
    Stop,
}

/// Runs `rtc watch`.
pub fn run(args: &Args, ctx: &Context) -> Exit {
    let asset_roots = match args.render.assets.roots() {
        Ok(r) => r,
        Err(e) => return report::usage_error(&e, ctx.color),
    };
    let preview = match &args.output {
        None => None,
        Some(path) => {
            let format = match crate::args::image_output(path, "the preview") {
                Ok(f) => f,
                Err(e) => return report::usage_error(&e, ctx.color),
            };
            let adapter = match args.render.adapter.choice() {
                Ok(c) => c,
                Err(e) => return report::usage_error(&e, ctx.color),
            };
            Some(Preview {
                path: path.clone(),
                format,
                size: args.render.scene.image_size(),
                samples: args.render.spp.samples,
                adapter,
                asset_roots,
            })
        }
    };
    if !args.path.is_file() {
        return report::usage_error(
            &format!("cannot read `{}`: no such file", args.path.display()),
            ctx.color,
        );
    }
    let targets = if args.target.is_empty() {
        Target::ALL.to_vec()
    } else {
        args.target.clone()
    };
    let mut session = Session::new(
        &args.path,
        args.render.scene.name.clone(),
        &ctx.options,
        targets,
        Some(args.out.clone()),
        preview,
        ctx.color,
    )
    .with_exec(args.exec.model());

    let (tx, rx) = mpsc::channel::<Msg>();
    let stop = tx.clone();
    if let Err(e) = ctrlc::set_handler(move || {
        let _ = stop.send(Msg::Stop);
    }) {
        report::usage_error(&format!("cannot catch Ctrl-C: {e}"), ctx.color);
        return Exit::Failure;
    }
    let events = tx.clone();
    let watcher = notify::recommended_watcher(move |res: notify::Result<notify::Event>| {
        let msg = match res {
            Ok(event) if matches!(event.kind, notify::EventKind::Access(_)) => return,
            Ok(event) => Msg::Paths(event.paths),
            Err(e) => Msg::WatchError(e.to_string()),
        };
        let _ = events.send(msg);
    });
    let mut watcher = match watcher {
        Ok(w) => w,
        Err(e) => {
            term::eprint(&format!(
                "{}: cannot watch files: {e}\n",
                term::paint("error", 31, ctx.color)
            ));
            return Exit::Failure;
        }
    };
    let mut dirs: BTreeSet<PathBuf> = BTreeSet::new();
    let debounce = Duration::from_millis(args.debounce_ms);

    let mut pending: Vec<PathBuf> = Vec::new();
    loop {
        let started = SystemTime::now();
        let reload = session.reload(&pending);
        pending.clear();
        term::eprint(&reload.messages);
        if reload.status != Status::Unchanged {
            term::print(&describe(&reload, ctx.color));
        }
        let added = update_dirs(&mut watcher, &mut dirs, &session, ctx);
        if args.exit_after.is_some_and(|n| reload.number >= n) {
            break;
        }
        if reload.number == 1 {
            term::print(&format!(
                "[watch] watching {} files in {} folders; Ctrl-C to stop\n",
                session.watched().count(),
                dirs.len()
            ));
        }
        // What changed in a new folder before it was watched sent no event: build it now.
        pending = session.missed(&added, started);
        if !pending.is_empty() {
            continue;
        }
        // Wait for a relevant event, then for quiet.
        match next_batch(&rx, &session, debounce, ctx) {
            Some(paths) => pending = paths,
            None => break,
        }
    }
    term::print("[watch] stopped\n");
    Exit::Success
}

/// Blocks until a relevant file event came and then `debounce` passed without one; returns the
/// paths named. `None`: stop (Ctrl-C, or the watcher went away).
fn next_batch(
    rx: &mpsc::Receiver<Msg>,
    session: &Session,
    debounce: Duration,
    ctx: &Context,
) -> Option<Vec<PathBuf>> {
    let mut paths: Vec<PathBuf> = Vec::new();
    loop {
        let msg = if paths.is_empty() {
            rx.recv().ok()?
        } else {
            match rx.recv_timeout(debounce) {
                Ok(m) => m,
                Err(mpsc::RecvTimeoutError::Timeout) => return Some(paths),
                Err(mpsc::RecvTimeoutError::Disconnected) => return None,
            }
        };
        match msg {
            Msg::Stop => return None,
            Msg::WatchError(e) => term::eprint(&format!(
                "{}: file watcher: {e}\n",
                term::paint("warning", 33, ctx.color)
            )),
            Msg::Paths(ps) => {
                for p in ps {
                    if session.is_relevant(&p) && !paths.contains(&p) {
                        paths.push(p);
                    }
                }
            }
        }
    }
}

/// Watches the folders of the session's files (and no others). Returns the folders it began to
/// watch: a file in one of them written while the build ran sent no event ([`Session::missed`]).
pub fn update_dirs(
    watcher: &mut notify::RecommendedWatcher,
    dirs: &mut BTreeSet<PathBuf>,
    session: &Session,
    ctx: &Context,
) -> Vec<PathBuf> {
    use notify::Watcher;
    let want: BTreeSet<PathBuf> = session
        .watched()
        .filter_map(|p| p.parent().map(Path::to_path_buf))
        .filter(|d| d.is_dir())
        .collect();
    for gone in dirs.difference(&want) {
        let _ = watcher.unwatch(gone);
    }
    let mut added = Vec::new();
    for new in want.difference(dirs) {
        match watcher.watch(new, notify::RecursiveMode::NonRecursive) {
            Ok(()) => added.push(new.clone()),
            Err(e) => term::eprint(&format!(
                "{}: cannot watch `{}`: {e}\n",
                term::paint("warning", 33, ctx.color),
                new.display()
            )),
        }
    }
    *dirs = want;
    added
}

#[cfg(test)]
mod tests;
