//! Dispatching kernels, in tiles over an image or once, and reading results back.
//!
//! Tiled dispatch splits a `width × height` image into tiles (row-major, left to right, top to
//! bottom; edge tiles are clipped) so that no single dispatch runs long enough to trip a GPU
//! watchdog. Each tile gets one [`TileParams`] record in a uniform buffer, selected by a dynamic
//! offset; tiles are recorded in batches of [`TileConfig::tiles_per_batch`], and after each batch
//! the dispatcher submits, waits (`device.poll(PollType::wait_indefinitely())`) and reports
//! progress as `(done_tiles, total_tiles)`.
//!
//! The kernel's side of the contract (what the compiler must generate):
//! - declare `TILE_PARAMS_WGSL` at the tile binding as `var<uniform>`;
//! - let `gid = global_invocation_id.xy`; return early when `any(gid >= tile.extent)`;
//! - the pixel is `tile.origin + gid`, its linear index `pixel.y * tile.image_size.x + pixel.x`.
//!
//! Each tile is dispatched with `ceil(extent / workgroup_size)` workgroups in x and y, so every
//! pixel of the image is covered by exactly one invocation (tests check this on a 37 × 23 image
//! with 16 × 16 tiles).
//!
//! Invariants: the tile uniform buffer persists across frames and grows only when the tile count
//! grows; wgpu errors inside a batch come back as [`DispatchError::Wgpu`]; read-back never panics
//! (`map_async` is waited for with a channel and a blocking poll).

#[cfg(not(target_arch = "wasm32"))]
use std::sync::mpsc;
use web_time::Instant;

use super::buffers::{BufferError, BufferSet};
use super::pipeline::{BindingKind, Kernel};
use super::{elapsed_ms, error_chain, Gpu};

mod rounds;
pub(crate) use rounds::add_stage_ms;
pub use rounds::{RoundDispatch, RoundKernels, RoundsReport, TileList};

/// Per-tile parameters, one 32-byte uniform record per tile.
///
/// Layout (WGSL uniform, std140-compatible; identical to [`TILE_PARAMS_WGSL`]):
/// | offset | field | meaning |
/// |---|---|---|
/// | 0 | `origin: vec2<u32>` | top-left pixel of the tile |
/// | 8 | `extent: vec2<u32>` | tile size in pixels, clipped at the image edge |
/// | 16 | `image_size: vec2<u32>` | the whole image's width and height |
/// | 24 | `tile_index: u32` | row-major index of the tile |
/// | 28 | `frame: u32` | the caller's frame/pass counter (e.g. to seed random numbers) |
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct TileParams {
    /// Top-left pixel of the tile.
    pub origin: [u32; 2],
    /// Tile size in pixels, clipped at the image edge.
    pub extent: [u32; 2],
    /// The whole image's size.
    pub image_size: [u32; 2],
    /// Row-major index of the tile.
    pub tile_index: u32,
    /// The caller's frame or pass counter.
    pub frame: u32,
}

const _: () = assert!(std::mem::size_of::<TileParams>() == 32);
const _: () = assert!(std::mem::align_of::<TileParams>() == 4);

/// The WGSL declaration matching [`TileParams`] (kernels paste or generate the same struct).
pub const TILE_PARAMS_WGSL: &str = "struct TileParams {
    origin: vec2<u32>,
    extent: vec2<u32>,
    image_size: vec2<u32>,
    tile_index: u32,
    frame: u32,
}
";

/// The largest tile side: the render kernel permutes a tile's 8 × 8 workgroups with 32-bit
/// arithmetic that needs at most 2^16 of them (`render_invocation` in `stdlib/kernel/trace.rt`).
pub const MAX_TILE_SIDE: u32 = 2048;

/// How to cut an image into tiles and how many tiles to submit at once.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileConfig {
    /// Tile width in pixels (> 0).
    pub tile_width: u32,
    /// Tile height in pixels (> 0).
    pub tile_height: u32,
    /// Tiles recorded per submit; progress is reported after each batch (> 0).
    pub tiles_per_batch: u32,
}

