//! The language-independent GPU core of the runtime: one [`Gpu`] context (instance, adapter,
//! device, queue), compute [`Kernel`]s with explicit bind group layouts, created one at a time or
//! as a set ([`Gpu::create_kernels`]: memory cache, parallel creation, warm-up, accounting, the
//! on-disk pipeline cache of `pipeline_cache.rs`), a persistent [`BufferSet`] keyed by binding,
//! and tiled dispatch with read-back ([`TileDispatcher`]).
//!
//! The layer knows nothing of the rtc language: a kernel is a compute entry point plus a list of
//! [`BindingDesc`]s in bind group 0, exactly what the compiler's manifest describes.
//!
//! A `Gpu` either owns its device ([`Gpu::new`]) or runs on a host application's adapter, device
//! and queue ([`Gpu::from_device`], checked against [`required_limits`] by `host.rs`).
//!
//! Invariants:
//! - Every wgpu call that can raise a validation, out-of-memory or internal error runs inside
//!   error scopes ([`Gpu::scoped`]), so wgpu's default uncaptured-error handler (which panics) is
//!   never reached by our own calls. A last-resort handler is installed anyway on a device we
//!   create; it records the message instead of panicking ([`Gpu::take_uncaptured_errors`]). On a
//!   host's device the host's handler stays (wgpu cannot chain handlers; see
//!   [`Gpu::from_device`]).
//! - A device we create has the adapter's own limits (not wgpu's small defaults), so big
//!   scenes fit; [`GpuLimits`] records the ones the runtime checks against.
//! - Nothing here exits the process or panics on a run-time failure; errors are typed.

mod adapter;
mod buffers;
mod cpu;
mod dispatch;
mod host;
mod kernels;
mod pipeline;
mod pipeline_cache;
#[cfg(target_arch = "wasm32")]
mod web;

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use web_time::Instant;

#[cfg(not(target_arch = "wasm32"))]
pub use adapter::list_adapters;
pub use adapter::{AdapterChoice, AdapterChoiceParseError, AdapterDescription};
pub use buffers::{BufferError, BufferLimits, BufferSet, UploadOutcome, UploadStats};
#[cfg(not(target_arch = "wasm32"))]
pub use cpu::apply_lavapipe_defaults;
pub use cpu::{
    lavapipe_defaults_applied, lavapipe_loads_per_lane, width_cache_dir, CpuJit, HostCpu,
    CACHE_DIR_VAR, JIT_VAR, NARROW_BEFORE_MESA, NARROW_WIDTH, QUICK_JIT, QUICK_JIT_MAX_SAMPLES,
    QUICK_JIT_MAX_SAMPLES_PRIMARY, QUICK_JIT_MAX_SAMPLES_SECONDARY, VECTOR_WIDTH_VAR,
    WAVEFRONT_PREVIEW_MAX_SAMPLES, WAVEFRONT_PREVIEW_MIN_WEIGHT_WITH_TABLES, WIDEST_MIN_SAMPLES,
    WIDEST_WIDTH, WIDE_MIN_SAMPLES,
};
pub(crate) use dispatch::add_stage_ms;
pub use dispatch::{
    dispatch_once, plan_tiles, read_buffer, read_vec4_f32, read_vec4_f32_prefix, DispatchError,
    DispatchReport, RoundDispatch, RoundKernels, RoundsReport, TileConfig, TileDispatcher,
    TileList, TileParams, TILE_PARAMS_WGSL,
};
#[cfg(target_arch = "wasm32")]
pub use dispatch::{read_buffer_async, read_vec4_f32_async};
pub use host::{
    missing_capabilities, required_limits, FromDeviceError, MissingCapability,
    KERNEL_STORAGE_BUFFERS,
};
pub use kernels::{pipelines_created, KernelOrigin, KernelReport};
pub use pipeline::{
    create_kernel, BindingDesc, BindingKind, Kernel, KernelDesc, KernelSource, PipelineError,
    PipelineTimings,
};
pub use pipeline_cache::{PipelineCacheConfig, PipelineCacheStatus, PIPELINE_CACHE_ENV};

