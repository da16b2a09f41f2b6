//! Rendering a compiled scene: from `rtc_compiler::kernel::CompiledScene` to a [`LinearImage`].
//!
//! [`Renderer::new`] does the one-time work, in order:
//! 1. the scene entities ([`Entities::build`]: assets, one BVH per mesh, `params`);
//! 2. the render kernel's pipeline (from the compiled `naga::Module`, with exactly the bindings the
//!    compiler lists and the tile uniform at the `tile` binding), created with the bounds kernel
//!    of step 3 as one set by [`create_scene_kernels`] (memory and disk caches, parallel compile,
//!    per-kernel accounting in [`RenderStats::kernels`]), its small tables placed in uniform
//!    buffers where the adapter compiles those faster ([`UniformTables`]). Each new pipeline's
//!    warm-up dispatch,
//!    where lavapipe compiles it (seconds for the full kernel), runs there, so the compile belongs
//!    to the setup, not to the render time;
//! 3. for scenes with custom geometry, the bounds kernel: instances uploaded in object order, one
//!    invocation per object, boxes read back from `accum` and handed to the entities, which then
//!    build the scene-level BVH (the one read-back of the setup: `Renderer::new_async`, for the
//!    web, awaits it instead of blocking);
//! 4. the first upload of every buffer ([`GpuScene::upload`]), so data above a device limit fails
//!    here with the buffer set's typed error naming the binding.
//!
//! [`Renderer::render`] then renders the whole image: it rebuilds the scene-level BVH if an object
//! moved ([`Renderer::set_transform`]), uploads what changed, zeroes the accumulation buffer and the
//! counters, runs `ceil(total_samples / samples_per_pass)` passes (each a tiled dispatch with
//! `TileParams.frame` = the pass index), reports progress over all tiles of all passes, reads the
//! accumulation back and averages it (rgb / a).
//!
//! A renderer is also the **live session** of a scene (the thesis's CPU render pipeline, 3.2.3):
//! built once, it keeps entities, buffers and kernels across frames and edits.
//! [`Renderer::accumulate`] adds passes to a running accumulation ([`Renderer::image`] reads it);
//! [`Renderer::set_field`] / [`Renderer::set_camera`] write an instance's fields in place and
//! [`Renderer::set_transform`] moves an object, each uploading only the words that changed (the
//! scene-level BVH's nodes and the instance records for a move; no object-level BVH is rebuilt)
//! and restarting the accumulation; [`Renderer::replace_kernel`] swaps in a recompile and keeps
//! every asset and object-level BVH whose file did not change ([`AssetStore`]) and every buffer
//! whose contents did not change. [`RenderStats::blas_builds`] and [`RenderStats::files_read`]
//! count over the session's life.
//!
//! Samples: every pass takes the camera's `samples_per_pass`, so the samples per pixel actually
//! taken are `total_samples` rounded up to a multiple of it ([`RenderStats::samples`]); the average
//! is exact whatever the count, because `accum.a` counts the samples.
//!
//! Rays per second are given twice: primary rays only (`width × height × samples`), and every ray
//! the kernel traced (camera, secondary and shadow rays: the kernel's counter 1, read after each
//! pass so a 32-bit counter cannot wrap within a render of fewer than 2³² rays per pass).
//!
//! Invariants: nothing here panics on run-time data or exits; every failure is a [`RenderError`];
//! wgpu errors raised outside our error scopes are collected after a render and reported.

#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::indexing_slicing
    )
)]

use web_time::Instant;

use glam::Mat4;
use rtc_bvh::Aabb;
/// The BVH builder presets ([`RenderOptions::bvh`]), re-exported for callers without `rtc-bvh`.
pub use rtc_bvh::BuildPreset;
use rtc_compiler::abi;
use rtc_compiler::kernel::wavefront;
/// The execution models ([`RenderOptions::exec`]), re-exported for callers.
pub use rtc_compiler::kernel::ExecModel;
use rtc_compiler::kernel::{
    CompiledScene, BOUNDS_ENTRY, BOUNDS_WORKGROUP, RENDER_ENTRY, RENDER_WORKGROUP,
};

use crate::assets::AssetRoots;
use crate::gpu::{
    dispatch_once, plan_tiles, BufferLimits, DispatchError, Gpu, Kernel, KernelDesc, KernelReport,
    KernelSource, PipelineCacheStatus, PipelineError, RoundDispatch, RoundKernels, TileConfig,
    TileDispatcher, TileList,
};
use crate::image_out::{ImageError, LinearImage, ToneMap};
use crate::resolve::{ResolveError, ResolveTarget, Resolver};
/// Which instance a field write goes to ([`Renderer::set_field`]), re-exported.
pub use crate::scene::FieldTarget;
use crate::scene::{
    AssetStore, Entities, EntityOptions, FrameUniforms, GpuScene, ObjectGeometry, SceneError,
    SrgbTextures, TablePlacement, UniformTables, UploadReport,
};
use rtc_compiler::sema::hir::{ConstValue, Instance, Program};

/// What to change from the scene's own settings, and how to run.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RenderOptions {
    /// Image size `[width, height]` instead of the scene's.
    pub size: Option<[u32; 2]>,
    /// Samples per pixel in total instead of the scene's `samples`.
    pub samples: Option<u32>,
    /// Tile size and batching; `None` picks [`TileConfig::for_adapter`].
    pub tiles: Option<TileConfig>,
    /// The BVH builder preset.
    pub bvh: BuildPreset,
    /// Buffer limits to enforce instead of the device's (tests fake tiny ones).
    pub limits: Option<BufferLimits>,
    /// Folders besides the scene's own that its assets may come from (`--asset-root`).
    pub asset_roots: AssetRoots,
    /// How samples are executed (`None`: as compiled, `CompiledScene::exec`);
    /// [`ExecModel::Wavefront`] needs a scene compiled with its stage kernels.
    pub exec: Option<ExecModel>,
    /// Wavefront model: submit and wait for each stage's dispatches alone and time them
    /// ([`RenderStats::stage_ms`]; `rtc render` sets it from `RTC_STAGE_TIMES`). A profile:
    /// the frame is slower by the waits, the image the same.
    pub stage_times: bool,
    /// Which small tables (`nodes`, `instances`) the kernels read from uniform buffers instead
    /// of storage buffers ([`TablePlacement::Auto`]: on lavapipe before Mesa 26, or on a CPU
    /// without AVX-512, where it makes the compile shorter; see `scene::UniformTables`). The image
    /// is the same either way.
    pub uniform_tables: TablePlacement,
    /// Flatten static objects that have meshes of their own into shared world-space BVHs (one
    /// scene-level leaf for them all; `scene::EntityOptions::flatten`): faster to trace for scenes
    /// of many small objects. For one-shot renders: moving a flattened object undoes it. The
    /// image differs only by the rounding of the baked vertices and normals.
    pub flatten: bool,
    /// How 8-bit sRGB textures are stored ([`SrgbTextures`]: decoded to linear half floats
    /// while they fit a budget, unless this or `RTC_SRGB_TEXTURES=encoded` says encoded). The
    /// image differs by the half floats' rounding, about 2^-11 of a texel's value.
    pub srgb_textures: SrgbTextures,
}