impl Default for TileConfig {
    /// 256 × 256 tiles, 4 per batch: 65 536 pixels per dispatch, short enough for desktop GPU
    /// watchdogs (about 2 s) unless a kernel spends over 30 µs per pixel, and 10 progress steps
    /// for a 1080p frame.
    fn default() -> Self {
        Self {
            tile_width: 256,
            tile_height: 256,
            tiles_per_batch: 4,
        }
    }
}

impl TileConfig {
    /// The default for an adapter: [`TileConfig::default`] for GPUs; 1024 × 1024 tiles, one per
    /// batch, for CPU adapters, which have no watchdog but pay a synchronisation per dispatch, and
    /// whose threads wait for the slowest at the end of each. Measured on lavapipe (2 cores,
    /// 1080p, 64 FMA per pixel): one whole-frame dispatch 46 ms, 512² tiles 48 ms, 256² tiles 65
    /// to 79 ms, 128² tiles 81 to 101 ms. On the thesis scene (1080p, best of 3, after the kernel
    /// spread its workgroups over each tile): 1024² tiles 1634 ms, the whole frame 1649 ms, 512²
    /// tiles two per batch 1738 ms, 256² tiles 1705 ms.
    pub fn for_adapter(adapter: &super::AdapterDescription) -> Self {
        match adapter.device_type {
            wgpu::DeviceType::Cpu => Self {
                tile_width: 1024,
                tile_height: 1024,
                tiles_per_batch: 1,
            },
            _ => Self::default(),
        }
    }
}

/// What a dispatch did and how long it took.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DispatchReport {
    /// Tiles dispatched.
    pub tiles: u32,
    /// Submits (batches).
    pub batches: u32,
    /// Milliseconds to flush pending buffer uploads to the GPU before the first tile.
    pub flush_ms: f64,
    /// Milliseconds from the first tile's recording to the last batch's completion.
    pub dispatch_ms: f64,
}

/// Why a dispatch or read-back failed.
#[derive(Debug, thiserror::Error)]
pub enum DispatchError {
    /// Tiled dispatch of a kernel created without a tile binding.
    #[error("kernel `{kernel}` has no tile binding; create it with `tile_binding` to dispatch it in tiles")]
    NoTileBinding {
        /// The kernel's label.
        kernel: String,
    },
    /// A single dispatch of a kernel that expects per-tile parameters.
    #[error("kernel `{kernel}` has a tile binding; dispatch it with `TileDispatcher::dispatch`")]
    NeedsTiles {
        /// The kernel's label.
        kernel: String,
    },
    /// The tile configuration is unusable.
    #[error("bad tile configuration {config:?}: {reason}")]
    BadTileConfig {
        /// The configuration.
        config: TileConfig,
        /// What is wrong.
        reason: &'static str,
    },
    /// The tile parameters do not fit one uniform buffer addressable by `u32` offsets.
    #[error(
        "the tile parameters need {bytes} bytes, more than one buffer holds; use larger tiles"
    )]
    TooManyTiles {
        /// Bytes needed.
        bytes: u64,
    },
    /// A dispatch needs more workgroups than the device allows in one dimension.
    #[error("kernel `{kernel}`: {count} workgroups in one dimension, but the adapter allows {limit}; use smaller tiles")]
    TooManyWorkgroups {
        /// The kernel's label.
        kernel: String,
        /// The count asked for.
        count: u32,
        /// `max_compute_workgroups_per_dimension`.
        limit: u32,
    },
    /// A binding's buffer is missing or unusable.
    #[error(transparent)]
    Buffer(#[from] BufferError),
    /// The buffer at a binding was created for another kind.
    #[error("kernel `{kernel}`: binding {binding} (`{name}`) needs a `{expected}` buffer, the set holds a `{found}` one")]
    BufferKind {
        /// The kernel's label.
        kernel: String,
        /// The binding.
        binding: u32,
        /// Its declared name.
        name: String,
        /// The kernel's kind.
        expected: BindingKind,
        /// The buffer's kind.
        found: BindingKind,
    },
    /// wgpu reported an error.
    #[error("wgpu error during {stage}: {message}")]
    Wgpu {
        /// What was being done.
        stage: &'static str,
        /// wgpu's message.
        message: String,
    },
    /// Waiting for the device failed (device lost, timeout).
    #[error("waiting for the GPU failed: {message}")]
    Poll {
        /// wgpu's message.
        message: String,
    },
    /// A wavefront tile still had running paths after the most rounds it may take.
    #[error("internal error: a tile's paths were still running after {rounds} rounds of the wavefront kernels")]
    TooManyRounds {
        /// The limit.
        rounds: u32,
    },
    /// Mapping a read-back buffer failed.
    #[error("reading back {size} bytes failed: {message}")]
    Map {
        /// Bytes requested.
        size: u64,
        /// What went wrong.
        message: String,
    },
}

