//! Compute pipelines with an explicit bind group layout, from a `naga::Module` or WGSL text.
//!
//! A [`Kernel`] is one compute entry point plus the binding list of bind group 0 that the
//! compiler's manifest describes ([`BindingDesc`]). The layout is built from that list, never
//! from wgpu's automatic layout (`layout: None`), so the runtime and the compiler agree on the
//! bindings by construction and a mismatch is reported here, naming the binding.
//!
//! Invariants:
//! - WGSL text is parsed by naga here (with the source for error messages) and then takes the
//!   same path as a module: one validation, one reflection, `ShaderSource::Naga`.
//! - Before wgpu sees the module, every resource the entry point uses is checked against the
//!   binding list: group 0 only, declared, and of a compatible kind. wgpu's own validation then
//!   runs inside error scopes, so its errors come back as [`PipelineError::Wgpu`], not panics.
//! - An optional *tile binding* is a uniform with a dynamic offset holding [`TileParams`]; the
//!   tiled dispatcher sets one offset per tile.
//! - Creation time is measured per phase ([`PipelineTimings`]).
//! - [`prepare`] (CPU work: parse, hash, memory cache, validation) and [`build`] (wgpu and the
//!   driver) are separate so that `kernels.rs` can run them for a set of kernels on threads.
//!
//! `create_shader_module_trusted` (no bounds checks, no loop bounding) is deliberately not used: it
//! needs `unsafe`, which the workspace denies, it is only sound for kernels proven in bounds, and
//! on lavapipe it measured within noise of the checked module (749 against 758 ms a thesis frame,
//! docs/bench/lavapipe.md).

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::fmt;
use std::num::NonZeroU64;
use web_time::Instant;

use super::dispatch::TileParams;
use super::kernels::{KernelOrigin, KernelReport};
use super::{elapsed_ms, Gpu};

/// How a binding is accessed by the shader.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BindingKind {
    /// `var<uniform>`.
    Uniform,
    /// `var<storage, read>`.
    StorageRead,
    /// `var<storage, read_write>`.
    StorageReadWrite,
}

impl BindingKind {
    /// Whether this is a storage buffer (either access).
    pub fn is_storage(self) -> bool {
        !matches!(self, BindingKind::Uniform)
    }

    fn wgpu_type(self) -> wgpu::BufferBindingType {
        match self {
            BindingKind::Uniform => wgpu::BufferBindingType::Uniform,
            BindingKind::StorageRead => wgpu::BufferBindingType::Storage { read_only: true },
            BindingKind::StorageReadWrite => wgpu::BufferBindingType::Storage { read_only: false },
        }
    }
}

impl fmt::Display for BindingKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            BindingKind::Uniform => "uniform",
            BindingKind::StorageRead => "storage, read",
            BindingKind::StorageReadWrite => "storage, read_write",
        })
    }
}

/// One binding of bind group 0, as the compiler's manifest lists it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BindingDesc {
    /// The binding number in group 0.
    pub binding: u32,
    /// A human name (the manifest's), used in errors and buffer labels.
    pub name: String,
    /// How the shader accesses it.
    pub kind: BindingKind,
    /// Smallest size in bytes a bound buffer may have (for an array: one element); 0 for none.
    pub min_size: u64,
}

impl BindingDesc {
    /// A binding description.
    pub fn new(binding: u32, name: impl Into<String>, kind: BindingKind, min_size: u64) -> Self {
        Self {
            binding,
            name: name.into(),
            kind,
            min_size,
        }
    }
}

/// Where the shader comes from.
#[derive(Clone, Debug)]
pub enum KernelSource<'a> {
    /// WGSL text, parsed by naga here.
    Wgsl(Cow<'a, str>),
    /// A module the compiler built (validated here again; wgpu validates once more).
    Naga(Box<naga::Module>),
}