/// Why a scene could not be rendered.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The scene could not be turned into entities or buffers.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A kernel pipeline could not be created.
    #[error(transparent)]
    Pipeline(#[from] PipelineError),
    /// A dispatch or read-back failed.
    #[error(transparent)]
    Dispatch(#[from] DispatchError),
    /// The accumulation could not be turned into an image.
    #[error(transparent)]
    Image(#[from] ImageError),
    /// The accumulation could not be resolved into the host's target.
    #[error(transparent)]
    Resolve(#[from] ResolveError),
    /// The image size is zero.
    #[error("cannot render a {width}x{height} image: both sides must be at least 1")]
    BadSize {
        /// Width asked for.
        width: u32,
        /// Height asked for.
        height: u32,
    },
    /// The sample count is zero.
    #[error("cannot render with 0 samples per pixel")]
    NoSamples,
    /// The render kernel does not declare the tile uniform, so it cannot be dispatched in tiles.
    #[error("internal error: the render kernel declares no `tile` binding")]
    NoTileBinding,
    /// A kernel declares a binding that is not in the ABI table.
    #[error("internal error: kernel `{kernel}` declares `{name}` at binding {binding}, which the ABI does not have")]
    UnknownBinding {
        /// Which kernel.
        kernel: &'static str,
        /// The variable's name.
        name: String,
        /// Its binding.
        binding: u32,
    },
    /// A debug pass was asked of a renderer running the wavefront model.
    #[error("internal error: debug passes run on the megakernel only")]
    DebugNeedsMegakernel,
    /// The wavefront model was asked for, but the scene was compiled without its stage kernels.
    #[error("internal error: the wavefront model needs the scene compiled with its stage kernels (KernelOptions::exec)")]
    NoStageKernels,
    /// The kernel set came back shorter than asked for.
    #[error("internal error: a kernel of the set was not created")]
    KernelSet,
    /// The scene has custom geometry but the compile produced no bounds kernel.
    #[error("internal error: the scene has custom geometry but no bounds kernel was compiled")]
    NoBoundsKernel,
    /// wgpu reported errors outside the runtime's error scopes.
    #[error("wgpu reported errors during the render: {}", messages.join("; "))]
    Wgpu {
        /// The messages.
        messages: Vec<String>,
    },
}

/// Figures of one render (and of the setup it needed).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RenderStats {
    /// The adapter, one line.
    pub adapter: String,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Samples per pixel one pass takes.
    pub samples_per_pass: u32,
    /// Samples per pixel taken (passes × samples per pass).
    pub samples: u32,
    /// Passes.
    pub passes: u32,
    /// Passes one dispatch ran ([`passes_per_dispatch`]; 1 but for a still render with the
    /// megakernel).
    pub passes_per_dispatch: u32,
    /// Tiles dispatched, over all passes (a dispatch of several passes counts once).
    pub tiles: u64,
    /// Milliseconds building BVHs for this render: every BLAS and the TLAS on the first render,
    /// only the TLAS after objects moved, 0 when nothing changed.
    pub bvh_build_ms: f64,
    /// Milliseconds loading assets (first render only).
    pub load_ms: f64,
    /// Milliseconds running the bounds kernel (first render of a scene with custom geometry).
    pub bounds_ms: f64,
    /// Milliseconds creating the kernel pipelines, including the warm-up dispatches that absorb
    /// drivers' compile-at-first-dispatch (first render only).
    pub pipeline_ms: f64,
    /// Each kernel of the scene: compiled or reused, and its cost (first render only).
    pub kernels: Vec<KernelReport>,
    /// The on-disk pipeline cache (first render only).
    pub pipeline_cache: Option<PipelineCacheStatus>,
    /// Milliseconds uploading: CPU staging plus the transfer before the first pass.
    pub upload_ms: f64,
    /// Bytes uploaded.
    pub bytes_uploaded: u64,
    /// Bindings whose data was written, by ABI name.
    pub buffers_written: Vec<&'static str>,
    /// Milliseconds of the passes (dispatch to completion), without uploads and read-back.
    pub render_ms: f64,
    /// Milliseconds reading the image back.
    pub readback_ms: f64,
    /// Primary rays traced (`width × height × samples`).
    pub primary_rays: u64,
    /// Primary rays per second of `render_ms`.
    pub rays_per_second: f64,
    /// Rays traced: camera, secondary and shadow rays (the kernel's counter 1; 0 for a kernel
    /// without it).
    pub rays_traced: u64,
    /// Rays traced per second of `render_ms`.
    pub traced_rays_per_second: f64,
    /// Samples that were NaN or infinite and counted as zero (the kernel's counter 0).
    pub nonfinite_samples: u32,
    /// Distinct triangles in memory.
    pub triangles: u64,
    /// Triangles as instanced by the objects.
    pub instanced_triangles: u64,
    /// Distinct meshes (one BLAS each).
    pub meshes: u32,
    /// Objects of the scene.
    pub objects: u32,
    /// Objects in the scene-level BVH (objects without a usable box are left out).
    pub instances: u32,
    /// The tables the kernels read from uniform buffers (`RenderOptions::uniform_tables`), by
    /// ABI name; empty when all are storage buffers.
    pub uniform_tables: Vec<&'static str>,
    /// Lights.
    pub lights: u32,
    /// Object-level BVH (BLAS) builds so far in this renderer's life, kernel replacements
    /// included (moving objects builds none).
    pub blas_builds: u32,
    /// Objects flattened into shared world-space BVHs ([`RenderOptions::flatten`]), and those
    /// BVHs.
    pub flattened: (u32, u32),
    /// 8-bit sRGB textures stored decoded as linear half floats ([`RenderOptions::srgb_textures`]).
    pub decoded_textures: u32,
    /// Asset files (meshes, images, glTF files) read so far in this renderer's life.
    pub files_read: u32,
    /// Samples per pixel in the accumulation after these passes.
    pub accumulated_samples: u32,
    /// TLAS builds so far.
    pub tlas_builds: u32,
    /// Problems that did not stop the render.
    pub warnings: Vec<String>,
    /// The execution model that ran.
    pub exec: ExecModel,
    /// Wavefront rounds run over all tiles and passes (0 for the megakernel).
    pub rounds: u64,
    /// The running paths the wavefront rounds listed, summed over rounds, tiles and passes: the
    /// invocations of each listed stage (camera, trace, shade, shadow) that held a path.
    pub listed_slots: u64,
    /// The tiles' pixels summed over the same rounds: the invocations a stage run over the whole
    /// tile would take (`listed_slots / slot_rounds`, the lanes compaction keeps busy).
    pub slot_rounds: u64,
    /// With [`RenderOptions::stage_times`], the wavefront kernels' milliseconds, each dispatch
    /// timed alone (`RoundsReport::stage_ms`, summed over passes); empty otherwise.
    pub stage_ms: Vec<(String, f64)>,
}

/// An image and how it was made.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderResult {
    /// Mean radiance per pixel.
    pub image: LinearImage,
    /// Figures.
    pub stats: RenderStats,
}

/// One-time costs, reported with the first render.
#[derive(Clone, Debug, Default)]
struct Setup {
    kernels: Vec<KernelReport>,
    pipeline_cache: Option<PipelineCacheStatus>,
    bvh_ms: f64,
    load_ms: f64,
    bounds_ms: f64,
    pipeline_ms: f64,
    upload: Option<(f64, u64)>,
}

/// A compiled scene ready to render on one GPU.
#[derive(Debug)]
pub struct Renderer<'g> {
    gpu: &'g Gpu,
    entities: Entities,
    scene: GpuScene,
    kernels: Kernels,
    /// `FrameUniforms::path_slots`: one tile's path slots (wavefront), else 0.
    path_slots: u32,
    /// Byte offset in `paths` of the word the wavefront rounds set while a path runs.
    path_flag_offset: u64,
    dispatcher: TileDispatcher,
    size: [u32; 2],
    samples_per_pass: u32,
    total_samples: u32,
    setup: Setup,
    written_at_setup: Vec<&'static str>,
    /// The resolve pass ([`Renderer::resolve_into`]), its pipelines created on first use.
    resolver: Resolver,
    /// The program the entities were built from (field writes pack with it).
    program: Program,
    /// What the renderer was made with (a kernel replacement keeps it).
    options: RenderOptions,
    /// Assets and object-level BVHs, kept across kernel replacements.
    store: AssetStore,
    /// Passes in the running accumulation (0: it starts afresh at the next pass).
    passes_done: u32,
}