/// The tiles covering a `width × height` image, row-major, edge tiles clipped. Empty when the
/// image or a tile dimension is empty.
pub fn plan_tiles(
    width: u32,
    height: u32,
    tile_width: u32,
    tile_height: u32,
    frame: u32,
) -> Vec<TileParams> {
    if width == 0 || height == 0 || tile_width == 0 || tile_height == 0 {
        return Vec::new();
    }
    let mut tiles = Vec::new();
    let mut index = 0u32;
    for y in (0..height).step_by(tile_height as usize) {
        for x in (0..width).step_by(tile_width as usize) {
            tiles.push(TileParams {
                origin: [x, y],
                extent: [tile_width.min(width - x), tile_height.min(height - y)],
                image_size: [width, height],
                tile_index: index,
                frame,
            });
            index = index.wrapping_add(1);
        }
    }
    tiles
}

/// Dispatches kernels in tiles; keeps its configuration and its tile uniform buffer across
/// frames.
#[derive(Debug, Default)]
pub struct TileDispatcher {
    config: TileConfig,
    params: Option<wgpu::Buffer>,
}

impl TileDispatcher {
    /// A dispatcher cutting images as `config` says (checked at dispatch).
    pub fn new(config: TileConfig) -> Self {
        Self {
            config,
            params: None,
        }
    }

    /// The tile configuration.
    pub fn config(&self) -> TileConfig {
        self.config
    }

    /// Changes the tile configuration for later dispatches.
    pub fn set_config(&mut self, config: TileConfig) {
        self.config = config;
    }