/// Why no GPU context could be created.
#[derive(Debug, thiserror::Error)]
pub enum AdapterError {
    /// wgpu found no adapter at all on the enabled backends.
    #[error(
        "no GPU adapter found (backends tried: {backends}). To run on the CPU, install Mesa's \
         software Vulkan driver (lavapipe): `apt-get install -y mesa-vulkan-drivers libvulkan1` \
         on Debian/Ubuntu; for the OpenGL fallback also `libegl1 libegl-mesa0 libgl1-mesa-dri`. \
         `WGPU_BACKEND` (vulkan, gl, metal, dx12) restricts the backends tried"
    )]
    NoAdapter {
        /// The backends the instance was allowed to use, as wgpu names them.
        backends: String,
    },
    /// Adapters exist, but none matches the explicit choice.
    #[error("no adapter matches {choice}; available: {}", available.join("; "))]
    NoMatch {
        /// The choice, rendered for humans.
        choice: String,
        /// One line per adapter that was found.
        available: Vec<String>,
    },
    /// The chosen adapter refused to create a device.
    #[error("adapter `{adapter}` could not create a device: {source}")]
    RequestDevice {
        /// The adapter's name.
        adapter: String,
        /// wgpu's reason.
        source: wgpu::RequestDeviceError,
    },
}

/// The device limits the runtime checks against (copied from the device at creation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GpuLimits {
    /// Largest size in bytes of one storage buffer binding.
    pub max_storage_buffer_binding_size: u64,
    /// Largest size in bytes of one uniform buffer binding.
    pub max_uniform_buffer_binding_size: u64,
    /// Largest size in bytes of any buffer.
    pub max_buffer_size: u64,
    /// How many storage buffers one compute shader may bind.
    pub max_storage_buffers_per_shader_stage: u32,
    /// Required alignment of dynamic uniform offsets.
    pub min_uniform_buffer_offset_alignment: u32,
    /// Largest workgroup count in one dimension of a dispatch.
    pub max_compute_workgroups_per_dimension: u32,
    /// Largest product of a workgroup's three sizes.
    pub max_compute_invocations_per_workgroup: u32,
}

impl GpuLimits {
    fn from_wgpu(limits: &wgpu::Limits) -> Self {
        Self {
            max_storage_buffer_binding_size: limits.max_storage_buffer_binding_size,
            max_uniform_buffer_binding_size: limits.max_uniform_buffer_binding_size,
            max_buffer_size: limits.max_buffer_size,
            max_storage_buffers_per_shader_stage: limits.max_storage_buffers_per_shader_stage,
            min_uniform_buffer_offset_alignment: limits.min_uniform_buffer_offset_alignment,
            max_compute_workgroups_per_dimension: limits.max_compute_workgroups_per_dimension,
            max_compute_invocations_per_workgroup: limits.max_compute_invocations_per_workgroup,
        }
    }
}

/// Wall-clock milliseconds spent creating the context.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct InitTimings {
    /// `Instance::new`.
    pub instance_ms: f64,
    /// Enumerating adapters and choosing one.
    pub adapter_ms: f64,
    /// `request_device`.
    pub device_ms: f64,
}

impl InitTimings {
    /// Sum of all phases.
    pub fn total_ms(&self) -> f64 {
        self.instance_ms + self.adapter_ms + self.device_ms
    }
}

/// One GPU context: the chosen adapter, its device and queue, and what we learnt about them.
#[derive(Debug)]
pub struct Gpu {
    adapter: wgpu::Adapter,
    device: wgpu::Device,
    queue: wgpu::Queue,
    description: AdapterDescription,
    limits: GpuLimits,
    init_timings: InitTimings,
    uncaptured: Arc<Mutex<Vec<String>>>,
    /// Recently created kernels by [`pipeline`]'s key, most recent last (at most [`KERNEL_CACHE`]).
    kernels: Mutex<Vec<(u64, Kernel)>>,
    /// Pipelines this context created.
    pipelines_created: AtomicU64,
    /// The on-disk pipeline cache, where enabled and supported.
    disk_cache: Option<pipeline_cache::DiskCache>,
    pipeline_cache_status: PipelineCacheStatus,
    /// Problems that did not stop anything (an ignored cache file), until taken.
    warnings: Mutex<Vec<String>>,
}

/// How many kernels a [`Gpu`] keeps for reuse (a wavefront scene has a dozen stage kernels).
const KERNEL_CACHE: usize = 32;

/// How to set up a [`Gpu`] besides the adapter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GpuOptions {
    /// The on-disk pipeline cache.
    pub pipeline_cache: PipelineCacheConfig,
}

impl GpuOptions {
    /// The options the environment asks for ([`PipelineCacheConfig::from_env`]).
    pub fn from_env() -> Self {
        Self {
            pipeline_cache: PipelineCacheConfig::from_env(),
        }
    }
}