/// The render kernel, or the wavefront model's stage kernels (in `wavefront::stages` order).
#[derive(Debug)]
enum Kernels {
    Mega(Kernel),
    Wavefront {
        stages: Vec<Kernel>,
        /// The most rounds one tile may take.
        max_rounds: u32,
        /// A sample is one shading step: no secondary rays and no shadow stage, so with one
        /// sample a pass every path ends in a tile's first round ([`one_step`]).
        one_step: bool,
        /// The shade stage accumulates the samples of a tile the host listed
        /// (`CompiledScene::shade_accumulates`): no finish stage after such a round.
        shade_accumulates: bool,
    },
}

impl Kernels {
    /// The dispatch of a wavefront pass: a round is count, compact, trace (which starts a new
    /// sample's camera ray too), shade, and with a shadow stage shadow, shade (`stages` in
    /// `wavefront::stages` order), each dispatched as its
    /// [`wavefront::Stage::dispatch`] says. With `first_round_ends` (every path ends in a tile's
    /// first round), the host lists the tile itself (`wavefront::LIST_TILE`) for its one round,
    /// without the count and compact stages, and, with `shade_accumulates`, without the finish
    /// stage, whose work the shade stage does.
    fn rounds(
        stages: &[Kernel],
        max_rounds: u32,
        flag_offset: u64,
        timed: bool,
        first_round_ends: bool,
        shade_accumulates: bool,
    ) -> Option<RoundKernels<'_>> {
        let (count, compact, trace, shade, shadow, finish) = match stages {
            [count, compact, trace, shade, shadow, finish] => {
                (count, compact, trace, shade, Some(shadow), finish)
            }
            [count, compact, trace, shade, finish] => (count, compact, trace, shade, None, finish),
            _ => return None,
        };
        let how = |stage: wavefront::Stage| match stage.dispatch() {
            wavefront::StageDispatch::Tile => RoundDispatch::Tile,
            wavefront::StageDispatch::Blocks => RoundDispatch::Row(wavefront::COMPACT_WORKGROUPS),
            wavefront::StageDispatch::Listed => {
                RoundDispatch::Indirect(flag_offset + wavefront::TAIL_DISPATCH_OFFSET)
            }
        };
        use wavefront::Stage as S;
        let mut round = vec![
            (count, how(S::Count)),
            (compact, how(S::Compact)),
            (trace, how(S::Trace)),
            (shade, how(S::Shade)),
        ];
        if let Some(shadow) = shadow {
            round.extend([(shadow, how(S::Shadow)), (shade, how(S::Shade))]);
        }
        Some(RoundKernels {
            round,
            finish,
            tile_list: (first_round_ends && shadow.is_none()).then_some(TileList {
                selector_offset: flag_offset + wavefront::TAIL_SELECTOR_OFFSET,
                selector: wavefront::LIST_TILE,
                group: RENDER_WORKGROUP[0] * RENDER_WORKGROUP[1],
                accumulates: shade_accumulates,
            }),
            flag_binding: abi::binding("paths")?.binding,
            flag_offset,
            max_rounds,
            timed,
        })
    }
}

/// Whether a sample of the wavefront model is one shading step: no secondary rays (no stack of
/// frames, no path loop) and no shadow stage (the shade stage traces its shadow rays, or replays
/// them within itself until the step commits, `wf_shade_replay_invocation`), so a path that the
/// trace stage starts ends in the shade stage of the same round.
fn one_step(compiled: &CompiledScene) -> bool {
    !compiled.linked.config.has_secondary_rays && !compiled.has_shadow_stage()
}

/// Rounds one tile of the wavefront model may take: each of a sample's rays needs a round (the
/// tree of a sample holds at most `sum of max_spawn^d` rays for `d <= max_depth`), a shading step
/// whose shadow queries depend on each other up to `SHADOW_QUERIES` more when the shadow stage
/// traces them, and two to spare.
fn max_rounds(compiled: &CompiledScene) -> u32 {
    let c = &compiled.linked.config;
    let mut rays: u64 = 1;
    let mut level: u64 = 1;
    if c.has_secondary_rays {
        for _ in 0..c.max_depth {
            level = level.saturating_mul(u64::from(c.max_spawn.max(1)));
            rays = rays.saturating_add(level);
        }
    }
    let replays = if compiled.has_shadow_stage() {
        u64::from(wavefront::SHADOW_QUERIES)
    } else {
        0
    };
    let per_sample = rays.saturating_mul(1 + replays);
    let rounds = per_sample
        .saturating_mul(u64::from(compiled.samples_per_pass.max(1)))
        .saturating_add(2);
    u32::try_from(rounds.min(1 << 24)).unwrap_or(1 << 24)
}

/// The wavefront model's tiles (dispatched one at a time, whatever `tiles_per_batch` says): the
/// adapter's tiles, no larger than the image (rounded up to
/// whole 8 x 8 workgroups), halved along their longer side until one tile's path records
/// (`path_words` words a pixel) and their tail (`wavefront::tail_bytes`) fit one storage binding of at most `max_binding` bytes.
fn wavefront_tiles(
    mut tiles: TileConfig,
    [width, height]: [u32; 2],
    path_words: u32,
    max_binding: u64,
) -> TileConfig {
    tiles.tile_width = tiles.tile_width.min(width.next_multiple_of(8)).max(8);
    tiles.tile_height = tiles.tile_height.min(height.next_multiple_of(8)).max(8);
    let bytes = |t: &TileConfig| {
        let slots = t.tile_width * t.tile_height;
        u64::from(slots) * u64::from(path_words) * 4 + wavefront::tail_bytes(slots)
    };
    while bytes(&tiles) > max_binding && (tiles.tile_width > 8 || tiles.tile_height > 8) {
        if tiles.tile_width >= tiles.tile_height {
            tiles.tile_width = (tiles.tile_width / 2).max(8);
        } else {
            tiles.tile_height = (tiles.tile_height / 2).max(8);
        }
    }
    tiles
}

/// The part of `program` that field writes need (types and structs, for layouts and packing),
/// without the function bodies.
fn layout_program(program: &Program) -> Program {
    Program {
        types: program.types.clone(),
        structs: program.structs.clone(),
        ..Program::default()
    }
}

/// What a frame during an interactive camera move may take (`rtc view`): a scene whose whole pass
/// is slower is shown reduced ([`preview_factor`], [`Renderer::preview`]).
pub const PREVIEW_BUDGET_MS: f64 = 40.0;

/// The reduction of width and height (1, 2, 4 or 8) for a step during a camera move when a whole
/// pass took `pass_ms`: the smallest whose pass (about `pass_ms / factor²`) fits
/// [`PREVIEW_BUDGET_MS`]; 1 before any whole pass was measured.
pub fn preview_factor(pass_ms: Option<f64>) -> u32 {
    let Some(ms) = pass_ms.filter(|ms| ms.is_finite()) else {
        return 1;
    };
    [1u32, 2, 4]
        .into_iter()
        .find(|&f| ms / f64::from(f * f) <= PREVIEW_BUDGET_MS)
        .unwrap_or(8)
}

/// The image size of a [`Renderer::preview`] at `1 / factor` (clamped to 1 to 64) of `size`,
/// rounded up.
pub fn preview_size([width, height]: [u32; 2], factor: u32) -> [u32; 2] {
    let f = factor.clamp(1, 64);
    [width.div_ceil(f), height.div_ceil(f)]
}

/// The most samples per pixel one megakernel dispatch of a still render takes
/// ([`passes_per_dispatch`]).
pub const MAX_SAMPLES_PER_DISPATCH: u32 = 16;

/// How many of a still render's `passes` passes (of `samples_per_pass` samples) one dispatch of
/// the megakernel runs ([`Renderer::render`]): the most that divide `passes` and keep a dispatch
/// at [`MAX_SAMPLES_PER_DISPATCH`] samples a pixel or fewer (at least 1). The image does not
/// depend on it (each pass is added to `accum` as its own dispatch adds it, `render_pixel` in
/// `stdlib/kernel/trace.rt`); the frame does: one dispatch and one read-back of the counters fewer
/// a pass, and in a path loop a lane whose path ends starts its next sample instead of idling
/// until its SIMD batch's longest path ends (cornell_path on lavapipe, 16 samples a dispatch:
/// docs/bench/README.md, "Several passes a dispatch (2026-12-07)"). Interactive
/// accumulation ([`Renderer::accumulate`]) keeps one pass a dispatch; so does the wavefront
/// model, whose slots already start their next sample as soon as one ends.
pub fn passes_per_dispatch(passes: u32, samples_per_pass: u32) -> u32 {
    let most = MAX_SAMPLES_PER_DISPATCH / samples_per_pass.max(1);
    (1..=most.min(passes))
        .rev()
        .find(|k| passes % k == 0)
        .unwrap_or(1)
}