    /// Runs `kernel` over a `width × height` image in tiles, binding the buffers of `buffers`
    /// (and the tile parameters at the kernel's tile binding); `frame` goes to
    /// [`TileParams::frame`]. Calls `progress(done, total)` once with `done = 0` before the first
    /// batch and after every completed batch.
    pub fn dispatch(
        &mut self,
        gpu: &Gpu,
        kernel: &Kernel,
        buffers: &BufferSet,
        [width, height]: [u32; 2],
        frame: u32,
        progress: &mut dyn FnMut(u32, u32),
    ) -> Result<DispatchReport, DispatchError> {
        let config = self.config;
        check_config(&config)?;
        let Some(tile_binding) = kernel.tile_binding() else {
            return Err(DispatchError::NoTileBinding {
                kernel: kernel.label().to_string(),
            });
        };
        let tiles = plan_tiles(width, height, config.tile_width, config.tile_height, frame);
        let total = u32::try_from(tiles.len()).unwrap_or(u32::MAX);
        let mut report = DispatchReport {
            tiles: total,
            ..DispatchReport::default()
        };
        progress(0, total);
        if tiles.is_empty() {
            return Ok(report);
        }

        check_workgroups(gpu, kernel, &config)?;
        let (params, stride) = self.upload_tiles(gpu, &tiles)?;
        let bind_group = bind_group(
            gpu,
            kernel,
            buffers,
            Some((tile_binding, tile_resource(params))),
        )?;
        // Flush the pending uploads first so their cost is not counted as dispatch time.
        report.flush_ms = flush_uploads(gpu)?;

        let start = Instant::now();
        let mut done = 0u32;
        for batch in tiles.chunks(config.tiles_per_batch as usize) {
            let ((), error) = gpu.scoped(|| {
                let mut encoder =
                    gpu.device()
                        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                            label: Some(kernel.label()),
                        });
                {
                    let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                        label: Some(kernel.label()),
                        timestamp_writes: None,
                    });
                    pass.set_pipeline(kernel.pipeline());
                    for tile in batch {
                        // Fits: the buffer size was checked against u32 offsets in params_buffer.
                        let offset = (u64::from(tile.tile_index) * stride) as u32;
                        pass.set_bind_group(0, &bind_group, &[offset]);
                        let [x, y] = tile_workgroups(kernel, tile);
                        pass.dispatch_workgroups(x, y, 1);
                    }
                }
                gpu.queue().submit([encoder.finish()]);
            });
            wgpu_result("tile dispatch", error)?;
            wait(gpu)?;
            done += batch.len() as u32;
            report.batches += 1;
            progress(done, total);
        }
        report.dispatch_ms = elapsed_ms(start);
        Ok(report)
    }

    /// Writes the parameters of `tiles` into the tile uniform buffer, one record every `stride`
    /// bytes (the device's uniform offset alignment), so tile `i` is bound at offset
    /// `i * stride`; returns the buffer and the stride.
    fn upload_tiles(
        &mut self,
        gpu: &Gpu,
        tiles: &[TileParams],
    ) -> Result<(&wgpu::Buffer, u64), DispatchError> {
        let stride = (std::mem::size_of::<TileParams>() as u64).next_multiple_of(u64::from(
            gpu.limits().min_uniform_buffer_offset_alignment.max(1),
        ));
        let params = self.params_buffer(gpu, stride * tiles.len() as u64)?;
        let mut bytes = vec![0u8; (stride * tiles.len() as u64) as usize];
        for (chunk, tile) in bytes.chunks_exact_mut(stride as usize).zip(tiles) {
            chunk[..std::mem::size_of::<TileParams>()].copy_from_slice(bytemuck::bytes_of(tile));
        }
        let ((), error) = gpu.scoped(|| gpu.queue().write_buffer(params, 0, &bytes));
        wgpu_result("tile parameter upload", error)?;
        Ok((params, stride))
    }

    /// The tile uniform buffer, grown (reallocated) only when `size` exceeds it.
    fn params_buffer(&mut self, gpu: &Gpu, size: u64) -> Result<&wgpu::Buffer, DispatchError> {
        if size > u64::from(u32::MAX) || size > gpu.limits().max_buffer_size {
            return Err(DispatchError::TooManyTiles { bytes: size });
        }
        let too_small = self.params.as_ref().is_none_or(|b| b.size() < size);
        if too_small {
            let (buffer, error) = gpu.scoped(|| {
                gpu.device().create_buffer(&wgpu::BufferDescriptor {
                    label: Some("rtc tile parameters"),
                    size,
                    usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                })
            });
            wgpu_result("tile parameter allocation", error)?;
            self.params = Some(buffer);
        }
        self.params.as_ref().ok_or(DispatchError::Wgpu {
            stage: "tile parameter allocation",
            message: "no buffer".to_string(),
        })
    }
}

/// Dispatches a kernel without a tile binding once with `workgroups` groups, waits for it and
/// returns the milliseconds from submit to completion.
pub fn dispatch_once(
    gpu: &Gpu,
    kernel: &Kernel,
    buffers: &BufferSet,
    workgroups: [u32; 3],
) -> Result<f64, DispatchError> {
    if kernel.tile_binding().is_some() {
        return Err(DispatchError::NeedsTiles {
            kernel: kernel.label().to_string(),
        });
    }
    let limit = gpu.limits().max_compute_workgroups_per_dimension;
    if let Some(&count) = workgroups.iter().find(|&&n| n > limit) {
        return Err(DispatchError::TooManyWorkgroups {
            kernel: kernel.label().to_string(),
            count,
            limit,
        });
    }
    let bind_group = bind_group(gpu, kernel, buffers, None)?;
    let start = Instant::now();
    let ((), error) = gpu.scoped(|| {
        let mut encoder = gpu
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some(kernel.label()),
            });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some(kernel.label()),
                timestamp_writes: None,
            });
            pass.set_pipeline(kernel.pipeline());
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(workgroups[0], workgroups[1], workgroups[2]);
        }
        gpu.queue().submit([encoder.finish()]);
    });
    wgpu_result("dispatch", error)?;
    wait(gpu)?;
    Ok(elapsed_ms(start))
}

