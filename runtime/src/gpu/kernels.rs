//! Creating a set of kernels at once ([`Gpu::create_kernels`]), with reuse and accounting.
//!
//! For each [`KernelDesc`] of the set, in this order:
//! 1. the memory cache of the [`Gpu`] (keyed by a hash of label, entry point, tile binding,
//!    binding list and module): a hit is returned as it is, [`KernelOrigin::MemoryCache`];
//! 2. otherwise the kernel is validated and its pipeline created, on worker threads (one per
//!    kernel, at most the machine's parallelism), with the on-disk [`wgpu::PipelineCache`] when the
//!    `Gpu` has one ([`KernelOrigin::DiskCache`] when the loaded file was written for this key,
//!    else [`KernelOrigin::Compiled`]);
//! 3. each new pipeline gets a warm-up dispatch of zero workgroups with scratch buffers, because
//!    lavapipe (llvmpipe) compiles a compute shader to machine code at its first dispatch, not in
//!    `vkCreateComputePipelines`; the dispatch runs no shader invocation. The warm-ups run one
//!    after another (a device has one queue, and lavapipe runs its commands on one thread);
//! 4. if any pipeline was new, the disk cache is written back.
//!
//! Every pipeline created counts once, in the `Gpu`'s counter ([`Gpu::pipelines_created`]) and in
//! a process-wide one ([`pipelines_created`]), so tests can assert what was recompiled.
//!
//! Invariants: the result has one entry per description, in order; a failure of one kernel does
//! not stop the others; no panics on bad input (errors are [`PipelineError`]s).

use std::fmt;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};
use web_time::Instant;

use super::pipeline::{build, prepare, Prepared};
use super::{elapsed_ms, Gpu, Kernel, KernelDesc, PipelineError, PipelineTimings};

/// Pipelines created by every [`Gpu`] of this process.
static CREATED: AtomicU64 = AtomicU64::new(0);

/// How many compute pipelines this process has created so far (all [`Gpu`]s).
pub fn pipelines_created() -> u64 {
    CREATED.load(Ordering::Relaxed)
}

pub(super) fn count_global() {
    CREATED.fetch_add(1, Ordering::Relaxed);
}

/// Where a kernel of [`Gpu::create_kernels`] came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum KernelOrigin {
    /// A new pipeline, compiled by the driver now.
    Compiled,
    /// The same kernel created earlier on this `Gpu`, reused without any driver work.
    MemoryCache,
    /// A new pipeline object created with the on-disk pipeline cache, whose file was written for
    /// this kernel by an earlier process. How much driver work that saved is in the timings.
    DiskCache,
}

impl KernelOrigin {
    /// Whether the driver created a pipeline for it now (compiled, or from the disk cache).
    pub fn is_new_pipeline(self) -> bool {
        !matches!(self, KernelOrigin::MemoryCache)
    }
}

impl fmt::Display for KernelOrigin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            KernelOrigin::Compiled => "compiled",
            KernelOrigin::MemoryCache => "reused (memory cache)",
            KernelOrigin::DiskCache => "reused (disk cache)",
        })
    }
}

/// What creating one kernel cost.
#[derive(Clone, Debug, PartialEq)]
pub struct KernelReport {
    /// The kernel's label.
    pub label: String,
    /// Compiled or reused.
    pub origin: KernelOrigin,
    /// The phases of creation (a memory-cache hit: parse and look-up only).
    pub timings: PipelineTimings,
    /// Milliseconds of the warm-up dispatch, where the driver may compile (0 if none ran).
    pub warm_up_ms: f64,
}

impl KernelReport {
    /// Milliseconds of the driver's work: `create_compute_pipeline` and the warm-up dispatch.
    pub fn driver_ms(&self) -> f64 {
        self.timings.pipeline_ms + self.warm_up_ms
    }

    /// Milliseconds in all: every phase and the warm-up.
    pub fn total_ms(&self) -> f64 {
        self.timings.total_ms() + self.warm_up_ms
    }
}