fn ms_since(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}

/// The ABI bindings a kernel module declares (its globals with a resource binding).
fn declared_bindings(
    module: &naga::Module,
    kernel: &'static str,
) -> Result<Vec<&'static abi::BindingDesc>, RenderError> {
    let mut out = Vec::new();
    for (_, var) in module.global_variables.iter() {
        let Some(rb) = &var.binding else { continue };
        let name = var.name.clone().unwrap_or_default();
        match abi::BINDINGS.iter().find(|b| b.binding == rb.binding) {
            Some(b) if rb.group == 0 && b.name == name => out.push(b),
            _ => {
                return Err(RenderError::UnknownBinding {
                    kernel,
                    name,
                    binding: rb.binding,
                })
            }
        }
    }
    out.sort_by_key(|b| b.binding);
    Ok(out)
}

/// A scene's kernels, created as one set ([`create_scene_kernels`]).
#[derive(Debug)]
pub struct SceneKernels {
    /// The render kernel (megakernel), or the stage kernels in `wavefront::stages` order.
    pub render: Vec<Kernel>,
    /// The bounds kernel and the ABI bindings it declares, when it was asked for.
    pub bounds: Option<(Kernel, Vec<&'static abi::BindingDesc>)>,
    /// Every ABI binding the render or stage kernels declare (the bounds kernel's are in
    /// `bounds`).
    pub bindings: Vec<&'static abi::BindingDesc>,
}

/// Creates the kernels of `compiled` for `exec` as one set with [`Gpu::create_kernels`] (memory
/// and disk caches, parallel creation, warm-up, per-kernel accounting in [`Kernel::report`]): the
/// render kernel or the wavefront model's stage kernels (six or seven), and the bounds kernel when
/// `with_bounds` (a scene with custom geometry), every module specialised with `tables` (the
/// same for all, so that one set of buffers serves them). Used by [`Renderer::new`] and by `rtc
/// compile --timings driver`.
pub fn create_scene_kernels(
    gpu: &Gpu,
    compiled: &CompiledScene,
    exec: ExecModel,
    with_bounds: bool,
    tables: UniformTables,
) -> Result<SceneKernels, RenderError> {
    let tile = abi::binding("tile").ok_or(RenderError::NoTileBinding)?;
    if !compiled.bindings.iter().any(|b| b.binding == tile.binding) {
        return Err(RenderError::NoTileBinding);
    }
    // (label, module, entry point, ABI bindings) of each render or stage kernel.
    let mut parts: Vec<(
        String,
        &naga::Module,
        &'static str,
        Vec<&'static abi::BindingDesc>,
    )> = Vec::new();
    match exec {
        ExecModel::Megakernel => parts.push((
            "rtc render".to_string(),
            &compiled.render,
            RENDER_ENTRY,
            compiled.bindings.clone(),
        )),
        ExecModel::Wavefront => {
            let stages = compiled
                .stages
                .as_ref()
                .ok_or(RenderError::NoStageKernels)?;
            if stages
                .iter()
                .map(|s| s.stage)
                .ne(wavefront::stages(compiled.has_shadow_stage()))
            {
                return Err(RenderError::NoStageKernels);
            }
            for s in stages {
                parts.push((
                    format!("rtc {}", s.stage.entry()),
                    &s.module,
                    s.stage.entry(),
                    s.bindings.clone(),
                ));
            }
        }
    }
    let runtime: Vec<Vec<crate::gpu::BindingDesc>> = parts
        .iter()
        .map(|(_, _, _, b)| GpuScene::runtime_bindings_with(b, tables))
        .collect();
    let bounds_module = match (&compiled.bounds, with_bounds) {
        (Some(module), true) => {
            let declared = declared_bindings(module, "bounds")?;
            let bindings = GpuScene::runtime_bindings_with(&declared, tables);
            Some((module, declared, bindings))
        }
        (None, true) => return Err(RenderError::NoBoundsKernel),
        (_, false) => None,
    };
    let mut descs: Vec<KernelDesc<'_>> = parts
        .iter()
        .zip(&runtime)
        .map(|((label, module, entry, _), bindings)| KernelDesc {
            label,
            source: KernelSource::Naga(specialised(module, tables)),
            entry_point: entry,
            bindings,
            tile_binding: Some(tile.binding),
        })
        .collect();
    if let Some((module, _, bindings)) = &bounds_module {
        descs.push(KernelDesc {
            label: "rtc bounds",
            source: KernelSource::Naga(specialised(module, tables)),
            entry_point: BOUNDS_ENTRY,
            bindings,
            tile_binding: None,
        });
    }
    let mut kernels = gpu.create_kernels(descs).into_iter();
    let mut render = Vec::with_capacity(parts.len());
    for _ in 0..parts.len() {
        render.push(kernels.next().ok_or(RenderError::KernelSet)??);
    }
    let bounds = match bounds_module {
        Some((_, declared, _)) => Some((kernels.next().ok_or(RenderError::KernelSet)??, declared)),
        None => None,
    };
    let mut bindings = Vec::new();
    for (_, _, _, b) in &parts {
        for &d in b {
            if !bindings.contains(&d) {
                bindings.push(d);
            }
        }
    }
    Ok(SceneKernels {
        render,
        bounds,
        bindings,
    })
}

/// A copy of `module` with `tables` as uniform buffers.
fn specialised(module: &naga::Module, tables: UniformTables) -> Box<naga::Module> {
    let mut module = Box::new(module.clone());
    tables.specialise(&mut module);
    module
}

impl<'g> Renderer<'g> {
    /// Prepares `compiled` for rendering on `gpu` (see the module docs for the steps).
    pub fn new(
        gpu: &'g Gpu,
        compiled: &CompiledScene,
        options: RenderOptions,
    ) -> Result<Self, RenderError> {
        Self::build(gpu, compiled, options, AssetStore::new(), None)
    }

    /// [`new`](Self::new) without blocking, for the web (`wasm32`): the one read-back of the
    /// setup (the boxes of custom geometry, from the bounds kernel) is awaited.
    #[cfg(target_arch = "wasm32")]
    pub async fn new_async(
        gpu: &'g Gpu,
        compiled: &CompiledScene,
        options: RenderOptions,
    ) -> Result<Self, RenderError> {
        let mut staged = Self::begin(gpu, compiled, options, AssetStore::new(), None)?;
        if let Some(started) = staged.dispatch_bounds()? {
            let boxes = staged.scene.read_accumulation_async(gpu).await?;
            staged.take_bounds(started, &boxes)?;
        }
        staged.finish(compiled)
    }

    /// [`new`](Self::new) with what a previous renderer of the scene leaves: its asset store and,
    /// from its GPU scene, every buffer whose contents are unchanged.
    fn build(
        gpu: &'g Gpu,
        compiled: &CompiledScene,
        options: RenderOptions,
        store: AssetStore,
        previous: Option<(GpuScene, &Entities)>,
    ) -> Result<Self, RenderError> {
        let mut staged = Self::begin(gpu, compiled, options, store, previous)?;
        if let Some(started) = staged.dispatch_bounds()? {
            let boxes = staged.scene.read_accumulation(gpu)?;
            staged.take_bounds(started, &boxes)?;
        }
        staged.finish(compiled)
    }

