//! Kernel assembly: from a checked program with the framework kernel and a link plan to the scene's
//! specialised `naga::Module`s.
//!
//! The phases of a whole compile, in order, are [`crate::pipeline::compile`]; this module provides
//! the kernel's parts of it: the generated modules `rtc:abi` and `rtc:config` ([`generated`]), the
//! lowering of one kernel entry point with its intrinsics, dispatchers and loaders ([`lower_kernel`]),
//! the scene's registry file, and the result, [`CompiledScene`], which is what `rtc compile` writes
//! out and what the runtime runs. [`compile_scene`] is the pipeline without targets.

pub mod dispatch;
mod entry;
pub mod generated;
pub mod intrinsics;
pub mod manifest;
pub mod wavefront;
pub mod weight;

use crate::abi::BindingDesc;
use crate::diag::Diagnostic;
use crate::driver::{Checked, Options};
use crate::link::{LinkOptions, Linked};
use crate::lower::LowerError;
use crate::sema::hir::{Program, SceneId};
use intrinsics::KernelHooks;
use std::path::PathBuf;

/// A compiled scene: the checked program, the link plan and the kernel modules.
#[derive(Debug)]
pub struct CompiledScene {
    /// The checked program (with the framework kernel), its sources and warnings.
    pub checked: Checked,
    /// The scene that was compiled.
    pub scene: SceneId,
    /// The link plan.
    pub linked: Linked,
    /// The render kernel: entry point [`RENDER_ENTRY`].
    pub render: naga::Module,
    /// The bounds kernel (entry point [`BOUNDS_ENTRY`]), when the scene has custom geometry.
    pub bounds: Option<naga::Module>,
    /// The bindings the render kernel declares, in binding order.
    pub bindings: Vec<&'static BindingDesc>,
    /// Samples per pixel one pass of the render kernel takes (the camera program's `samples`).
    pub samples_per_pass: u32,
    /// The wavefront model's stage kernels ([`wavefront::STAGES`], in that order), when the
    /// options asked for them ([`KernelOptions::exec`]).
    pub stages: Option<Vec<StageKernel>>,
    /// Words of one path slot of the wavefront model (`PATH_WORDS`).
    pub path_words: u32,
    /// The execution model the scene runs with ([`ExecModel::resolve`], then
    /// [`KernelOptions::wavefront_min_weight`]).
    pub exec: ExecModel,
    /// The render kernel's size with every call inlined ([`weight::inlined_weight`]).
    pub render_weight: u64,
    /// How long each phase of the compile took, in milliseconds, in order.
    pub timings: Vec<(&'static str, f64)>,
}

impl CompiledScene {
    /// Whether its wavefront stage kernels include the shadow stage (the shade stage replays its
    /// shadow rays, [`lower_shade_stage`]); false without stage kernels.
    pub fn has_shadow_stage(&self) -> bool {
        self.stages
            .iter()
            .flatten()
            .any(|s| s.stage == wavefront::Stage::Shadow)
    }

    /// Whether its shade stage adds the samples of a tile the host listed to `accum` itself
    /// (`wf_sample_accumulate`; then no finish stage runs after such a round); false without stage
    /// kernels.
    pub fn shade_accumulates(&self) -> bool {
        self.stages.iter().flatten().any(|s| {
            s.stage == wavefront::Stage::Shade && s.bindings.iter().any(|b| b.name == "accum")
        })
    }

    /// Whether its shade stage replays its shadow rays around its own traversal
    /// (`wavefront::SHADE_REPLAY_ROOT`, [`ShadowRays::Replay`]); false without stage kernels.
    pub fn replays_in_shade_stage(&self) -> bool {
        self.stages
            .iter()
            .flatten()
            .filter(|s| s.stage == wavefront::Stage::Shade)
            .any(|s| {
                s.module
                    .functions
                    .iter()
                    .any(|(_, f)| f.name.as_deref() == Some(wavefront::SHADE_REPLAY_ROOT))
            })
    }
}

/// One stage kernel of the wavefront model.
#[derive(Debug)]
pub struct StageKernel {
    /// Which stage.
    pub stage: wavefront::Stage,
    /// The module (entry point [`wavefront::Stage::entry`]).
    pub module: naga::Module,
    /// The bindings it declares, in binding order.
    pub bindings: Vec<&'static BindingDesc>,
}

/// How a scene's samples are executed on the device.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ExecModel {
    /// One kernel traces each pixel's samples to completion (`render`).
    #[default]
    Megakernel,
    /// Stage kernels run in rounds over a tile, through path state in `paths`
    /// ([`wavefront`]).
    Wavefront,
}