/// Everything needed to create a [`Kernel`].
#[derive(Clone, Debug)]
pub struct KernelDesc<'a> {
    /// Debug label for wgpu objects.
    pub label: &'a str,
    /// The shader.
    pub source: KernelSource<'a>,
    /// The compute entry point's name.
    pub entry_point: &'a str,
    /// Bind group 0, in any order; binding numbers must be unique.
    pub bindings: &'a [BindingDesc],
    /// The uniform binding that receives [`TileParams`] per tile (dynamic offset), if the kernel
    /// is dispatched in tiles. It must be listed in `bindings` with kind `Uniform`.
    pub tile_binding: Option<u32>,
}

/// Milliseconds spent in each phase of kernel creation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PipelineTimings {
    /// WGSL parse (0 for a naga module).
    pub parse_ms: f64,
    /// naga validation and binding reflection.
    pub validate_ms: f64,
    /// `create_shader_module` (wgpu validates the module again).
    pub shader_module_ms: f64,
    /// Layouts and `create_compute_pipeline` (backend code generation and the driver's compile).
    pub pipeline_ms: f64,
}

impl PipelineTimings {
    /// Sum of all phases.
    pub fn total_ms(&self) -> f64 {
        self.parse_ms + self.validate_ms + self.shader_module_ms + self.pipeline_ms
    }
}

/// Why a kernel could not be created.
#[derive(Debug, thiserror::Error)]
pub enum PipelineError {
    /// The WGSL text does not parse.
    #[error("kernel `{label}`: WGSL parse error:\n{message}")]
    Parse {
        /// The kernel's label.
        label: String,
        /// naga's rendered diagnostic.
        message: String,
    },
    /// naga rejects the module.
    #[error("kernel `{label}`: the shader module does not validate:\n{message}")]
    Validation {
        /// The kernel's label.
        label: String,
        /// naga's rendered diagnostic.
        message: String,
    },
    /// No compute entry point of that name.
    #[error("kernel `{label}`: no compute entry point `{entry_point}` (compute entry points: {available:?})")]
    MissingEntryPoint {
        /// The kernel's label.
        label: String,
        /// The requested name.
        entry_point: String,
        /// The compute entry points present.
        available: Vec<String>,
    },
    /// A binding number appears twice in the list.
    #[error("kernel `{label}`: binding {binding} is listed twice")]
    DuplicateBinding {
        /// The kernel's label.
        label: String,
        /// The repeated number.
        binding: u32,
    },
    /// The shader uses a resource outside group 0.
    #[error("kernel `{label}`: the shader uses `{name}` at @group({group}) @binding({binding}); only group 0 is supported")]
    UnsupportedGroup {
        /// The kernel's label.
        label: String,
        /// The shader variable's name.
        name: String,
        /// Its group.
        group: u32,
        /// Its binding.
        binding: u32,
    },
    /// The shader uses a binding the list does not declare.
    #[error("kernel `{label}`: the shader uses `{name}` at binding {binding}, which the binding list does not declare")]
    UndeclaredBinding {
        /// The kernel's label.
        label: String,
        /// The shader variable's name.
        name: String,
        /// Its binding.
        binding: u32,
    },
    /// The shader's access does not fit the declared kind.
    #[error("kernel `{label}`: binding {binding} (`{name}`) is declared `{declared}` but the shader needs `{shader}`")]
    KindMismatch {
        /// The kernel's label.
        label: String,
        /// The binding.
        binding: u32,
        /// The declared name.
        name: String,
        /// The declared kind.
        declared: BindingKind,
        /// What the shader declares.
        shader: BindingKind,
    },
    /// A shader variable at a binding is not a buffer (textures and samplers are not supported yet).
    #[error("kernel `{label}`: `{name}` at binding {binding} is not a uniform or storage buffer")]
    UnsupportedResource {
        /// The kernel's label.
        label: String,
        /// The shader variable's name.
        name: String,
        /// Its binding.
        binding: u32,
    },
    /// The tile binding is missing from the list or not a uniform.
    #[error("kernel `{label}`: tile binding {binding} must be listed as a `uniform` binding")]
    BadTileBinding {
        /// The kernel's label.
        label: String,
        /// The tile binding.
        binding: u32,
    },
    /// More storage buffers than the device allows per stage.
    #[error("kernel `{label}`: {count} storage buffers, but the adapter allows {limit} per shader stage")]
    TooManyStorageBuffers {
        /// The kernel's label.
        label: String,
        /// How many the list declares.
        count: u32,
        /// `max_storage_buffers_per_shader_stage`.
        limit: u32,
    },
    /// The workgroup is larger than the device allows.
    #[error("kernel `{label}`: workgroup size {size:?} has more than {limit} invocations")]
    WorkgroupTooLarge {
        /// The kernel's label.
        label: String,
        /// The entry point's workgroup size.
        size: [u32; 3],
        /// `max_compute_invocations_per_workgroup`.
        limit: u32,
    },
    /// wgpu reported an error while creating the shader module or pipeline.
    #[error("kernel `{label}`: wgpu rejected the {stage}: {message}")]
    Wgpu {
        /// The kernel's label.
        label: String,
        /// `shader module` or `compute pipeline`.
        stage: &'static str,
        /// wgpu's message with its sources.
        message: String,
    },
}