    /// The setup up to the bounds kernel: entities (assets, BVHs), pipelines, the GPU scene.
    fn begin(
        gpu: &'g Gpu,
        compiled: &CompiledScene,
        options: RenderOptions,
        mut store: AssetStore,
        previous: Option<(GpuScene, &Entities)>,
    ) -> Result<Staged<'g>, RenderError> {
        let program = compiled
            .checked
            .program
            .as_ref()
            .ok_or(SceneError::NoProgram)?;
        let desc = &program.scenes[compiled.scene];
        let [width, height] = options
            .size
            .unwrap_or([desc.settings.width, desc.settings.height]);
        if width == 0 || height == 0 {
            return Err(RenderError::BadSize { width, height });
        }
        let total_samples = options.samples.unwrap_or(desc.settings.samples);
        if total_samples == 0 {
            return Err(RenderError::NoSamples);
        }
        let samples_per_pass = compiled.samples_per_pass.max(1);
        let mut setup = Setup::default();

        let mut entities = Entities::build_with_store(
            program,
            desc,
            &compiled.linked,
            &EntityOptions {
                bvh: options.bvh,
                asset_roots: options.asset_roots.clone(),
                flatten: options.flatten,
                srgb_textures: match SrgbTextures::from_env() {
                    SrgbTextures::Encoded => SrgbTextures::Encoded,
                    SrgbTextures::Decoded => options.srgb_textures,
                },
            },
            &mut store,
        )?;
        let es = entities.stats();
        setup.load_ms = es.load_ms;
        setup.bvh_ms = es.blas_ms
            + if entities.needs_bounds() {
                0.0
            } else {
                es.tlas_ms
            };

        // Pipelines: the render kernel and, for custom geometry, the bounds kernel.
        let start = Instant::now();
        let exec = options.exec.unwrap_or(compiled.exec);
        let tables = UniformTables::choose(options.uniform_tables, gpu.description(), &entities);
        let SceneKernels {
            render,
            bounds,
            bindings: mut all,
            ..
        } = create_scene_kernels(gpu, compiled, exec, entities.needs_bounds(), tables)?;
        setup.kernels = render
            .iter()
            .chain(bounds.as_ref().map(|(k, _)| k))
            .map(Kernel::report)
            .collect();
        setup.pipeline_cache = Some(gpu.pipeline_cache_status());
        let kernels = match exec {
            ExecModel::Megakernel => {
                Kernels::Mega(render.into_iter().next().ok_or(RenderError::KernelSet)?)
            }
            ExecModel::Wavefront => Kernels::Wavefront {
                stages: render,
                max_rounds: max_rounds(compiled),
                one_step: one_step(compiled),
                shade_accumulates: compiled.shade_accumulates(),
            },
        };
        setup.pipeline_ms = ms_since(start);

        if let Some((_, declared)) = &bounds {
            all.extend(declared.iter().copied());
        }
        let mut tiles = options
            .tiles
            .unwrap_or_else(|| TileConfig::for_adapter(gpu.description()));
        let mut scene = match previous {
            Some((mut scene, old)) => {
                scene.rebind(&all, tables);
                entities.inherit_versions(old);
                scene
            }
            None => GpuScene::with_tables(gpu, &all, tables),
        };
        if let Kernels::Wavefront { .. } = kernels {
            // One tile's path records in one binding, within WebGPU's default 128 MiB.
            let max = gpu.limits().max_storage_buffer_binding_size.min(128 << 20);
            tiles = wavefront_tiles(tiles, [width, height], compiled.path_words, max);
            // The records, then the tail: the running count the rounds read, the listed stages'
            // dispatch, and the list of running slots (`wavefront::tail_bytes`).
            let slots = tiles.tile_width * tiles.tile_height;
            scene.set_path_bytes(
                u64::from(slots) * u64::from(compiled.path_words) * 4
                    + wavefront::tail_bytes(slots),
            );
        }
        if let Some(limits) = options.limits {
            scene = scene.with_limits(limits);
        }

        Ok(Staged {
            gpu,
            entities,
            scene,
            kernels,
            bounds: bounds.map(|(k, _)| k),
            tiles,
            size: [width, height],
            samples_per_pass,
            total_samples,
            setup,
            written_at_setup: Vec::new(),
            upload: (0.0, 0),
            options,
            store,
        })
    }

    /// The scene's entities (objects, meshes, parameters, BVHs).
    pub fn entities(&self) -> &Entities {
        &self.entities
    }

    /// The GPU buffers.
    pub fn gpu_scene(&self) -> &GpuScene {
        &self.scene
    }

    /// The image size.
    pub fn size(&self) -> [u32; 2] {
        self.size
    }