impl ExecModel {
    /// The model a scene runs with: `choice` (the command line's `--exec`) if given, else the
    /// scene's `exec` setting (`EXEC_MEGAKERNEL` 1, `EXEC_WAVEFRONT` 2), else, for `EXEC_AUTO`,
    /// `auto` (`KernelOptions::auto`: the megakernel, except under `rtc watch`). ARCHITECTURE.md,
    /// "Decisions", has the figures that decided it.
    pub fn resolve(choice: Option<ExecModel>, setting: u32, auto: ExecModel) -> ExecModel {
        match (choice, setting) {
            (Some(m), _) => m,
            (None, 1) => ExecModel::Megakernel,
            (None, 2) => ExecModel::Wavefront,
            (None, _) => auto,
        }
    }

    /// Its name on the command line and in scene settings.
    pub fn name(self) -> &'static str {
        match self {
            ExecModel::Megakernel => "megakernel",
            ExecModel::Wavefront => "wavefront",
        }
    }
}

/// The render kernel's entry point.
pub const RENDER_ENTRY: &str = "render";
/// The bounds kernel's entry point.
pub const BOUNDS_ENTRY: &str = "bounds";
/// Workgroup size of the render kernel (pixels in x and y).
pub const RENDER_WORKGROUP: [u32; 2] = [8, 8];
/// Workgroup size of the bounds kernel (objects).
pub const BOUNDS_WORKGROUP: u32 = 64;

/// What a debug kernel writes to the accumulation buffer instead of radiance. A debug kernel
/// traces one camera ray per pixel (the pass's first sample; no shading, no secondary or shadow
/// rays) and adds one `vec4f` per pixel to `accum` (a zeroed buffer after one pass holds exactly
/// that value). Normal kernels (`None`) contain none of this code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DebugMode {
    /// `x` = BVH nodes visited (scene level and object level: one per node the traversal loop
    /// enters, the root included, not counting a scene root the ray misses), `y` = primitives
    /// tested (triangles and `@intersection` calls), `z` = `t` of the closest accepted hit or -1,
    /// `w` = the hit object's index in the scene (`Hit.instance`) or -1.
    Counts,
    /// `xyz` = the camera ray's origin (world space), `w` = its `tmin`.
    RayOrigin,
    /// `xyz` = the camera ray's direction as the camera program returned it (not renormalised),
    /// `w` = its `tmax` (`+inf` when unbounded).
    RayDirection,
}

/// Options of the kernel itself (beyond the link plan).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct KernelOptions {
    /// Build a debug kernel that writes [`DebugMode`] values instead of radiance.
    pub debug: Option<DebugMode>,
    /// The execution model, overriding the scene's `exec` setting (`None`: the setting's, see
    /// [`ExecModel::resolve`]). The wavefront model's stage kernels are built
    /// ([`CompiledScene::stages`]) when the model resolved is the wavefront.
    pub exec: Option<ExecModel>,
    /// What the scene setting `EXEC_AUTO` means for this compile: the megakernel (the default:
    /// faster frames) or, for `rtc watch`, the wavefront model (a material edit recompiles one
    /// stage kernel).
    pub auto: ExecModel,
    /// With `auto` the wavefront model: the smallest render kernel, in [`weight::inlined_weight`],
    /// for which `EXEC_AUTO` means the wavefront model in a scene of small, built-in geometry
    /// ([`small_built_in_geometry`]). Such a scene with a lighter kernel keeps the megakernel,
    /// which then compiles faster than the stage kernels on a driver that gets uniform tables
    /// (`rtc render` sets it for a small render there; docs/bench/compile.md, "Which model
    /// compiles faster, with uniform tables (2026-12-04)"). 0: no bound.
    pub wavefront_min_weight: u64,
    /// Where the wavefront model traces the shadow rays of a shading step.
    pub shadow_rays: ShadowRays,
    /// The image size of the render the kernels are for, when the caller sets one (`rtc render
    /// --size`); else the scene's own ([`ShadowRays::Auto`] weighs the render's samples).
    pub render_size: Option<[u32; 2]>,
    /// The samples per pixel of that render, when the caller sets them (`--spp`); else the
    /// scene's own.
    pub render_spp: Option<u32>,
}