/// A compute pipeline with its explicit bind group layout and what the dispatcher needs to know.
/// Cloning is cheap: wgpu's handles are reference-counted.
#[derive(Clone, Debug)]
pub struct Kernel {
    label: String,
    pipeline: wgpu::ComputePipeline,
    bind_group_layout: wgpu::BindGroupLayout,
    bindings: Vec<BindingDesc>,
    tile_binding: Option<u32>,
    workgroup_size: [u32; 3],
    timings: PipelineTimings,
    origin: KernelOrigin,
    warm_up_ms: f64,
}

impl Kernel {
    /// The debug label.
    pub fn label(&self) -> &str {
        &self.label
    }

    /// The wgpu pipeline.
    pub fn pipeline(&self) -> &wgpu::ComputePipeline {
        &self.pipeline
    }

    /// The explicit layout of bind group 0.
    pub fn bind_group_layout(&self) -> &wgpu::BindGroupLayout {
        &self.bind_group_layout
    }

    /// The bindings of group 0, sorted by binding number.
    pub fn bindings(&self) -> &[BindingDesc] {
        &self.bindings
    }

    /// The tile-parameter binding, if any.
    pub fn tile_binding(&self) -> Option<u32> {
        self.tile_binding
    }

    /// The entry point's `@workgroup_size`.
    pub fn workgroup_size(&self) -> [u32; 3] {
        self.workgroup_size
    }

    /// How long creation took, per phase (for a reused kernel: the look-up only).
    pub fn timings(&self) -> PipelineTimings {
        self.timings
    }

    /// Whether this kernel was compiled now or reused, and from which cache.
    pub fn origin(&self) -> KernelOrigin {
        self.origin
    }

    /// What creating this kernel cost, for the render summary and `rtc compile --timings`.
    pub fn report(&self) -> KernelReport {
        KernelReport {
            label: self.label.clone(),
            origin: self.origin,
            timings: self.timings,
            warm_up_ms: self.warm_up_ms,
        }
    }

    pub(super) fn set_warm_up_ms(&mut self, ms: f64) {
        self.warm_up_ms = ms;
    }

    pub(super) fn set_origin(&mut self, origin: KernelOrigin) {
        self.origin = origin;
    }
}

/// Creates a compute kernel: parse (WGSL), validate and reflect, check the bindings, build the
/// explicit layout, create the shader module and the pipeline, and warm it up. A kernel this
/// [`Gpu`] created before from the same module and bindings is reused. This is
/// [`Gpu::create_kernels`] for one kernel.
pub fn create_kernel(gpu: &Gpu, desc: KernelDesc<'_>) -> Result<Kernel, PipelineError> {
    gpu.create_kernels(vec![desc]).pop().unwrap_or_else(|| {
        Err(PipelineError::Wgpu {
            label: String::new(),
            stage: "kernel set",
            message: "no kernel came back".to_string(),
        })
    })
}