impl Gpu {
    /// Chooses an adapter (see [`AdapterChoice`] for the rules) and creates a device with the
    /// adapter's own limits; the pipeline cache is configured from the environment
    /// ([`GpuOptions::from_env`]).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new(choice: &AdapterChoice) -> Result<Self, AdapterError> {
        Self::with_options(choice, &GpuOptions::from_env())
    }

    /// [`Gpu::new`] with explicit options.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn with_options(
        choice: &AdapterChoice,
        options: &GpuOptions,
    ) -> Result<Self, AdapterError> {
        pollster::block_on(Self::with_options_async(choice, options))
    }

    /// [`Gpu::with_options`] without blocking, for the web (`wasm32`, where the adapter and
    /// device requests are promises) or an async host. On the web the device gets WebGPU's
    /// default limits ([`required_limits`]): a page requests no raised limits.
    pub async fn with_options_async(
        choice: &AdapterChoice,
        options: &GpuOptions,
    ) -> Result<Self, AdapterError> {
        let (adapter, mut init_timings) = adapter::select(choice).await?;
        let info = adapter.get_info();
        let description = AdapterDescription::from_info(&info);

        let cache_dir = match &options.pipeline_cache {
            PipelineCacheConfig::Off => Err(PipelineCacheStatus::Off),
            PipelineCacheConfig::Dir(dir) => match pipeline_cache::DiskCache::supported(&adapter) {
                Ok(()) => Ok(dir.clone()),
                Err(reason) => Err(PipelineCacheStatus::Unsupported { reason }),
            },
        };
        let start = Instant::now();
        let descriptor = wgpu::DeviceDescriptor {
            label: Some("rtc device"),
            required_features: if cache_dir.is_ok() {
                wgpu::Features::PIPELINE_CACHE
            } else {
                wgpu::Features::empty()
            },
            required_limits: if cfg!(target_arch = "wasm32") {
                required_limits()
            } else {
                adapter.limits()
            },
            experimental_features: wgpu::ExperimentalFeatures::disabled(),
            memory_hints: wgpu::MemoryHints::Performance,
            trace: wgpu::Trace::Off,
        };
        let (device, queue) = adapter
            .request_device(&descriptor)
            .await
            .map_err(|source| AdapterError::RequestDevice {
                adapter: info.name.clone(),
                source,
            })?;
        init_timings.device_ms = elapsed_ms(start);

        let gpu = Self::assemble(adapter, device, queue, description, init_timings, cache_dir);
        gpu.record_uncaptured_errors();
        Ok(gpu)
    }

    /// A context on a host application's own adapter, device and queue (owned clones of wgpu's
    /// handles: the host keeps using its own), for embedding rtc: no instance, adapter or device
    /// is created. rtc records its commands on `queue` and creates its buffers and pipelines on
    /// `device`; the host's resources are untouched.
    ///
    /// The device must offer what rtc's kernels need ([`required_limits`], and compute shaders);
    /// otherwise this fails with [`FromDeviceError::Unsupported`], listing every shortfall.
    /// Requesting `required_limits()` (or `adapter.limits()`, for scenes whose buffers exceed
    /// WebGPU's default 128 MiB binding) when creating the device satisfies it. No feature is
    /// required; the on-disk pipeline cache of `options` is used only when the device was
    /// created with `Features::PIPELINE_CACHE` (its status says why not otherwise).
    ///
    /// **Uncaptured errors.** wgpu keeps one uncaptured-error handler per device and offers no
    /// way to read the current one, so a handler cannot be chained. This constructor therefore
    /// leaves the host's handler in place: rtc runs each of its own wgpu calls inside error
    /// scopes and reports failures as typed errors, so its calls do not reach that handler, and
    /// [`Gpu::take_uncaptured_errors`] stays empty. A host that wants rtc's recording handler
    /// instead (errors collected rather than wgpu's default panic) calls
    /// [`Gpu::record_uncaptured_errors`], which replaces the device's handler.
    pub fn from_device(
        adapter: wgpu::Adapter,
        device: wgpu::Device,
        queue: wgpu::Queue,
        options: &GpuOptions,
    ) -> Result<Self, FromDeviceError> {
        let info = adapter.get_info();
        let missing = missing_capabilities(&device.limits(), &adapter.get_downlevel_capabilities());
        if !missing.is_empty() {
            return Err(FromDeviceError::Unsupported {
                adapter: info.name,
                missing,
            });
        }
        let description = AdapterDescription::from_info(&info);
        let cache_dir = match &options.pipeline_cache {
            PipelineCacheConfig::Off => Err(PipelineCacheStatus::Off),
            PipelineCacheConfig::Dir(dir) => match pipeline_cache::DiskCache::supported(&adapter) {
                Err(reason) => Err(PipelineCacheStatus::Unsupported { reason }),
                Ok(()) if !device.features().contains(wgpu::Features::PIPELINE_CACHE) => {
                    Err(PipelineCacheStatus::Unsupported {
                        reason: "the host's device was created without wgpu's PIPELINE_CACHE \
                                 feature"
                            .to_string(),
                    })
                }
                Ok(()) => Ok(dir.clone()),
            },
        };
        Ok(Self::assemble(
            adapter,
            device,
            queue,
            description,
            InitTimings::default(),
            cache_dir,
        ))
    }

    /// The context around a device, with the on-disk pipeline cache opened from `cache_dir`
    /// (or its status, when there is none).
    fn assemble(
        adapter: wgpu::Adapter,
        device: wgpu::Device,
        queue: wgpu::Queue,
        description: AdapterDescription,
        init_timings: InitTimings,
        cache_dir: Result<std::path::PathBuf, PipelineCacheStatus>,
    ) -> Self {
        let limits = GpuLimits::from_wgpu(&device.limits());
        let (disk_cache, pipeline_cache_status, warnings) = match cache_dir {
            Ok(dir) => {
                let opened = pipeline_cache::DiskCache::open(&device, &adapter, &dir);
                (opened.cache, opened.status, opened.warnings)
            }
            Err(status) => (None, status, Vec::new()),
        };
        Self {
            adapter,
            device,
            queue,
            description,
            limits,
            init_timings,
            uncaptured: Arc::new(Mutex::new(Vec::new())),
            kernels: Mutex::new(Vec::new()),
            pipelines_created: AtomicU64::new(0),
            disk_cache,
            pipeline_cache_status,
            warnings: Mutex::new(warnings),
        }
    }

    /// Installs rtc's uncaptured-error handler on the device, replacing the current one: errors
    /// raised outside any error scope are recorded for [`Gpu::take_uncaptured_errors`] instead of
    /// reaching wgpu's default handler (which panics). [`Gpu::new`] does this itself;
    /// [`Gpu::from_device`] leaves the choice to the host.
    pub fn record_uncaptured_errors(&self) {
        let sink = Arc::clone(&self.uncaptured);
        self.device
            .on_uncaptured_error(Arc::new(move |error: wgpu::Error| {
                sink.lock()
                    .unwrap_or_else(PoisonError::into_inner)
                    .push(error.to_string());
            }));
    }

    /// How many compute pipelines this context has created (memory-cache hits do not count).
    pub fn pipelines_created(&self) -> u64 {
        self.pipelines_created.load(Ordering::Relaxed)
    }

    fn count_pipeline_creation(&self) {
        self.pipelines_created.fetch_add(1, Ordering::Relaxed);
        kernels::count_global();
    }

    /// What became of the on-disk pipeline cache (updated when a write shows that the driver
    /// keeps nothing in it).
    pub fn pipeline_cache_status(&self) -> PipelineCacheStatus {
        match (&self.disk_cache, &self.pipeline_cache_status) {
            (Some(disk), PipelineCacheStatus::Active { bytes, .. }) => disk.status(*bytes),
            (_, status) => status.clone(),
        }
    }

    fn disk_cache(&self) -> Option<&pipeline_cache::DiskCache> {
        self.disk_cache.as_ref()
    }

    /// Problems since the last call that did not stop anything (an ignored or unwritable
    /// pipeline cache file), one sentence each.
    pub fn take_warnings(&self) -> Vec<String> {
        std::mem::take(&mut *self.warnings.lock().unwrap_or_else(PoisonError::into_inner))
    }

    fn warn(&self, message: String) {
        self.warnings
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .push(message);
    }

    /// A kernel created earlier on this device from the same module and bindings, if kept.
    fn cached_kernel(&self, key: u64) -> Option<Kernel> {
        let mut kernels = self.kernels.lock().unwrap_or_else(PoisonError::into_inner);
        let at = kernels.iter().position(|(k, _)| *k == key)?;
        let entry = kernels.remove(at);
        let kernel = entry.1.clone();
        kernels.push(entry);
        Some(kernel)
    }

    /// Keeps `kernel` for reuse, dropping the least recently used beyond [`KERNEL_CACHE`].
    fn cache_kernel(&self, key: u64, kernel: Kernel) {
        let mut kernels = self.kernels.lock().unwrap_or_else(PoisonError::into_inner);
        kernels.retain(|(k, _)| *k != key);
        kernels.push((key, kernel));
        if kernels.len() > KERNEL_CACHE {
            kernels.remove(0);
        }
    }

    /// What the chosen adapter is (name, backend, device type, driver), for printing.
    pub fn description(&self) -> &AdapterDescription {
        &self.description
    }

    /// The device limits the runtime checks against.
    pub fn limits(&self) -> &GpuLimits {
        &self.limits
    }

    /// How long creating this context took.
    pub fn init_timings(&self) -> InitTimings {
        self.init_timings
    }

    /// The wgpu adapter.
    pub fn adapter(&self) -> &wgpu::Adapter {
        &self.adapter
    }

    /// The wgpu device.
    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    /// The wgpu queue.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// Errors wgpu reported outside any error scope since the last call (normally none: the
    /// runtime scopes its own calls; this catches errors from callers using the raw device).
    /// Always empty on a host's device unless [`Gpu::record_uncaptured_errors`] was called.
    pub fn take_uncaptured_errors(&self) -> Vec<String> {
        std::mem::take(
            &mut *self
                .uncaptured
                .lock()
                .unwrap_or_else(PoisonError::into_inner),
        )
    }

    /// Runs `f` inside validation, out-of-memory and internal error scopes and returns its value
    /// with the first error raised, rendered with its source chain.
    /// Error scopes are per thread in wgpu, so kernels may be created on several threads at once.
    ///
    /// On the web (`wasm32`) nothing may block, so the scopes are popped in spawned futures and
    /// their errors are recorded for [`Gpu::take_uncaptured_errors`] instead: this returns no
    /// error, and a failure surfaces at the next check of the recorded errors (the end of
    /// [`Renderer::accumulate`](crate::render::Renderer::accumulate), for one).
    pub fn scoped<T>(&self, f: impl FnOnce() -> T) -> (T, Option<String>) {
        #[cfg(not(target_arch = "wasm32"))]
        {
            scoped_on(&self.device, f)
        }
        #[cfg(target_arch = "wasm32")]
        {
            (scoped_deferred(&self.device, &self.uncaptured, f), None)
        }
    }

    /// Blocks until all submitted work is done.
    pub fn wait_idle(&self) -> Result<(), wgpu::PollError> {
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map(|_| ())
    }
}