/// Where the wavefront model traces the shadow rays (`shadow(…)` calls) of a shading step
/// ([`lower_shade_stage`]; `kernel::wavefront` explains the three ways).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ShadowRays {
    /// [`ShadowRays::AutoFastFrames`] for a render of more than
    /// [`wavefront::FAST_COMPILE_MAX_SAMPLES`] samples ([`KernelOptions::render_size`] and
    /// [`KernelOptions::render_spp`], else the scene's own), else
    /// [`ShadowRays::AutoFastCompile`].
    #[default]
    Auto,
    /// In the shade stage where they are made ([`ShadowRays::Shade`]) when it then holds at most
    /// [`wavefront::MAX_SHADE_TRAVERSALS_FAST_FRAMES`] copies of the traversal, else replayed
    /// there ([`ShadowRays::Replay`]): the fastest frames.
    AutoFastFrames,
    /// In the shade stage where they are made when it then holds at most
    /// [`wavefront::MAX_SHADE_TRAVERSALS`] copies of the traversal, else in the shadow stage
    /// ([`ShadowRays::Stage`]): the fastest compile (each further copy makes the shade stage's
    /// driver compile longer, more than the shadow stage's own compile; docs/bench/lavapipe.md,
    /// "Shadow rays replayed in the shade stage (2026-12-06)").
    AutoFastCompile,
    /// In the shade stage, where they are made (the scene has no shadow stage).
    Shade,
    /// In the shade stage, which records them, traces them at its one traversal, and commits the
    /// step when they are all unoccluded or runs it again with their answers (the scene has no
    /// shadow stage).
    Replay,
    /// In the shadow stage: the shade stage records them and replays the step in its next dispatch.
    Stage,
}

impl ShadowRays {
    /// [`ShadowRays::Auto`] for a render of `samples` samples: [`ShadowRays::AutoFastFrames`]
    /// beyond [`wavefront::FAST_COMPILE_MAX_SAMPLES`], else [`ShadowRays::AutoFastCompile`]; any
    /// other choice as it is.
    pub fn for_samples(self, samples: u64) -> ShadowRays {
        match self {
            ShadowRays::Auto if samples > wavefront::FAST_COMPILE_MAX_SAMPLES => {
                ShadowRays::AutoFastFrames
            }
            ShadowRays::Auto => ShadowRays::AutoFastCompile,
            placement => placement,
        }
    }
}

/// The most triangles of built-in meshes a scene may have for [`small_built_in_geometry`]: its
/// BVH records then fit in the runtime's 64 KiB uniform table (2,048 records of 32 bytes, with
/// room for one record per object).
pub const SMALL_GEOMETRY_TRIANGLES: u64 = 4096;

/// Whether every object of `scene` has built-in geometry (`quad_mesh`, `cube_mesh`,
/// `sphere_mesh`, or a `@geometry` struct), with at most [`SMALL_GEOMETRY_TRIANGLES`] triangles
/// in all, and the scene imports no glTF model: what the compiler can tell, before any file is
/// read, of whether the scene's BVH is small.
pub fn small_built_in_geometry(scene: &crate::sema::hir::SceneDesc) -> bool {
    use crate::sema::hir::{Geometry, MeshAsset};
    if !scene.models.is_empty() {
        return false;
    }
    let mut triangles: u64 = 0;
    for object in &scene.objects {
        let t = match &object.geometry {
            Geometry::Mesh(MeshAsset::File { .. }) => return false,
            Geometry::Mesh(MeshAsset::Quad) => 2,
            Geometry::Mesh(MeshAsset::Cube) => 12,
            // An icosahedron (20 faces), each face split in four per subdivision.
            Geometry::Mesh(MeshAsset::Sphere { subdivisions }) => {
                20u64.saturating_mul(4u64.saturating_pow(*subdivisions))
            }
            Geometry::Custom(_) => 1,
        };
        triangles = triangles.saturating_add(t);
    }
    triangles <= SMALL_GEOMETRY_TRIANGLES
}

/// Why a scene could not be compiled: the diagnostics (with the sources to render them).
#[derive(Debug)]
pub struct CompileFailure {
    /// Everything that was checked, for rendering the diagnostics.
    pub checked: Checked,
    /// The errors (and warnings).
    pub diagnostics: Vec<Diagnostic>,
}

/// The framework kernel's files, checked with every scene.
pub const KERNEL_ROOTS: &[&str] = &["std/kernel/trace.rt", "std/kernel/wavefront.rt"];

