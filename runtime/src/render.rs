//! Rendering a compiled scene: from `rtc_compiler::kernel::CompiledScene` to a [`LinearImage`].
//!
//! [`Renderer::new`] does the one-time work, in order:
//! 1. the scene entities ([`Entities::build`]: assets, one BVH per mesh, `params`);
//! 2. the render kernel's pipeline (from the compiled `naga::Module`, with exactly the bindings the
//!    compiler lists and the tile uniform at the `tile` binding), created with the bounds kernel
//!    of step 3 as one set by [`create_scene_kernels`] (memory and disk caches, parallel compile,
//!    per-kernel accounting in [`RenderStats::kernels`]). Each new pipeline's warm-up dispatch,
//!    where lavapipe compiles it (seconds for the full kernel), runs there, so the compile belongs
//!    to the setup, not to the render time;
//! 3. for scenes with custom geometry, the bounds kernel: instances uploaded in object order, one
//!    invocation per object, boxes read back from `accum` and handed to the entities, which then
//!    build the scene-level BVH;
//! 4. the first upload of every buffer ([`GpuScene::upload`]), so data above a device limit fails
//!    here with the buffer set's typed error naming the binding.
//!
//! [`Renderer::render`] then renders the whole image: it rebuilds the scene-level BVH if an object
//! moved ([`Renderer::set_transform`]), uploads what changed, zeroes the accumulation buffer and the
//! counters, runs `ceil(total_samples / samples_per_pass)` passes (each a tiled dispatch with
//! `TileParams.frame` = the pass index), reports progress over all tiles of all passes, reads the
//! accumulation back and averages it (rgb / a).
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

use std::time::Instant;

use glam::Mat4;
use rtc_bvh::Aabb;
/// The BVH builder presets ([`RenderOptions::bvh`]), re-exported for callers without `rtc-bvh`.
pub use rtc_bvh::BuildPreset;
use rtc_compiler::abi;
use rtc_compiler::kernel::{CompiledScene, BOUNDS_ENTRY, BOUNDS_WORKGROUP, RENDER_ENTRY};

use crate::assets::AssetRoots;
use crate::gpu::{
    dispatch_once, plan_tiles, BufferLimits, DispatchError, Gpu, Kernel, KernelDesc, KernelReport,
    KernelSource, PipelineCacheStatus, PipelineError, TileConfig, TileDispatcher,
};
use crate::image_out::{ImageError, LinearImage};
use crate::scene::{Entities, EntityOptions, GpuScene, ObjectGeometry, SceneError, UploadReport};

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
    /// Tiles dispatched, over all passes.
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
    /// Lights.
    pub lights: u32,
    /// BLAS builds so far.
    pub blas_builds: u32,
    /// TLAS builds so far.
    pub tlas_builds: u32,
    /// Problems that did not stop the render.
    pub warnings: Vec<String>,
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
    kernel: Kernel,
    dispatcher: TileDispatcher,
    size: [u32; 2],
    samples_per_pass: u32,
    total_samples: u32,
    setup: Setup,
    written_at_setup: Vec<&'static str>,
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