/// A kernel after the CPU-side work: reused from the memory cache, or validated and ready for
/// the driver.
pub(super) enum Prepared<'a> {
    /// The memory cache held it (its timings say how long the look-up took).
    Cached(Kernel),
    /// Validated; the shader module and pipeline are still to be created.
    New(Box<Job<'a>>),
}

/// What [`build`] needs.
pub(super) struct Job<'a> {
    pub(super) key: u64,
    label: String,
    entry_point: &'a str,
    module: naga::Module,
    bindings: BTreeMap<u32, BindingDesc>,
    tile_binding: Option<u32>,
    workgroup_size: [u32; 3],
    timings: PipelineTimings,
}

/// Parses, hashes, looks up the memory cache, validates and reflects: everything before wgpu.
pub(super) fn prepare<'a>(gpu: &Gpu, desc: KernelDesc<'a>) -> Result<Prepared<'a>, PipelineError> {
    let label = desc.label.to_string();
    let mut timings = PipelineTimings::default();

    let start = Instant::now();
    let (module, source_text) = match desc.source {
        KernelSource::Wgsl(text) => {
            let module = naga::front::wgsl::parse_str(&text).map_err(|e| PipelineError::Parse {
                label: label.clone(),
                message: e.emit_to_string(&text),
            })?;
            (module, Some(text))
        }
        KernelSource::Naga(module) => (*module, None),
    };
    timings.parse_ms = elapsed_ms(start);

    // The same module with the same bindings on the same device is the same pipeline: reuse it.
    // This is what makes a watch-mode preview fast when an edit leaves the kernel unchanged.
    let start = Instant::now();
    let key = kernel_key(
        [desc.label, desc.entry_point],
        desc.tile_binding,
        desc.bindings,
        &module,
    );
    if let Some(mut kernel) = gpu.cached_kernel(key) {
        kernel.timings = PipelineTimings {
            parse_ms: timings.parse_ms,
            validate_ms: elapsed_ms(start),
            ..PipelineTimings::default()
        };
        kernel.origin = KernelOrigin::MemoryCache;
        kernel.warm_up_ms = 0.0;
        return Ok(Prepared::Cached(kernel));
    }
    let key_ms = elapsed_ms(start);

    let start = Instant::now();
    let bindings = sorted_bindings(&label, desc.bindings)?;
    let workgroup_size = reflect(
        &label,
        &module,
        source_text.as_deref(),
        desc.entry_point,
        &bindings,
    )?;
    check_limits(gpu, &label, &bindings, workgroup_size)?;
    if let Some(tile) = desc.tile_binding {
        if bindings.get(&tile).map(|b| b.kind) != Some(BindingKind::Uniform) {
            return Err(PipelineError::BadTileBinding {
                label,
                binding: tile,
            });
        }
    }
    timings.validate_ms = elapsed_ms(start) + key_ms;
    Ok(Prepared::New(Box::new(Job {
        key,
        label,
        entry_point: desc.entry_point,
        module,
        bindings,
        tile_binding: desc.tile_binding,
        workgroup_size,
        timings,
    })))
}