/// E0706 for an ambiguous or unknown scene name; E0703 when the files declare no scene at all.
/// Both are located in the user's files: an unknown name at the scenes there are, no scene at the
/// start of the (first) user file, or, when `paths` held no `.rt` file at all (an empty folder),
/// at an empty source named after `paths`, added to `checked`'s sources for the purpose.
pub(crate) fn scene_choice_diagnostic(
    e: &crate::sema::hir::SceneChoiceError,
    checked: &mut Checked,
    paths: &[PathBuf],
) -> Diagnostic {
    use crate::sema::hir::SceneChoiceError as C;
    let program = checked.program.as_ref();
    let root_file = program.and_then(|p| p.modules.iter().find(|m| m.is_root).map(|m| m.file));
    let scenes: Vec<crate::source::Span> = program
        .map(|p| {
            p.scenes
                .iter()
                .filter(|(_, s)| p.modules[s.module.index()].is_root)
                .map(|(_, s)| s.span)
                .collect()
        })
        .unwrap_or_default();
    let shown: Vec<String> = paths.iter().map(|p| format!("`{}`", p.display())).collect();
    let shown = shown.join(", ");
    match e {
        C::NotFound { name, available } => {
            let names: Vec<String> = available.iter().map(|n| format!("`{n}`")).collect();
            let message = format!("no scene named `{name}` in {shown}");
            match scenes.split_first() {
                Some((first, rest)) => {
                    let mut d = Diagnostic::error(crate::diag::codes::E0706, message, *first)
                        .with_label(format!("a scene, not `{name}`"));
                    for s in rest {
                        d = d.with_secondary(*s, "another scene");
                    }
                    d.with_help(format!(
                        "the scenes are {}; choose one with `--scene NAME`",
                        names.join(", ")
                    ))
                }
                None => no_scene(checked, root_file, &shown, message),
            }
        }
        _ => e.to_diagnostic().unwrap_or_else(|| {
            let message = format!("there is no scene to compile in {shown}");
            no_scene(checked, root_file, &shown, message)
        }),
    }
}

/// E0703 (no scene) at the start of `file`, or of an empty source named `shown` when the paths
/// gave no file.
fn no_scene(
    checked: &mut Checked,
    file: Option<crate::source::FileId>,
    shown: &str,
    message: String,
) -> Diagnostic {
    let (file, help) = match file {
        Some(f) => (
            f,
            "declare one: `scene name { camera …  object … }` (see spec/scenes.md)".to_string(),
        ),
        None => (
            checked
                .sources
                .add(shown.trim_matches('`').to_string(), None, String::new()),
            format!("{shown} holds no `.rt` file; give a scene file, or a folder of them"),
        ),
    };
    Diagnostic::error(
        crate::diag::codes::E0703,
        message,
        crate::source::Span::new(file, 0, 0),
    )
    .with_help(help)
}

/// Writes the scene's program registry (its part of `rtc.registry.json` beside its file) if it
/// changed.
pub fn save_registry(c: &CompiledScene) -> std::io::Result<()> {
    let Some(program) = c.checked.program.as_ref() else {
        return Ok(());
    };
    let path = registry_path(program, c.scene);
    let key = registry_key(program, c.scene);
    let (mut registry, _) = crate::link::registry::load_scene(&path, &key);
    // Re-linking against the file's registry records exactly the ids this compile used.
    let _ = crate::link::link(program, c.scene, &mut registry, &LinkOptions::default());
    crate::link::registry::save_scene(&path, &key, &registry)
}

/// The scene's key in its registry file: the declaring file's name and the scene's name.
pub fn registry_key(program: &crate::sema::hir::Program, scene: SceneId) -> String {
    let s = &program.scenes[scene];
    let file = program.modules[s.module.index()]
        .path
        .as_deref()
        .and_then(std::path::Path::file_name)
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    crate::link::registry::scene_key(&file, &s.name)
}

/// The registry file of a scene: `rtc.registry.json` in the folder of the file that declares it.
pub fn registry_path(program: &crate::sema::hir::Program, scene: SceneId) -> PathBuf {
    let module = &program.modules[program.scenes[scene].module.index()];
    module
        .path
        .as_deref()
        .and_then(std::path::Path::parent)
        .unwrap_or(std::path::Path::new("."))
        .join(crate::link::registry::FILE_NAME)
}

/// Compiles the scene `scene` (or the only scene) of the given root files: the pipeline
/// ([`crate::pipeline::compile`]) without targets.
pub fn compile_scene(
    paths: &[PathBuf],
    scene: Option<&str>,
    options: &Options,
    link_options: &LinkOptions,
) -> Result<CompiledScene, Box<CompileFailure>> {
    compile_scene_with(
        paths,
        scene,
        options,
        link_options,
        &KernelOptions::default(),
    )
}