impl Gpu {
    /// Creates every kernel of `descs` (see the module docs): memory cache first, the rest
    /// validated and created in parallel, each new one warmed up by a dispatch of zero
    /// workgroups. One result per description, in order; [`Kernel::report`] says what each cost.
    pub fn create_kernels(&self, descs: Vec<KernelDesc<'_>>) -> Vec<Result<Kernel, PipelineError>> {
        let count = descs.len();
        let queue: Mutex<Vec<Option<KernelDesc<'_>>>> =
            Mutex::new(descs.into_iter().map(Some).collect());
        let results: Mutex<Vec<Option<Result<Kernel, PipelineError>>>> =
            Mutex::new((0..count).map(|_| None).collect());
        let next = AtomicUsize::new(0);
        let disk = self.disk_cache();
        let work = || loop {
            let i = next.fetch_add(1, Ordering::Relaxed);
            if i >= count {
                break;
            }
            let desc = queue
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .get_mut(i)
                .and_then(Option::take);
            let Some(desc) = desc else { continue };
            let result = prepare(self, desc).and_then(|prepared| match prepared {
                Prepared::Cached(kernel) => Ok(kernel),
                Prepared::New(job) => {
                    let key = job.key;
                    let from_disk = disk.is_some_and(|d| d.had(key));
                    let mut kernel = build(self, *job, disk.map(|d| d.wgpu_cache()))?;
                    if let Some(d) = disk {
                        d.record(key);
                    }
                    if from_disk {
                        kernel.set_origin(KernelOrigin::DiskCache);
                    }
                    Ok(kernel)
                }
            });
            if let Some(slot) = results
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .get_mut(i)
            {
                *slot = Some(result);
            }
        };
        // The web has no threads (and wgpu's handles there are not `Send`): one at a time.
        #[cfg(target_arch = "wasm32")]
        work();
        #[cfg(not(target_arch = "wasm32"))]
        let threads = std::thread::available_parallelism()
            .map_or(1, |n| n.get())
            .min(count);
        #[cfg(not(target_arch = "wasm32"))]
        if threads <= 1 {
            work();
        } else {
            std::thread::scope(|s| {
                for _ in 0..threads {
                    s.spawn(work);
                }
            });
        }
        let mut results: Vec<Result<Kernel, PipelineError>> = results
            .into_inner()
            .unwrap_or_else(PoisonError::into_inner)
            .into_iter()
            .map(|r| {
                r.unwrap_or_else(|| {
                    Err(PipelineError::Wgpu {
                        label: String::new(),
                        stage: "kernel set",
                        message: "a worker thread stopped without a result".to_string(),
                    })
                })
            })
            .collect();

        let mut new_pipelines = false;
        for result in &mut results {
            let Ok(kernel) = result else { continue };
            if !kernel.origin().is_new_pipeline() {
                continue;
            }
            new_pipelines = true;
            match warm_up(self, kernel) {
                Ok(ms) => kernel.set_warm_up_ms(ms),
                Err(e) => *result = Err(e),
            }
        }
        if new_pipelines {
            if let Some(d) = disk {
                if let Err(why) = d.save() {
                    self.warn(format!("the pipeline cache was not saved: {why}"));
                }
            }
        }
        results
    }
}

/// One dispatch of zero workgroups of `kernel` with scratch buffers of each binding's minimum
/// size: the driver binds the pipeline (and lavapipe compiles it) but runs no invocation.
/// Returns the milliseconds from submission to completion.
fn warm_up(gpu: &Gpu, kernel: &Kernel) -> Result<f64, PipelineError> {
    let device = gpu.device();
    let start = Instant::now();
    let ((), error) = gpu.scoped(|| {
        let buffers: Vec<(u32, wgpu::Buffer, u64)> = kernel
            .bindings()
            .iter()
            .map(|b| {
                let size = if kernel.tile_binding() == Some(b.binding) {
                    std::mem::size_of::<super::TileParams>() as u64
                } else {
                    b.min_size
                }
                .max(16)
                .next_multiple_of(16);
                let usage = if b.kind.is_storage() {
                    wgpu::BufferUsages::STORAGE
                } else {
                    wgpu::BufferUsages::UNIFORM
                };
                let buffer = device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("rtc warm-up"),
                    size,
                    usage,
                    mapped_at_creation: false,
                });
                (b.binding, buffer, size)
            })
            .collect();
        let entries: Vec<wgpu::BindGroupEntry<'_>> = buffers
            .iter()
            .map(|(binding, buffer, size)| wgpu::BindGroupEntry {
                binding: *binding,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer,
                    offset: 0,
                    size: wgpu::BufferSize::new(*size),
                }),
            })
            .collect();
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("rtc warm-up"),
            layout: kernel.bind_group_layout(),
            entries: &entries,
        });
        let offsets: &[u32] = if kernel.tile_binding().is_some() {
            &[0]
        } else {
            &[]
        };
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("rtc warm-up"),
        });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("rtc warm-up"),
                timestamp_writes: None,
            });
            pass.set_pipeline(kernel.pipeline());
            pass.set_bind_group(0, &group, offsets);
            pass.dispatch_workgroups(0, 0, 0);
        }
        gpu.queue().submit([encoder.finish()]);
    });
    if let Some(message) = error {
        return Err(PipelineError::Wgpu {
            label: kernel.label().to_string(),
            stage: "warm-up dispatch",
            message,
        });
    }
    gpu.wait_idle().map_err(|e| PipelineError::Wgpu {
        label: kernel.label().to_string(),
        stage: "warm-up dispatch",
        message: e.to_string(),
    })?;
    Ok(elapsed_ms(start))
}