    /// Records the resolve of the running accumulation (the average as the last
    /// [`accumulate`](Self::accumulate) or [`render`](Self::render) left it; after a change,
    /// accumulate first) into `target`, a texture or buffer the caller owns: the
    /// PNG's sRGB bytes (tone-mapped with `tone`) or linear floats, by the target's format (see
    /// [`crate::resolve`]). With `encoder` the pass is recorded there and the caller submits it,
    /// ordered after this renderer's own submissions; without, it is submitted at once on the
    /// queue. Neither blocks nor reads back.
    pub fn resolve_into(
        &self,
        target: ResolveTarget<'_>,
        tone: &ToneMap,
        encoder: Option<&mut wgpu::CommandEncoder>,
    ) -> Result<(), RenderError> {
        let accum = self
            .accumulation_buffer()
            .ok_or(ResolveError::NoAccumulation)?;
        match encoder {
            Some(encoder) => {
                self.resolver
                    .encode(self.gpu, encoder, accum, self.size, target, tone)?;
            }
            None => {
                let device = self.gpu.device();
                let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
                    label: Some("rtc resolve"),
                });
                self.resolver
                    .encode(self.gpu, &mut encoder, accum, self.size, target, tone)?;
                let ((), error) = self.gpu.scoped(|| {
                    self.gpu.queue().submit([encoder.finish()]);
                });
                if let Some(message) = error {
                    return Err(ResolveError::Wgpu(message).into());
                }
            }
        }
        Ok(())
    }

    /// Moves object `object` (its new object-to-world matrix); the next pass rebuilds the
    /// scene-level BVH (never an object's) and uploads only the instance records and the
    /// scene-level BVH's nodes. Restarts the accumulation.
    pub fn set_transform(&mut self, object: usize, transform: Mat4) -> Result<(), RenderError> {
        self.entities.set_transform(object, transform)?;
        self.passes_done = 0;
        Ok(())
    }

    /// Whether a glTF model's node animation moves some object of the scene (the scene's own
    /// `animate` entries are in its description: [`crate::animation::is_animated`]).
    pub fn has_model_animation(&self) -> bool {
        self.entities.has_model_animation()
    }

    /// The length in seconds of the longest glTF node animation (0 without one, or when it has
    /// a single key).
    pub fn model_animation_length(&self) -> f32 {
        self.entities.model_animation_length()
    }

    /// Moves every object a glTF node animation moves to its pose at `t` seconds, with
    /// [`set_transform`](Self::set_transform) (the next pass rebuilds the scene-level BVH, never
    /// an object's). Does nothing, and keeps the accumulation, in a scene without one.
    pub fn set_model_time(&mut self, t: f32) -> Result<(), RenderError> {
        for (object, transform) in self.entities.model_transforms_at(t) {
            self.set_transform(object, transform)?;
        }
        Ok(())
    }

    /// Sets field `field` of `target`'s instance (the camera's `position`, a light's
    /// `intensity`, an object's material `color`) to `value`, which must have the field's type;
    /// the next pass uploads only the words that changed. An instance several targets shared is
    /// first given to `target` alone. Restarts the accumulation.
    pub fn set_field(
        &mut self,
        target: FieldTarget,
        field: &str,
        value: &ConstValue,
    ) -> Result<(), RenderError> {
        self.entities
            .set_field(&self.program, target, field, value)?;
        self.passes_done = 0;
        Ok(())
    }

    /// Replaces the camera's fields with those of `camera`, an instance of the same camera
    /// struct (every field but asset handles). Restarts the accumulation.
    pub fn set_camera(&mut self, camera: &Instance) -> Result<(), RenderError> {
        self.entities
            .set_instance(&self.program, FieldTarget::Camera, camera)?;
        self.passes_done = 0;
        Ok(())
    }

    /// Replaces the kernels with those of `compiled`, a recompile of the same scene (its program
    /// or scene file edited): entities are rebuilt from the new description, but every asset
    /// and object-level BVH whose file did not change comes from the store (no file is read, no
    /// BLAS built), and every GPU buffer whose contents did not change stays as it is. Camera,
    /// transforms and fields come from `compiled` (edits made with [`set_field`](Self::set_field)
    /// or [`set_transform`](Self::set_transform) are not carried over); the image size and
    /// the samples of a [`render`](Self::render) stay this renderer's. Restarts the
    /// accumulation. On an error this renderer keeps its kernels and entities, and re-uploads
    /// its buffers at the next pass.
    pub fn replace_kernel(&mut self, compiled: &CompiledScene) -> Result<(), RenderError> {
        let store = std::mem::take(&mut self.store);
        let empty = self.scene.emptied(self.gpu);
        let scene = std::mem::replace(&mut self.scene, empty);
        let mut options = self.options.clone();
        options.size = Some(self.size);
        let samples = self.total_samples;
        options.samples = Some(samples);
        let rebuilt = Self::build(
            self.gpu,
            compiled,
            options,
            store,
            Some((scene, &self.entities)),
        );
        match rebuilt {
            Ok(mut new) => {
                new.options = std::mem::take(&mut self.options);
                *self = new;
                Ok(())
            }
            Err(e) => {
                self.entities.force_full_upload();
                Err(e)
            }
        }
    }

    /// The index of the object called `name` (a scene `object NAME`, or a model node's
    /// `file.glb#nodes[i]`), for [`set_transform`](Self::set_transform) and
    /// [`FieldTarget::Material`].
    pub fn object_index(&self, name: &str) -> Option<usize> {
        self.entities
            .objects()
            .iter()
            .position(|o| o.name.as_deref() == Some(name))
    }

    /// The assets and object-level BVHs kept across kernel replacements, and its counters.
    pub fn store(&self) -> &AssetStore {
        &self.store
    }

    /// The accumulation buffer (`accum`: per pixel a `vec4<f32>` of rgb sums and the sample
    /// count in `a`, row-major, `width × height` entries), for a host that resolves it itself.
    pub fn accumulation_buffer(&self) -> Option<&wgpu::Buffer> {
        let b = abi::binding("accum")?;
        self.scene.buffers().buffer(b.binding)
    }

    /// Samples per pixel in the running accumulation.
    pub fn accumulated_samples(&self) -> u32 {
        self.passes_done.saturating_mul(self.samples_per_pass)
    }

    /// Samples per pixel a [`render`](Self::render) takes (the scene's, or the override).
    pub fn total_samples(&self) -> u32 {
        self.total_samples
    }

    /// Samples per pixel one pass adds.
    pub fn samples_per_pass(&self) -> u32 {
        self.samples_per_pass
    }

    /// Makes the next pass start a new accumulation.
    pub fn reset_accumulation(&mut self) {
        self.passes_done = 0;
    }

    /// Tiles times passes of the next render, for sizing a progress display: the total its
    /// `progress` counts to (a dispatch of several passes counts each of them).
    pub fn total_tiles(&self) -> u64 {
        self.tiles_per_pass() * u64::from(self.passes())
    }

    fn tiles_per_pass(&self) -> u64 {
        self.tiles_for(self.size)
    }

    fn tiles_for(&self, [width, height]: [u32; 2]) -> u64 {
        let cfg = self.dispatcher.config();
        plan_tiles(width, height, cfg.tile_width, cfg.tile_height, 0).len() as u64
    }

    fn passes(&self) -> u32 {
        self.total_samples.div_ceil(self.samples_per_pass)
    }

    /// Renders the image afresh: the scene's samples (or the override), in passes.
    /// `progress(done, total)` is called with tiles done over all passes.
    pub fn render(
        &mut self,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<RenderResult, RenderError> {
        self.passes_done = 0;
        let passes = self.passes();
        let per_dispatch = match self.kernels {
            Kernels::Mega(_) => passes_per_dispatch(passes, self.samples_per_pass),
            Kernels::Wavefront { .. } => 1,
        };
        let mut stats = self.run_passes(passes, per_dispatch, self.size, progress)?;
        let start = Instant::now();
        let image = self.image()?;
        stats.readback_ms += ms_since(start);
        Ok(RenderResult { image, stats })
    }

    /// The running accumulation's mean radiance per pixel (read back from the GPU).
    pub fn image(&self) -> Result<LinearImage, RenderError> {
        let [width, height] = self.size;
        let accum = self.scene.read_accumulation(self.gpu)?;
        Ok(LinearImage::from_accumulation(width, height, &accum)?)
    }

    /// [`image`](Self::image) without blocking, for the web (`wasm32`).
    #[cfg(target_arch = "wasm32")]
    pub async fn image_async(&self) -> Result<LinearImage, RenderError> {
        let [width, height] = self.size;
        let accum = self.scene.read_accumulation_async(self.gpu).await?;
        Ok(LinearImage::from_accumulation(width, height, &accum)?)
    }

    /// The kernel's counters (rays traced since the accumulation started, non-finite samples,
    /// dropped shadow queries) without blocking, for the web (`wasm32`), where
    /// [`accumulate`](Self::accumulate) reads none back and its stats count no traced rays.
    #[cfg(target_arch = "wasm32")]
    pub async fn counters_async(&self) -> Result<crate::scene::Counters, RenderError> {
        Ok(self.scene.read_counters_async(self.gpu).await?)
    }

    /// Adds `passes` passes (each [`samples_per_pass`](Self::samples_per_pass) samples per
    /// pixel) to the running accumulation, after uploading what changed (rebuilding the
    /// scene-level BVH first if an object moved); a change since the last pass (camera,
    /// transform, field, kernel) or [`reset_accumulation`](Self::reset_accumulation) starts it
    /// afresh. Pass `k` of an accumulation draws the random numbers of pass `k` of a
    /// [`render`](Self::render), so `accumulate(1)` four times gives the image of a 4-pass
    /// render. The figures are of these passes (and, on the first call, of the setup).
    pub fn accumulate(
        &mut self,
        passes: u32,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<RenderStats, RenderError> {
        self.run_passes(passes, 1, self.size, progress)
    }

    /// Renders one pass of the scene as it is now at `1 / factor` of the image's width and
    /// height (rounded up; `factor` clamped to 1 to 64) and returns that small image: a coarse
    /// preview for an interactive camera move, at about `1 / factor²` of a pass's cost, showing
    /// the same view (the camera program sees the small image size). The pass draws the random
    /// numbers of an accumulation's first pass and writes the start of the accumulation buffer,
    /// so it ends the running accumulation: the next [`accumulate`](Self::accumulate) starts
    /// afresh, and a [`resolve_into`](Self::resolve_into) before it resolves nothing meaningful.
    pub fn preview(&mut self, factor: u32) -> Result<RenderResult, RenderError> {
        let [width, height] = preview_size(self.size, factor);
        self.passes_done = 0;
        let result = self.run_passes(1, 1, [width, height], &mut |_, _| {});
        self.passes_done = 0;
        let mut stats = result?;
        stats.accumulated_samples = 0;
        let start = Instant::now();
        let count = u64::from(width) * u64::from(height);
        let accum = self.scene.read_accumulation_prefix(self.gpu, count)?;
        let image = LinearImage::from_accumulation(width, height, &accum)?;
        stats.readback_ms += ms_since(start);
        Ok(RenderResult { image, stats })
    }

    /// `passes` passes at `size` (the image's, or a preview's smaller one), after uploading what
    /// changed, `per_dispatch` of them a dispatch (the megakernel's; 1 unless it divides
    /// `passes`); the accumulation buffer stays sized for the whole image.
    fn run_passes(
        &mut self,
        passes: u32,
        per_dispatch: u32,
        size: [u32; 2],
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<RenderStats, RenderError> {
        let gpu = self.gpu;
        let setup = std::mem::take(&mut self.setup);
        let mut bvh_ms = setup.bvh_ms;
        if self.entities.refresh()? {
            bvh_ms += self.entities.stats().tlas_ms;
        }
        let image_pixels = u64::from(self.size[0]) * u64::from(self.size[1]);
        let [width, height] = size;
        let pixels = u64::from(width) * u64::from(height);
        // Every dispatch takes as many passes (`passes_per_dispatch` is one uniform).
        let per_dispatch = if per_dispatch > 0 && passes % per_dispatch == 0 {
            per_dispatch
        } else {
            1
        };
        let frame = FrameUniforms {
            path_slots: self.path_slots,
            passes_per_dispatch: per_dispatch,
            ..self
                .entities
                .frame_uniforms(self.samples_per_pass, self.total_samples)
        };
        let report: UploadReport =
            self.scene
                .upload(gpu, &mut self.entities, &frame, image_pixels)?;
        let mut written = std::mem::take(&mut self.written_at_setup);
        for name in report.written() {
            if !written.contains(&name) {
                written.push(name);
            }
        }
        let (setup_upload_ms, setup_bytes) = setup.upload.unwrap_or_default();
        if self.passes_done == 0 {
            self.scene.clear_accumulation(gpu)?;
        } else {
            self.scene.clear_counters(gpu)?;
        }

        let per_pass = self.tiles_for(size);
        let total = per_pass * u64::from(passes);
        let dispatches = passes / per_dispatch;
        let mut render_ms = 0.0;
        let mut flush_ms = 0.0;
        let mut tiles = 0u64;
        let mut rays_traced = 0u64;
        let mut last_rays = 0u32;
        let mut rounds = 0u64;
        let mut listed_slots = 0u64;
        let mut slot_rounds = 0u64;
        let mut stage_ms: Vec<(String, f64)> = Vec::new();
        for i in 0..dispatches {
            let first = i * per_dispatch;
            let pass = self.passes_done.saturating_add(first);
            let base = u64::from(first) * per_pass;
            let mut report =
                |done: u32, _| progress(base + u64::from(done) * u64::from(per_dispatch), total);
            let d = match &self.kernels {
                Kernels::Mega(kernel) => self.dispatcher.dispatch(
                    gpu,
                    kernel,
                    self.scene.buffers(),
                    size,
                    pass,
                    &mut report,
                )?,
                Kernels::Wavefront {
                    stages,
                    max_rounds,
                    one_step,
                    shade_accumulates,
                } => {
                    let kernels = Kernels::rounds(
                        stages,
                        *max_rounds,
                        self.path_flag_offset,
                        self.options.stage_times,
                        *one_step && self.samples_per_pass <= 1,
                        *shade_accumulates,
                    )
                    .ok_or(RenderError::NoStageKernels)?;
                    let r = self.dispatcher.dispatch_rounds(
                        gpu,
                        &kernels,
                        self.scene.buffers(),
                        size,
                        pass,
                        &mut report,
                    )?;
                    rounds += r.rounds;
                    listed_slots += r.running;
                    slot_rounds += r.tile_slots;
                    for (label, ms) in &r.stage_ms {
                        crate::gpu::add_stage_ms(&mut stage_ms, label, *ms);
                    }
                    r.dispatch
                }
            };
            render_ms += d.dispatch_ms;
            flush_ms += d.flush_ms;
            tiles += u64::from(d.tiles);
            // On the web the counters are read only by `counters_async` (nothing may block).
            if dispatches > 1 && cfg!(not(target_arch = "wasm32")) {
                let rays = self.scene.read_counters(gpu)?.rays;
                rays_traced += u64::from(rays.wrapping_sub(last_rays));
                last_rays = rays;
            }
        }
        self.passes_done = self.passes_done.saturating_add(passes);

        let start = Instant::now();
        #[cfg(not(target_arch = "wasm32"))]
        let counters = self.scene.read_counters(gpu)?;
        #[cfg(target_arch = "wasm32")]
        let counters = crate::scene::Counters::default();
        rays_traced += u64::from(counters.rays.wrapping_sub(last_rays));
        let readback_ms = ms_since(start);
        let messages = gpu.take_uncaptured_errors();
        if !messages.is_empty() {
            return Err(RenderError::Wgpu { messages });
        }

        let es = self.entities.stats();
        let mut warnings: Vec<String> = self
            .entities
            .warnings()
            .iter()
            .cloned()
            .chain(gpu.take_warnings())
            .collect();
        if counters.shadow_overflow > 0 {
            let limit = match self.kernels {
                Kernels::Mega(_) => format!(
                    "a light program's sample records at most {} (`LIGHT_QUERIES`)",
                    rtc_compiler::kernel::intrinsics::LIGHT_QUERIES
                ),
                Kernels::Wavefront { .. } => format!(
                    "a shading step of the wavefront model records at most {} (render with the megakernel for this scene)",
                    rtc_compiler::kernel::wavefront::SHADOW_QUERIES
                ),
            };
            warnings.push(format!(
                "{} shadow queries were answered \"unoccluded\" without tracing: {limit}",
                counters.shadow_overflow
            ));
        }
        let samples = passes.saturating_mul(self.samples_per_pass);
        let primary_rays = pixels * u64::from(samples);
        let objects = self.entities.objects().len() as u32;
        let store = self.store.counters();
        Ok(RenderStats {
            adapter: gpu.description().to_string(),
            width,
            height,
            samples_per_pass: self.samples_per_pass,
            samples,
            passes,
            passes_per_dispatch: per_dispatch,
            tiles,
            bvh_build_ms: bvh_ms,
            load_ms: setup.load_ms,
            bounds_ms: setup.bounds_ms,
            pipeline_ms: setup.pipeline_ms,
            kernels: setup.kernels,
            pipeline_cache: setup.pipeline_cache,
            upload_ms: setup_upload_ms + report.stats.upload_ms + flush_ms,
            bytes_uploaded: setup_bytes + report.stats.bytes_uploaded,
            buffers_written: written,
            render_ms,
            readback_ms,
            primary_rays,
            rays_per_second: if render_ms > 0.0 {
                primary_rays as f64 / (render_ms / 1e3)
            } else {
                0.0
            },
            rays_traced,
            traced_rays_per_second: if render_ms > 0.0 {
                rays_traced as f64 / (render_ms / 1e3)
            } else {
                0.0
            },
            nonfinite_samples: counters.nonfinite,
            triangles: es.triangles,
            instanced_triangles: es.instanced_triangles,
            meshes: self.entities.meshes().len() as u32,
            objects,
            instances: self.entities.instances().len() as u32,
            uniform_tables: self.scene.tables().names(),
            lights: self.entities.lights().len() as u32,
            blas_builds: store.blas_builds,
            flattened: (es.flattened_objects, es.flat_bvhs),
            decoded_textures: es.decoded_textures,
            tlas_builds: es.tlas_builds,
            files_read: store.meshes_read + store.images_read + store.models_read,
            accumulated_samples: self.accumulated_samples(),
            warnings,
            exec: match self.kernels {
                Kernels::Mega(_) => ExecModel::Megakernel,
                Kernels::Wavefront { .. } => ExecModel::Wavefront,
            },
            rounds,
            listed_slots,
            slot_rounds,
            stage_ms,
        })
    }
}

impl Renderer<'_> {
    /// Runs one pass of a **debug kernel** (compiled with `rtc_compiler::kernel::compile_scene_with`
    /// and `KernelOptions { debug: Some(mode) }`) and returns its raw per-pixel values, row-major
    /// (`y * width + x`), `width × height` of them. What the four channels hold is the
    /// `DebugMode`'s (nodes visited, primitives tested, hit `t` or -1, hit object or -1; or the
    /// camera ray's origin and `tmin`; or its direction and `tmax`). The values are not divided by
    /// a sample count: one pass writes each pixel once, into a zeroed buffer.
    ///
    /// With a normal kernel this returns the first pass's raw accumulation (`rgb` sums, `a` = the
    /// samples of one pass).
    pub fn render_debug(&mut self) -> Result<Vec<[f32; 4]>, RenderError> {
        let gpu = self.gpu;
        self.entities.refresh()?;
        let [width, height] = self.size;
        let pixels = u64::from(width) * u64::from(height);
        let frame = self
            .entities
            .frame_uniforms(self.samples_per_pass, self.total_samples);
        self.scene.upload(gpu, &mut self.entities, &frame, pixels)?;
        self.scene.clear_accumulation(gpu)?;
        let Kernels::Mega(kernel) = &self.kernels else {
            return Err(RenderError::DebugNeedsMegakernel);
        };
        self.dispatcher.dispatch(
            gpu,
            kernel,
            self.scene.buffers(),
            self.size,
            0,
            &mut |_, _| {},
        )?;
        let mut accum = self.scene.read_accumulation(gpu)?;
        let messages = gpu.take_uncaptured_errors();
        if !messages.is_empty() {
            return Err(RenderError::Wgpu { messages });
        }
        accum.truncate(usize::try_from(pixels).unwrap_or(usize::MAX));
        Ok(accum)
    }
}

/// A renderer's setup between [`Renderer::begin`] and [`Staged::finish`]: what is built so far,
/// and the bounds kernel when the scene has custom geometry (whose boxes are read back between
/// [`Staged::dispatch_bounds`] and [`Staged::take_bounds`], blocking or awaited).
struct Staged<'g> {
    gpu: &'g Gpu,
    entities: Entities,
    scene: GpuScene,
    kernels: Kernels,
    bounds: Option<Kernel>,
    tiles: TileConfig,
    size: [u32; 2],
    samples_per_pass: u32,
    total_samples: u32,
    setup: Setup,
    written_at_setup: Vec<&'static str>,
    /// Milliseconds and bytes uploaded for the bounds kernel.
    upload: (f64, u64),
    options: RenderOptions,
    store: AssetStore,
}