/// Copies the first `size` bytes of `buffer` (which needs `COPY_SRC` usage; every storage buffer
/// of a [`BufferSet`] has it) into host memory.
pub fn read_buffer(gpu: &Gpu, buffer: &wgpu::Buffer, size: u64) -> Result<Vec<u8>, DispatchError> {
    read_mapped(gpu, buffer, size, <[u8]>::to_vec)
}

/// Reads back the whole bound range of `binding` as `vec4<f32>` values (e.g. the accumulation
/// buffer: rgb = radiance sum, a = sample count). A trailing partial element is dropped.
pub fn read_vec4_f32(
    gpu: &Gpu,
    buffers: &BufferSet,
    binding: u32,
) -> Result<Vec<[f32; 4]>, DispatchError> {
    read_vec4_f32_prefix(gpu, buffers, binding, u64::MAX)
}

/// Reads back the first `count` `vec4<f32>` values of `binding` (fewer when its bound range is
/// shorter): a preview's pixels at the start of the accumulation buffer.
pub fn read_vec4_f32_prefix(
    gpu: &Gpu,
    buffers: &BufferSet,
    binding: u32,
    count: u64,
) -> Result<Vec<[f32; 4]>, DispatchError> {
    let (buffer, size) = vec4_binding(buffers, binding)?;
    read_mapped(gpu, buffer, size.min(count.saturating_mul(16)), vec4s_from)
}

/// The buffer at `binding` of `buffers` and its bound size rounded down to whole `vec4f`s.
fn vec4_binding(buffers: &BufferSet, binding: u32) -> Result<(&wgpu::Buffer, u64), DispatchError> {
    let (Some(buffer), Some(size)) = (buffers.buffer(binding), buffers.bound_size(binding)) else {
        return Err(BufferError::Missing {
            set: buffers.label().to_string(),
            binding,
        }
        .into());
    };
    Ok((buffer, size - size % 16))
}

/// Whole `vec4f`s from read-back bytes: one copy into typed memory, so no alignment assumption
/// about the mapping.
fn vec4s_from(bytes: &[u8]) -> Vec<[f32; 4]> {
    let whole = bytes.len() - bytes.len() % 16;
    let mut out = vec![[0f32; 4]; whole / 16];
    bytemuck::cast_slice_mut::<[f32; 4], u8>(&mut out).copy_from_slice(&bytes[..whole]);
    out
}

/// Copies `size` bytes of `buffer` into a staging buffer, maps it and hands the bytes to
/// `consume`. `size` is rounded up to a multiple of 4 for the copy; `consume` sees exactly `size`.
fn read_mapped<T>(
    gpu: &Gpu,
    buffer: &wgpu::Buffer,
    size: u64,
    consume: impl FnOnce(&[u8]) -> T,
) -> Result<T, DispatchError> {
    match copy_to_staging(gpu, buffer, size)? {
        Some(staging) => map_read(gpu, &staging, size, consume),
        None => Ok(consume(&[])),
    }
}