/// [`compile_scene`] with kernel options (a debug kernel: [`KernelOptions::debug`]).
pub fn compile_scene_with(
    paths: &[PathBuf],
    scene: Option<&str>,
    options: &Options,
    link_options: &LinkOptions,
    kernel_options: &KernelOptions,
) -> Result<CompiledScene, Box<CompileFailure>> {
    let request = crate::pipeline::Request {
        paths,
        scene,
        options,
        link: link_options,
        kernel: kernel_options,
        targets: &[],
    };
    crate::pipeline::compile(&request).map(|c| c.scene)
}

/// The bindings a kernel declares, in binding order.
pub type Bindings = Vec<&'static BindingDesc>;

/// Phases 5 and 6 of the pipeline: lowers the kernel function `root` (`render_invocation` or
/// `compute_bounds` of `stdlib/kernel/`) and everything it reaches, which pulls in exactly the
/// programs, dispatchers, loaders and bindings the scene uses, wraps it in the compute entry point
/// `entry` ([`RENDER_ENTRY`] or [`BOUNDS_ENTRY`]), validates and compacts the module. Returns it with
/// the bindings it declares; a failure is an internal error, as a diagnostic.
///
/// The wavefront model's shade stage is lowered with its `shadow` calls replayed (the shadow
/// stage traces them); [`lower_shade_stage`] chooses.
pub fn lower_kernel(
    checked: &Checked,
    linked: &Linked,
    root: &str,
    entry: &str,
) -> Result<(naga::Module, Bindings), Box<Diagnostic>> {
    let shade = entry == wavefront::Stage::Shade.entry();
    let ways = ShadeWays {
        replay_shadows: shade,
        traces_no_rays: shade,
        accumulates: false,
    };
    lower_kernel_with(checked, linked, root, entry, ways)
}

/// How a kernel's shadow rays, ray count and sample ends lower (the wavefront shade stage's ways;
/// all false in every other kernel), [`KernelHooks`]'s fields of the same names.
#[derive(Clone, Copy, Debug, Default)]
struct ShadeWays {
    /// `shadow(…)` is replayed (`shadow_replay`) rather than traced where it is made.
    replay_shadows: bool,
    /// `ray_count_load()` is a literal 0 and `pending_step_waits()` leaves the queries to the
    /// shadow stage.
    traces_no_rays: bool,
    /// `sample_done(…)` is `wf_sample_accumulate`, else `wf_sample_done`.
    accumulates: bool,
}

/// [`lower_kernel_with`] for the shade stage. `ways.accumulates` asks for the accumulation: where
/// every sample ends in its first shading step (no secondary rays; `traces_no_rays` false: no
/// shadow stage), the stage is first lowered with `sample_done` as `wf_sample_accumulate`, which
/// binds `accum`, and kept unless that takes it past [`wavefront::MAX_STORAGE_BUFFERS`]; otherwise
/// it is lowered without (the finish stage accumulates).
fn lower_shade_with(
    checked: &Checked,
    linked: &Linked,
    root: &str,
    ways: ShadeWays,
) -> Result<(naga::Module, Bindings), Box<Diagnostic>> {
    let entry = wavefront::Stage::Shade.entry();
    if ways.accumulates && !linked.config.has_secondary_rays && !ways.traces_no_rays {
        let lowered = lower_kernel_with(checked, linked, root, entry, ways)?;
        if wavefront::storage_buffers(&lowered.1) <= wavefront::MAX_STORAGE_BUFFERS {
            return Ok(lowered);
        }
    }
    let ways = ShadeWays {
        accumulates: false,
        ..ways
    };
    lower_kernel_with(checked, linked, root, entry, ways)
}