impl<'g> Staged<'g> {
    /// Uploads what the bounds kernel reads and dispatches it over every object (the scene with
    /// custom geometry only; `None` otherwise). Its boxes are then in the accumulation buffer.
    fn dispatch_bounds(&mut self) -> Result<Option<(Instant, UploadReport)>, RenderError> {
        let Some(kernel) = &self.bounds else {
            return Ok(None);
        };
        let start = Instant::now();
        let report = dispatch_bounds(
            self.gpu,
            &mut self.entities,
            &mut self.scene,
            kernel,
            self.samples_per_pass,
            self.total_samples,
        )?;
        Ok(Some((start, report)))
    }

    /// Gives the boxes read back after [`dispatch_bounds`](Self::dispatch_bounds) to the
    /// custom-geometry objects and builds the TLAS.
    fn take_bounds(
        &mut self,
        (start, report): (Instant, UploadReport),
        boxes: &[[f32; 4]],
    ) -> Result<(), RenderError> {
        apply_bounds(&mut self.entities, boxes)?;
        self.setup.bounds_ms = ms_since(start) - report.stats.upload_ms;
        self.setup.bvh_ms += self.entities.stats().tlas_ms;
        self.upload = (report.stats.upload_ms, report.stats.bytes_uploaded);
        self.written_at_setup = report.written();
        Ok(())
    }