/// [`read_buffer`] without blocking, for the web (`wasm32`): the copy is submitted and the
/// mapping awaited (the browser completes it; there is no poll to call).
#[cfg(target_arch = "wasm32")]
pub async fn read_buffer_async(
    gpu: &Gpu,
    buffer: &wgpu::Buffer,
    size: u64,
) -> Result<Vec<u8>, DispatchError> {
    let Some(staging) = copy_to_staging(gpu, buffer, size)? else {
        return Ok(Vec::new());
    };
    let (sender, receiver) = super::web::oneshot();
    staging.map_async(wgpu::MapMode::Read, .., move |result| sender.send(result));
    let map_error = |message: String| DispatchError::Map { size, message };
    match receiver.await {
        Some(Ok(())) => {}
        Some(Err(e)) => return Err(map_error(error_chain(&e))),
        None => return Err(map_error("the mapping was dropped".to_string())),
    }
    let bytes = {
        let view = staging
            .get_mapped_range(..)
            .map_err(|e| map_error(error_chain(&e)))?;
        view[..size as usize].to_vec()
    };
    staging.unmap();
    Ok(bytes)
}

/// [`read_vec4_f32`] without blocking, for the web (`wasm32`).
#[cfg(target_arch = "wasm32")]
pub async fn read_vec4_f32_async(
    gpu: &Gpu,
    buffers: &BufferSet,
    binding: u32,
) -> Result<Vec<[f32; 4]>, DispatchError> {
    let (buffer, size) = vec4_binding(buffers, binding)?;
    Ok(vec4s_from(&read_buffer_async(gpu, buffer, size).await?))
}

/// Copies `size` bytes of `buffer` (rounded up to a multiple of 4) into a new `MAP_READ`
/// staging buffer and submits the copy; `None` when there is nothing to copy.
fn copy_to_staging(
    gpu: &Gpu,
    buffer: &wgpu::Buffer,
    size: u64,
) -> Result<Option<wgpu::Buffer>, DispatchError> {
    let copy_size = size.next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT);
    if copy_size == 0 {
        return Ok(None);
    }
    if copy_size > buffer.size() {
        return Err(DispatchError::Map {
            size,
            message: format!("the buffer holds only {} bytes", buffer.size()),
        });
    }
    let (staging, error) = gpu.scoped(|| {
        let staging = gpu.device().create_buffer(&wgpu::BufferDescriptor {
            label: Some("rtc read-back"),
            size: copy_size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = gpu
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("rtc read-back"),
            });
        encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, Some(copy_size));
        gpu.queue().submit([encoder.finish()]);
        staging
    });
    wgpu_result("read-back copy", error)?;
    Ok(Some(staging))
}

/// Waits for the submitted work, maps the `MAP_READ` buffer `staging` and hands its first `size`
/// bytes to `consume`, then unmaps it.
fn map_read<T>(
    gpu: &Gpu,
    staging: &wgpu::Buffer,
    size: u64,
    consume: impl FnOnce(&[u8]) -> T,
) -> Result<T, DispatchError> {
    // A page cannot block for a mapping: read back with `read_buffer_async` there.
    #[cfg(target_arch = "wasm32")]
    {
        let _ = (gpu, staging, consume);
        Err(DispatchError::Map {
            size,
            message: "a blocking read-back is not possible on the web (the wavefront model's \
                      rounds read back mid-frame: use the megakernel there; custom geometry's \
                      bounds need the awaiting setup, `Renderer::new_async`)"
                .to_string(),
        })
    }
    #[cfg(not(target_arch = "wasm32"))]
    map_read_blocking(gpu, staging, size, consume)
}

/// [`map_read`] off the web: a channel and a blocking poll.
#[cfg(not(target_arch = "wasm32"))]
fn map_read_blocking<T>(
    gpu: &Gpu,
    staging: &wgpu::Buffer,
    size: u64,
    consume: impl FnOnce(&[u8]) -> T,
) -> Result<T, DispatchError> {
    let (sender, receiver) = mpsc::channel();
    staging.map_async(wgpu::MapMode::Read, .., move |result| {
        // The receiver outlives the wait below; a send error only means nobody listens.
        let _ = sender.send(result);
    });
    wait(gpu)?;
    let map_error = |message: String| DispatchError::Map { size, message };
    match receiver.recv() {
        Ok(Ok(())) => {}
        Ok(Err(e)) => return Err(map_error(error_chain(&e))),
        Err(e) => return Err(map_error(e.to_string())),
    }
    let value = {
        let view = staging
            .get_mapped_range(..)
            .map_err(|e| map_error(error_chain(&e)))?;
        consume(&view[..size as usize])
    };
    staging.unmap();
    Ok(value)
}