/// [`Gpu::scoped`] on a bare device (while the `Gpu` is being built).
fn scoped_on<T>(device: &wgpu::Device, f: impl FnOnce() -> T) -> (T, Option<String>) {
    let internal = device.push_error_scope(wgpu::ErrorFilter::Internal);
    let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let value = f();
    let errors = [
        pollster::block_on(validation.pop()),
        pollster::block_on(oom.pop()),
        pollster::block_on(internal.pop()),
    ];
    let first = errors.into_iter().flatten().next().map(|e| error_chain(&e));
    (value, first)
}

/// [`Gpu::scoped`] on the web: the scopes' errors go to `sink` once their futures resolve.
#[cfg(target_arch = "wasm32")]
fn scoped_deferred<T>(
    device: &wgpu::Device,
    sink: &Arc<Mutex<Vec<String>>>,
    f: impl FnOnce() -> T,
) -> T {
    let internal = device.push_error_scope(wgpu::ErrorFilter::Internal);
    let oom = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let value = f();
    let pops = [validation.pop(), oom.pop(), internal.pop()];
    let sink = Arc::clone(sink);
    wasm_bindgen_futures::spawn_local(async move {
        for pop in pops {
            if let Some(error) = pop.await {
                sink.lock()
                    .unwrap_or_else(PoisonError::into_inner)
                    .push(error_chain(&error));
            }
        }
    });
    value
}

/// Renders an error and all its sources on one line (wgpu's `Display` often hides the detail).
pub(crate) fn error_chain(error: &dyn std::error::Error) -> String {
    let mut text = error.to_string();
    let mut source = error.source();
    while let Some(inner) = source {
        let line = inner.to_string();
        if !text.contains(&line) {
            text.push_str(": ");
            text.push_str(&line);
        }
        source = inner.source();
    }
    text
}

/// Milliseconds since `start`.
pub(crate) fn elapsed_ms(start: Instant) -> f64 {
    start.elapsed().as_secs_f64() * 1e3
}