/// Creates the shader module, the layouts and the pipeline (with the driver's pipeline cache
/// when given), counts the creation and keeps the kernel in the memory cache.
pub(super) fn build(
    gpu: &Gpu,
    job: Job<'_>,
    cache: Option<&wgpu::PipelineCache>,
) -> Result<Kernel, PipelineError> {
    let Job {
        key,
        label,
        entry_point,
        module,
        bindings,
        tile_binding,
        workgroup_size,
        mut timings,
    } = job;

    let start = Instant::now();
    let (shader, error) = gpu.scoped(|| {
        gpu.device()
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(&label),
                source: wgpu::ShaderSource::Naga(Cow::Owned(module)),
            })
    });
    if let Some(message) = error {
        return Err(PipelineError::Wgpu {
            label,
            stage: "shader module",
            message,
        });
    }
    timings.shader_module_ms = elapsed_ms(start);

    let start = Instant::now();
    let entries: Vec<wgpu::BindGroupLayoutEntry> = bindings
        .values()
        .map(|b| layout_entry(b, tile_binding == Some(b.binding)))
        .collect();
    let ((bind_group_layout, pipeline), error) = gpu.scoped(|| {
        let device = gpu.device();
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(&label),
            entries: &entries,
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(&label),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(&label),
            layout: Some(&layout),
            module: &shader,
            entry_point: Some(entry_point),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache,
        });
        (bind_group_layout, pipeline)
    });
    if let Some(message) = error {
        return Err(PipelineError::Wgpu {
            label,
            stage: "compute pipeline",
            message,
        });
    }
    timings.pipeline_ms = elapsed_ms(start);
    gpu.count_pipeline_creation();

    let kernel = Kernel {
        label,
        pipeline,
        bind_group_layout,
        bindings: bindings.into_values().collect(),
        tile_binding,
        workgroup_size,
        timings,
        origin: KernelOrigin::Compiled,
        warm_up_ms: 0.0,
    };
    gpu.cache_kernel(key, kernel.clone());
    Ok(kernel)
}

/// A hash of everything a pipeline depends on: the label, entry point, tile binding, binding list
/// and the module itself: its `Debug` form, which holds every arena's contents, with the source
/// spans left out (`Span { start: …, end: … }`, which blocks list): an edit that only moves code
/// in a file (a longer constant in the user's scene shifts every later file's spans) must not make
/// an unchanged kernel new.
fn kernel_key(
    names: [&str; 2],
    tile_binding: Option<u32>,
    bindings: &[BindingDesc],
    module: &naga::Module,
) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    names.hash(&mut h);
    tile_binding.hash(&mut h);
    format!("{bindings:?}").hash(&mut h);
    without_spans(&format!("{module:?}")).hash(&mut h);
    h.finish()
}

/// `text` with every `Span { start: A, end: B }` written as `Span`.
fn without_spans(text: &str) -> String {
    const OPEN: &str = "Span { start: ";
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(OPEN) {
        out.push_str(&rest[..at]);
        out.push_str("Span");
        let after = &rest[at + OPEN.len()..];
        match after.find(" }") {
            Some(end) => rest = &after[end + 2..],
            None => {
                rest = after;
                break;
            }
        }
    }
    out.push_str(rest);
    out
}

fn sorted_bindings(
    label: &str,
    bindings: &[BindingDesc],
) -> Result<BTreeMap<u32, BindingDesc>, PipelineError> {
    let mut sorted = BTreeMap::new();
    for b in bindings {
        if sorted.insert(b.binding, b.clone()).is_some() {
            return Err(PipelineError::DuplicateBinding {
                label: label.to_string(),
                binding: b.binding,
            });
        }
    }
    Ok(sorted)
}