fn check_config(config: &TileConfig) -> Result<(), DispatchError> {
    let reason = if config.tile_width == 0 || config.tile_height == 0 {
        "tile width and height must be positive"
    } else if config.tile_width > MAX_TILE_SIDE || config.tile_height > MAX_TILE_SIDE {
        "tile width and height must be at most 2048"
    } else if config.tiles_per_batch == 0 {
        "tiles_per_batch must be positive"
    } else {
        return Ok(());
    };
    Err(DispatchError::BadTileConfig {
        config: *config,
        reason,
    })
}

/// Refuses `kernel` when `config`'s tiles need more workgroups in one dimension than the device
/// allows.
fn check_workgroups(gpu: &Gpu, kernel: &Kernel, config: &TileConfig) -> Result<(), DispatchError> {
    let limit = gpu.limits().max_compute_workgroups_per_dimension;
    let [wx, wy, _] = kernel.workgroup_size();
    for count in [
        config.tile_width.div_ceil(wx.max(1)),
        config.tile_height.div_ceil(wy.max(1)),
    ] {
        if count > limit {
            return Err(DispatchError::TooManyWorkgroups {
                kernel: kernel.label().to_string(),
                count,
                limit,
            });
        }
    }
    Ok(())
}

/// The workgroups (x, y) that cover `tile` with `kernel`'s workgroup size.
fn tile_workgroups(kernel: &Kernel, tile: &TileParams) -> [u32; 2] {
    let [wx, wy, _] = kernel.workgroup_size();
    [
        tile.extent[0].div_ceil(wx.max(1)),
        tile.extent[1].div_ceil(wy.max(1)),
    ]
}

/// One tile's record of the tile uniform buffer `params`, for a bind group entry (bound with a
/// dynamic offset per tile).
fn tile_resource(params: &wgpu::Buffer) -> wgpu::BindingResource<'_> {
    wgpu::BindingResource::Buffer(wgpu::BufferBinding {
        buffer: params,
        offset: 0,
        size: wgpu::BufferSize::new(std::mem::size_of::<TileParams>() as u64),
    })
}

/// Submits the pending buffer uploads and waits for them, so their cost is not counted as
/// dispatch time; returns the milliseconds it took.
fn flush_uploads(gpu: &Gpu) -> Result<f64, DispatchError> {
    let start = Instant::now();
    let ((), error) = gpu.scoped(|| {
        gpu.queue().submit([]);
    });
    wgpu_result("upload flush", error)?;
    wait(gpu)?;
    Ok(elapsed_ms(start))
}

/// Bind group 0 for `kernel`: every listed binding from `buffers`, except the tile binding.
fn bind_group(
    gpu: &Gpu,
    kernel: &Kernel,
    buffers: &BufferSet,
    tile: Option<(u32, wgpu::BindingResource<'_>)>,
) -> Result<wgpu::BindGroup, DispatchError> {
    let mut entries = Vec::with_capacity(kernel.bindings().len());
    let mut tile = tile;
    for desc in kernel.bindings() {
        if let Some((binding, resource)) = tile.take_if(|(b, _)| *b == desc.binding) {
            entries.push(wgpu::BindGroupEntry { binding, resource });
            continue;
        }
        let resource = buffers.binding_resource(desc.binding)?;
        if let Some(found) = buffers.kind(desc.binding) {
            if found.is_storage() != desc.kind.is_storage() {
                return Err(DispatchError::BufferKind {
                    kernel: kernel.label().to_string(),
                    binding: desc.binding,
                    name: desc.name.clone(),
                    expected: desc.kind,
                    found,
                });
            }
        }
        entries.push(wgpu::BindGroupEntry {
            binding: desc.binding,
            resource,
        });
    }
    let (group, error) = gpu.scoped(|| {
        gpu.device().create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(kernel.label()),
            layout: kernel.bind_group_layout(),
            entries: &entries,
        })
    });
    wgpu_result("bind group creation", error)?;
    Ok(group)
}