/// The kernels of a compiled scene, as [`create_scene_kernels`] made them.
#[derive(Debug)]
pub struct SceneKernels {
    /// The render kernel.
    pub render: Kernel,
    /// The bounds kernel and the ABI bindings it declares, when it was asked for.
    pub bounds: Option<(Kernel, Vec<&'static abi::BindingDesc>)>,
}

/// Creates the kernels of `compiled` as one set with [`Gpu::create_kernels`] (memory and disk
/// caches, parallel compile, warm-up, per-kernel accounting in [`Kernel::report`]): the render
/// kernel, and the bounds kernel when `with_bounds` (a scene with custom geometry). Used by
/// [`Renderer::new`] and by `rtc compile --timings driver`.
pub fn create_scene_kernels(
    gpu: &Gpu,
    compiled: &CompiledScene,
    with_bounds: bool,
) -> Result<SceneKernels, RenderError> {
    let tile = abi::binding("tile").ok_or(RenderError::NoTileBinding)?;
    if !compiled.bindings.iter().any(|b| b.binding == tile.binding) {
        return Err(RenderError::NoTileBinding);
    }
    let render_bindings = GpuScene::runtime_bindings(&compiled.bindings);
    let bounds_module = match (&compiled.bounds, with_bounds) {
        (Some(module), true) => {
            let declared = declared_bindings(module, "bounds")?;
            let bindings = GpuScene::runtime_bindings(&declared);
            Some((module, declared, bindings))
        }
        (None, true) => return Err(RenderError::NoBoundsKernel),
        (_, false) => None,
    };
    let mut descs = vec![KernelDesc {
        label: "rtc render",
        source: KernelSource::Naga(Box::new(compiled.render.clone())),
        entry_point: RENDER_ENTRY,
        bindings: &render_bindings,
        tile_binding: Some(tile.binding),
    }];
    if let Some((module, _, bindings)) = &bounds_module {
        descs.push(KernelDesc {
            label: "rtc bounds",
            source: KernelSource::Naga(Box::new((*module).clone())),
            entry_point: BOUNDS_ENTRY,
            bindings,
            tile_binding: None,
        });
    }
    let mut kernels = gpu.create_kernels(descs).into_iter();
    let render = kernels.next().ok_or(RenderError::KernelSet)??;
    let bounds = match bounds_module {
        Some((_, declared, _)) => Some((kernels.next().ok_or(RenderError::KernelSet)??, declared)),
        None => None,
    };
    Ok(SceneKernels { render, bounds })
}

impl<'g> Renderer<'g> {
    /// Prepares `compiled` for rendering on `gpu` (see the module docs for the steps).
    pub fn new(
        gpu: &'g Gpu,
        compiled: &CompiledScene,
        options: RenderOptions,
    ) -> Result<Self, RenderError> {
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

        let mut entities = Entities::build(
            program,
            desc,
            &compiled.linked,
            &EntityOptions {
                bvh: options.bvh,
                asset_roots: options.asset_roots.clone(),
            },
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
        let SceneKernels {
            render: kernel,
            bounds,
        } = create_scene_kernels(gpu, compiled, entities.needs_bounds())?;
        setup.kernels = std::iter::once(&kernel)
            .chain(bounds.as_ref().map(|(k, _)| k))
            .map(Kernel::report)
            .collect();
        setup.pipeline_cache = Some(gpu.pipeline_cache_status());
        setup.pipeline_ms = ms_since(start);

        let mut all: Vec<&'static abi::BindingDesc> = compiled.bindings.clone();
        if let Some((_, declared)) = &bounds {
            all.extend(declared.iter().copied());
        }
        let mut scene = GpuScene::new(gpu, &all);
        if let Some(limits) = options.limits {
            scene = scene.with_limits(limits);
        }

        let mut written_at_setup = Vec::new();
        let mut upload = (0.0, 0);
        if let Some((bounds_kernel, _)) = &bounds {
            let start = Instant::now();
            let report = run_bounds(
                gpu,
                &mut entities,
                &mut scene,
                bounds_kernel,
                samples_per_pass,
                total_samples,
            )?;
            setup.bounds_ms = ms_since(start) - report.stats.upload_ms;
            setup.bvh_ms += entities.stats().tlas_ms;
            upload = (report.stats.upload_ms, report.stats.bytes_uploaded);
            written_at_setup = report.written();
        }

        let frame = entities.frame_uniforms(samples_per_pass, total_samples);
        let report = scene.upload(gpu, &entities, &frame, u64::from(width) * u64::from(height))?;
        setup.upload = Some((
            upload.0 + report.stats.upload_ms,
            upload.1 + report.stats.bytes_uploaded,
        ));
        for name in report.written() {
            if !written_at_setup.contains(&name) {
                written_at_setup.push(name);
            }
        }

        let tiles = options
            .tiles
            .unwrap_or_else(|| TileConfig::for_adapter(gpu.description()));
        let dispatcher = TileDispatcher::new(tiles);
        Ok(Self {
            gpu,
            entities,
            scene,
            kernel,
            dispatcher,
            size: [width, height],
            samples_per_pass,
            total_samples,
            setup,
            written_at_setup,
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

    /// Moves object `object` (its new object-to-world matrix); the next render rebuilds the
    /// scene-level BVH and uploads only `nodes` and `instances`.
    pub fn set_transform(&mut self, object: usize, transform: Mat4) -> Result<(), RenderError> {
        Ok(self.entities.set_transform(object, transform)?)
    }

    /// Total tiles the next render dispatches (all passes), for sizing a progress display.
    pub fn total_tiles(&self) -> u64 {
        let cfg = self.dispatcher.config();
        let tiles = plan_tiles(
            self.size[0],
            self.size[1],
            cfg.tile_width,
            cfg.tile_height,
            0,
        )
        .len();
        tiles as u64 * u64::from(self.passes())
    }

    fn passes(&self) -> u32 {
        self.total_samples.div_ceil(self.samples_per_pass)
    }

    /// Renders the image. `progress(done, total)` is called with tiles done over all passes.
    pub fn render(
        &mut self,
        progress: &mut dyn FnMut(u64, u64),
    ) -> Result<RenderResult, RenderError> {
        let gpu = self.gpu;
        let setup = std::mem::take(&mut self.setup);
        let mut bvh_ms = setup.bvh_ms;
        if self.entities.refresh()? {
            bvh_ms += self.entities.stats().tlas_ms;
        }
        let [width, height] = self.size;
        let pixels = u64::from(width) * u64::from(height);
        let frame = self
            .entities
            .frame_uniforms(self.samples_per_pass, self.total_samples);
        let report: UploadReport = self.scene.upload(gpu, &self.entities, &frame, pixels)?;
        let mut written = std::mem::take(&mut self.written_at_setup);
        for name in report.written() {
            if !written.contains(&name) {
                written.push(name);
            }
        }
        let (setup_upload_ms, setup_bytes) = setup.upload.unwrap_or_default();
        self.scene.clear_accumulation(gpu)?;

        let passes = self.passes();
        let total = self.total_tiles();
        let per_pass = total / u64::from(passes.max(1));
        let mut render_ms = 0.0;
        let mut flush_ms = 0.0;
        let mut tiles = 0u64;
        let mut rays_traced = 0u64;
        let mut last_rays = 0u32;
        for pass in 0..passes {
            let base = u64::from(pass) * per_pass;
            let d = self.dispatcher.dispatch(
                gpu,
                &self.kernel,
                self.scene.buffers(),
                self.size,
                pass,
                &mut |done, _| progress(base + u64::from(done), total),
            )?;
            render_ms += d.dispatch_ms;
            flush_ms += d.flush_ms;
            tiles += u64::from(d.tiles);
            if passes > 1 {
                let rays = self.scene.read_counters(gpu)?.rays;
                rays_traced += u64::from(rays.wrapping_sub(last_rays));
                last_rays = rays;
            }
        }

        let start = Instant::now();
        let accum = self.scene.read_accumulation(gpu)?;
        let counters = self.scene.read_counters(gpu)?;
        rays_traced += u64::from(counters.rays.wrapping_sub(last_rays));
        let image = LinearImage::from_accumulation(width, height, &accum)?;
        let readback_ms = ms_since(start);
        let messages = gpu.take_uncaptured_errors();
        if !messages.is_empty() {
            return Err(RenderError::Wgpu { messages });
        }

        let es = self.entities.stats();
        let samples = passes.saturating_mul(self.samples_per_pass);
        let primary_rays = pixels * u64::from(samples);
        let objects = self.entities.objects().len() as u32;
        let stats = RenderStats {
            adapter: gpu.description().to_string(),
            width,
            height,
            samples_per_pass: self.samples_per_pass,
            samples,
            passes,
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
            lights: self.entities.lights().len() as u32,
            blas_builds: es.blas_builds,
            tlas_builds: es.tlas_builds,
            warnings: self
                .entities
                .warnings()
                .iter()
                .cloned()
                .chain(gpu.take_warnings())
                .collect(),
        };
        Ok(RenderResult { image, stats })
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
        self.scene.upload(gpu, &self.entities, &frame, pixels)?;
        self.scene.clear_accumulation(gpu)?;
        self.dispatcher.dispatch(
            gpu,
            &self.kernel,
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

/// Runs the bounds kernel over every object and gives the custom-geometry boxes to the entities,
/// then builds the TLAS. Returns what the upload for it did.
fn run_bounds(
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
    let boxes = scene.read_accumulation(gpu)?;
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
    Ok(report)
}