/// Validates the module, finds the entry point and checks every global it uses against the
/// binding list. Returns the entry point's workgroup size.
fn reflect(
    label: &str,
    module: &naga::Module,
    source: Option<&str>,
    entry_point: &str,
    bindings: &BTreeMap<u32, BindingDesc>,
) -> Result<[u32; 3], PipelineError> {
    let label_s = || label.to_string();
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(module)
    .map_err(|e| PipelineError::Validation {
        label: label_s(),
        message: match source {
            Some(text) => e.emit_to_string(text),
            None => super::error_chain(e.as_inner()),
        },
    })?;

    let found = module
        .entry_points
        .iter()
        .enumerate()
        .find(|(_, ep)| ep.stage == naga::ShaderStage::Compute && ep.name == entry_point);
    let Some((index, ep)) = found else {
        return Err(PipelineError::MissingEntryPoint {
            label: label_s(),
            entry_point: entry_point.to_string(),
            available: module
                .entry_points
                .iter()
                .filter(|ep| ep.stage == naga::ShaderStage::Compute)
                .map(|ep| ep.name.clone())
                .collect(),
        });
    };
    let uses = info.get_entry_point(index);

    for (handle, var) in module.global_variables.iter() {
        let Some(rb) = &var.binding else { continue };
        if uses[handle].is_empty() {
            continue;
        }
        let name = var
            .name
            .clone()
            .unwrap_or_else(|| format!("global#{}", handle.index()));
        if rb.group != 0 {
            return Err(PipelineError::UnsupportedGroup {
                label: label_s(),
                name,
                group: rb.group,
                binding: rb.binding,
            });
        }
        let shader_kind = match var.space {
            naga::AddressSpace::Uniform => BindingKind::Uniform,
            naga::AddressSpace::Storage { access }
                if access.contains(naga::StorageAccess::STORE) =>
            {
                BindingKind::StorageReadWrite
            }
            naga::AddressSpace::Storage { .. } => BindingKind::StorageRead,
            _ => {
                return Err(PipelineError::UnsupportedResource {
                    label: label_s(),
                    name,
                    binding: rb.binding,
                })
            }
        };
        let Some(declared) = bindings.get(&rb.binding) else {
            return Err(PipelineError::UndeclaredBinding {
                label: label_s(),
                name,
                binding: rb.binding,
            });
        };
        // A read-write layout entry may back a read-only shader variable; nothing else mixes.
        let compatible = declared.kind == shader_kind
            || (declared.kind == BindingKind::StorageReadWrite
                && shader_kind == BindingKind::StorageRead);
        if !compatible {
            return Err(PipelineError::KindMismatch {
                label: label_s(),
                binding: rb.binding,
                name: declared.name.clone(),
                declared: declared.kind,
                shader: shader_kind,
            });
        }
    }
    Ok(ep.workgroup_size)
}

fn check_limits(
    gpu: &Gpu,
    label: &str,
    bindings: &BTreeMap<u32, BindingDesc>,
    workgroup_size: [u32; 3],
) -> Result<(), PipelineError> {
    let limits = gpu.limits();
    let storage = bindings.values().filter(|b| b.kind.is_storage()).count();
    let storage = u32::try_from(storage).unwrap_or(u32::MAX);
    if storage > limits.max_storage_buffers_per_shader_stage {
        return Err(PipelineError::TooManyStorageBuffers {
            label: label.to_string(),
            count: storage,
            limit: limits.max_storage_buffers_per_shader_stage,
        });
    }
    let invocations = workgroup_size
        .iter()
        .try_fold(1u32, |acc, &n| acc.checked_mul(n))
        .unwrap_or(u32::MAX);
    if invocations > limits.max_compute_invocations_per_workgroup {
        return Err(PipelineError::WorkgroupTooLarge {
            label: label.to_string(),
            size: workgroup_size,
            limit: limits.max_compute_invocations_per_workgroup,
        });
    }
    Ok(())
}

fn layout_entry(binding: &BindingDesc, is_tile: bool) -> wgpu::BindGroupLayoutEntry {
    let min_size = if is_tile {
        std::mem::size_of::<TileParams>() as u64
    } else {
        binding.min_size
    };
    wgpu::BindGroupLayoutEntry {
        binding: binding.binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: binding.kind.wgpu_type(),
            has_dynamic_offset: is_tile,
            min_binding_size: NonZeroU64::new(min_size),
        },
        count: None,
    }
}

#[cfg(test)]
mod span_tests {
    #[test]
    fn spans_are_left_out_of_the_key_text() {
        assert_eq!(
            super::without_spans("Block { body: [Return], span_info: [Span { start: 3, end: 9 }, Span { start: 10, end: 12 }] }"),
            "Block { body: [Return], span_info: [Span, Span] }"
        );
        assert_eq!(super::without_spans("no spans"), "no spans");
    }
}