    /// The rest of the setup (frame uniforms, the upload of everything) and the renderer.
    fn finish(self, compiled: &CompiledScene) -> Result<Renderer<'g>, RenderError> {
        let Staged {
            gpu,
            mut entities,
            mut scene,
            kernels,
            tiles,
            size: [width, height],
            samples_per_pass,
            total_samples,
            mut setup,
            mut written_at_setup,
            upload,
            options,
            store,
            ..
        } = self;
        let program = compiled
            .checked
            .program
            .as_ref()
            .ok_or(SceneError::NoProgram)?;
        let path_slots = match kernels {
            Kernels::Wavefront { .. } => tiles.tile_width * tiles.tile_height,
            Kernels::Mega(_) => 0,
        };
        let path_flag_offset = u64::from(path_slots) * u64::from(compiled.path_words) * 4;
        let frame = FrameUniforms {
            path_slots,
            ..entities.frame_uniforms(samples_per_pass, total_samples)
        };
        let report = scene.upload(
            gpu,
            &mut entities,
            &frame,
            u64::from(width) * u64::from(height),
        )?;
        setup.upload = Some((
            upload.0 + report.stats.upload_ms,
            upload.1 + report.stats.bytes_uploaded,
        ));
        for name in report.written() {
            if !written_at_setup.contains(&name) {
                written_at_setup.push(name);
            }
        }

        let dispatcher = TileDispatcher::new(tiles);
        Ok(Renderer {
            gpu,
            entities,
            scene,
            kernels,
            path_slots,
            path_flag_offset,
            dispatcher,
            size: [width, height],
            samples_per_pass,
            total_samples,
            setup,
            written_at_setup,
            resolver: Resolver::new(),
            program: layout_program(program),
            options,
            store,
            passes_done: 0,
        })
    }
}

/// Uploads what the bounds kernel reads and runs it over every object; the boxes (two `vec4f`
/// per object: low, high corner) are then in the accumulation buffer, for [`apply_bounds`].
/// Returns what the upload did.
fn dispatch_bounds(
    gpu: &Gpu,
    entities: &mut Entities,
    scene: &mut GpuScene,
    kernel: &Kernel,
    samples_per_pass: u32,
    total_samples: u32,
) -> Result<UploadReport, RenderError> {
    let objects = entities.objects().len();
    let mut frame = entities.frame_uniforms(samples_per_pass, total_samples);
    frame.instance_count = u32::try_from(objects).map_err(|_| SceneError::TooLarge {
        what: "objects",
        count: objects as u64,
    })?;
    frame.tlas_root = 0;
    let report = scene.upload_for_bounds(gpu, entities, &frame)?;
    scene.clear_accumulation(gpu)?;
    let groups = frame.instance_count.div_ceil(BOUNDS_WORKGROUP).max(1);
    dispatch_once(gpu, kernel, scene.buffers(), [groups, 1, 1])?;
    Ok(report)
}

/// Gives the custom-geometry objects their boxes (as [`dispatch_bounds`] left them) and builds
/// the TLAS.
fn apply_bounds(entities: &mut Entities, boxes: &[[f32; 4]]) -> Result<(), RenderError> {
    let custom: Vec<usize> = entities
        .objects()
        .iter()
        .enumerate()
        .filter(|(_, o)| matches!(o.geometry, ObjectGeometry::Custom { .. }))
        .map(|(i, _)| i)
        .collect();
    for i in custom {
        let bounds = match (boxes.get(2 * i), boxes.get(2 * i + 1)) {
            (Some(lo), Some(hi)) => Some(Aabb::new(
                glam::Vec3::new(lo[0], lo[1], lo[2]),
                glam::Vec3::new(hi[0], hi[1], hi[2]),
            )),
            _ => None,
        };
        entities.set_custom_bounds(i, bounds)?;
    }
    entities.rebuild_tlas()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{passes_per_dispatch, MAX_SAMPLES_PER_DISPATCH};

    #[test]
    fn a_dispatch_takes_the_most_passes_that_divide_the_render_within_the_sample_bound() {
        // (passes, samples a pass) -> passes a dispatch
        for (passes, samples, want) in [
            (64, 1, 16),
            (64, 4, 4),
            (24, 1, 12),
            (6, 1, 6),
            (7, 1, 7),
            (17, 1, 1),
            (34, 1, 2),
            (1, 1, 1),
            (4, 16, 1),
            (4, 32, 1),
            (0, 1, 1),
            (8, 0, 8),
        ] {
            let k = passes_per_dispatch(passes, samples);
            assert_eq!(k, want, "{passes} passes of {samples}");
            assert!(k >= 1 && (passes == 0 || passes % k == 0));
            assert!(k == 1 || k * samples.max(1) <= MAX_SAMPLES_PER_DISPATCH);
        }
    }
}