/// The wavefront model's shade stage, and whether it traces its own shadow rays (then the scene
/// has no shadow stage), as `placement` says ([`ShadowRays::Auto`] is taken as
/// [`ShadowRays::AutoFastFrames`]; the compile resolves it first, [`ShadowRays::for_samples`]): where
/// they are made when asked to or when that makes at most the automatic choice's number of copies
/// of the traversal ([`weight::inlined_copies`]), else lowered a second time, replaying them
/// within the stage (`wf_shade_replay_invocation`) or for the shadow stage. With `accumulate`,
/// a shade stage whose samples all end in their first step also does the finish stage's work in a
/// round over a tile the host listed, where `accum` fits its bindings
/// ([`CompiledScene::shade_accumulates`]; the compile asks for it beyond
/// [`wavefront::SHADE_ACCUMULATES_MIN_SAMPLES`]).
pub fn lower_shade_stage(
    checked: &Checked,
    linked: &Linked,
    placement: ShadowRays,
    accumulate: bool,
) -> Result<(naga::Module, Bindings, bool), Box<Diagnostic>> {
    let stage = wavefront::Stage::Shade;
    let ways = |replay_shadows, traces_no_rays| ShadeWays {
        replay_shadows,
        traces_no_rays,
        accumulates: accumulate,
    };
    let most = match placement {
        ShadowRays::Replay | ShadowRays::Stage => None,
        ShadowRays::Shade => Some(u64::MAX),
        ShadowRays::AutoFastCompile => Some(wavefront::MAX_SHADE_TRAVERSALS),
        ShadowRays::Auto | ShadowRays::AutoFastFrames => {
            Some(wavefront::MAX_SHADE_TRAVERSALS_FAST_FRAMES)
        }
    };
    if let Some(most) = most {
        let (module, bindings) =
            lower_shade_with(checked, linked, stage.root(), ways(false, false))?;
        let copies = weight::inlined_copies(&module, stage.entry(), wavefront::TRAVERSAL_FN)
            .unwrap_or(u64::MAX);
        if copies <= most {
            return Ok((module, bindings, true));
        }
    }
    if matches!(placement, ShadowRays::Stage | ShadowRays::AutoFastCompile) {
        let (module, bindings) = lower_shade_with(checked, linked, stage.root(), ways(true, true))?;
        return Ok((module, bindings, false));
    }
    let (module, bindings) = lower_shade_with(
        checked,
        linked,
        wavefront::SHADE_REPLAY_ROOT,
        ways(true, false),
    )?;
    Ok((module, bindings, true))
}

/// [`lower_kernel`], with the shade stage's `ways`: `shadow` calls replayed (`shadow_replay`) or
/// traced where they are made; with `traces_no_rays`, `ray_count_load()` is a literal 0 and
/// `pending_step_waits()` leaves the queries to the shadow stage (a shade stage whose shadow stage
/// traces them); with `accumulates`, `sample_done(…)` is `wf_sample_accumulate` (a shade stage
/// whose samples all end in their first step), else `wf_sample_done`.
fn lower_kernel_with(
    checked: &Checked,
    linked: &Linked,
    root: &str,
    entry: &str,
    ways: ShadeWays,
) -> Result<(naga::Module, Bindings), Box<Diagnostic>> {
    let Some(program) = checked.program.as_ref() else {
        return Err(Box::new(Diagnostic::error(
            crate::diag::codes::ICE,
            "the checked program is missing",
            crate::source::Span::default(),
        )));
    };
    let lowered = lower_entry(program, &checked.sources, linked, root, entry, ways);
    match lowered {
        Ok((mut module, bindings)) => {
            // Compaction drops types and constants nothing uses, so outputs (and their snapshots)
            // change only when the code does.
            naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
            Ok((module, bindings))
        }
        Err(e) => Err(Box::new(e.to_diagnostic(program))),
    }
}

fn lower_entry(
    program: &Program,
    sources: &crate::source::SourceMap,
    linked: &Linked,
    root: &str,
    entry: &str,
    ways: ShadeWays,
) -> Result<(naga::Module, Bindings), LowerError> {
    let root = intrinsics::kernel_fn(program, root)?;
    let mut hooks = KernelHooks {
        program,
        linked,
        config: linked.config,
        generated: dispatch::Generated::default(),
        replay_shadows: ways.replay_shadows,
        traces_no_rays: ways.traces_no_rays,
        accumulates: ways.accumulates,
    };
    let build_entry = |cx: &mut crate::lower::Lowerer<'_>,
                       roots: &[naga::Handle<naga::Function>]| {
        match (entry, roots) {
            (RENDER_ENTRY, [f]) => entry::render_entry(cx, *f),
            (BOUNDS_ENTRY, [f]) => entry::bounds_entry(cx, *f),
            (name, [f]) if wavefront::Stage::from_entry(name).is_some() => {
                entry::stage_entry(cx, name, *f)
            }
            _ => Err(dispatch::kernel_error(format!(
                "no kernel entry point `{entry}`"
            ))),
        }
    };
    let lowered = crate::lower::lower(program, sources, &[root], &mut hooks, build_entry)?;
    Ok((lowered.module, hooks.generated.used_bindings()))
}