fn wgpu_result(stage: &'static str, error: Option<String>) -> Result<(), DispatchError> {
    match error {
        Some(message) => Err(DispatchError::Wgpu { stage, message }),
        None => Ok(()),
    }
}

fn wait(gpu: &Gpu) -> Result<(), DispatchError> {
    gpu.wait_idle().map_err(|e| DispatchError::Poll {
        message: error_chain(&e),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cpu_adapters_get_bigger_tiles() {
        let mut adapter = super::super::AdapterDescription {
            name: "llvmpipe".into(),
            backend: wgpu::Backend::Vulkan,
            device_type: wgpu::DeviceType::Cpu,
            driver: String::new(),
            driver_info: String::new(),
            vendor: 0,
            device: 0,
        };
        assert_eq!(TileConfig::for_adapter(&adapter).tile_width, 1024);
        adapter.device_type = wgpu::DeviceType::DiscreteGpu;
        assert_eq!(TileConfig::for_adapter(&adapter), TileConfig::default());
        assert!(check_config(&TileConfig::default()).is_ok());
        let zero = TileConfig {
            tiles_per_batch: 0,
            ..TileConfig::default()
        };
        assert!(matches!(
            check_config(&zero),
            Err(DispatchError::BadTileConfig { .. })
        ));
        let huge = TileConfig {
            tile_width: MAX_TILE_SIDE + 1,
            ..TileConfig::default()
        };
        assert!(matches!(
            check_config(&huge),
            Err(DispatchError::BadTileConfig { .. })
        ));
    }

    #[test]
    fn tiles_cover_an_odd_image_once() {
        let tiles = plan_tiles(37, 23, 16, 16, 7);
        assert_eq!(tiles.len(), 3 * 2);
        let mut hits = vec![0u32; 37 * 23];
        for t in &tiles {
            for y in t.origin[1]..t.origin[1] + t.extent[1] {
                for x in t.origin[0]..t.origin[0] + t.extent[0] {
                    hits[(y * 37 + x) as usize] += 1;
                }
            }
            assert_eq!(t.frame, 7);
            assert_eq!(t.image_size, [37, 23]);
        }
        assert!(hits.iter().all(|&h| h == 1));
        assert_eq!(tiles[2].extent, [5, 16]);
        assert_eq!(tiles[5].extent, [5, 7]);
        assert!(plan_tiles(0, 5, 16, 16, 0).is_empty());
    }

    #[test]
    fn tile_params_match_wgsl_layout() {
        let module =
            naga::front::wgsl::parse_str(TILE_PARAMS_WGSL).expect("TILE_PARAMS_WGSL parses");
        let mut layouter = naga::proc::Layouter::default();
        layouter
            .update(module.to_ctx())
            .expect("TILE_PARAMS_WGSL lays out");
        let (handle, ty) = module
            .types
            .iter()
            .find(|(_, ty)| ty.name.as_deref() == Some("TileParams"))
            .expect("TileParams is declared");
        assert_eq!(
            layouter[handle].size as usize,
            std::mem::size_of::<TileParams>()
        );
        let naga::TypeInner::Struct { members, .. } = &ty.inner else {
            panic!("TileParams is a struct");
        };
        let offsets: Vec<(String, u32)> = members
            .iter()
            .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
            .collect();
        let expected = [
            ("origin", std::mem::offset_of!(TileParams, origin)),
            ("extent", std::mem::offset_of!(TileParams, extent)),
            ("image_size", std::mem::offset_of!(TileParams, image_size)),
            ("tile_index", std::mem::offset_of!(TileParams, tile_index)),
            ("frame", std::mem::offset_of!(TileParams, frame)),
        ];
        assert_eq!(offsets.len(), expected.len());
        for ((name, offset), (want_name, want_offset)) in offsets.iter().zip(expected) {
            assert_eq!(name, want_name);
            assert_eq!(*offset as usize, want_offset);
        }
    }
}
