//! Persistent GPU buffers keyed by binding number, re-uploaded only when their data changed.
//!
//! A [`BufferSet`] lives across frames. Each binding owns one `wgpu::Buffer`; an upload first
//! decides whether anything changed, by one of two rules the caller picks per call:
//! - [`BufferSet::upload`]: a 64-bit content hash plus the length. Costs one pass over the data
//!   on the CPU, saves the transfer when nothing changed. The hash is foldhash's quality variant
//!   (fast, not cryptographic): an accidental collision is astronomically unlikely, a crafted one
//!   is not, which is irrelevant for scene data the process produced itself.
//! - [`BufferSet::upload_generation`]: a caller-supplied generation counter plus the length; no
//!   hashing. Use it for big scene data whose owner knows when it changes.
//!
//! Invariants:
//! - A buffer is reallocated only when the new (padded) size exceeds its capacity or its kind
//!   changes; a smaller upload reuses it, and the binding is then bound with the smaller size
//!   (so `arrayLength` in the shader sees the new length).
//! - Sizes are padded with zeros to a multiple of 4 bytes (16 for uniforms) and to at least the
//!   binding's `min_size`, because wgpu needs copy sizes in multiples of 4 and non-empty bindings.
//! - Data larger than the device allows for one binding is refused with
//!   [`BufferError::TooLarge`], naming the binding, the limit and the size; the caller may split
//!   it. Nothing is uploaded in that case.
//! - [`UploadStats`] count what happened since [`BufferSet::begin_frame`], so tests and the CLI
//!   can see that an unchanged frame uploads zero bytes.
//! - New buffers are zero-filled (wgpu guarantees it), which is what accumulation targets need.

use std::collections::BTreeMap;
use std::hash::{BuildHasher, Hasher};
use web_time::Instant;

use super::pipeline::{BindingDesc, BindingKind};
use super::{elapsed_ms, Gpu};

/// wgpu's copy alignment (`COPY_BUFFER_ALIGNMENT`).
const COPY_ALIGN: u64 = 4;
/// Uniform buffers are padded to a multiple of this (the largest WGSL uniform alignment).
const UNIFORM_ALIGN: u64 = 16;

/// The limits a [`BufferSet`] enforces; taken from the device, replaceable for tests.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferLimits {
    /// Largest storage binding in bytes.
    pub max_storage_buffer_binding_size: u64,
    /// Largest uniform binding in bytes.
    pub max_uniform_buffer_binding_size: u64,
    /// Largest buffer in bytes.
    pub max_buffer_size: u64,
}

impl BufferLimits {
    /// The limits of `gpu`'s device.
    pub fn of(gpu: &Gpu) -> Self {
        let l = gpu.limits();
        Self {
            max_storage_buffer_binding_size: l.max_storage_buffer_binding_size,
            max_uniform_buffer_binding_size: l.max_uniform_buffer_binding_size,
            max_buffer_size: l.max_buffer_size,
        }
    }
}

/// Why data could not be placed in a buffer.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum BufferError {
    /// The data exceeds a device limit.
    #[error(
        "binding {binding} (`{name}`): {size} bytes exceed the device's {limit_name} of {limit} \
         bytes; split the data or choose an adapter with larger limits"
    )]
    TooLarge {
        /// The binding.
        binding: u32,
        /// Its name.
        name: String,
        /// The size in bytes asked for (the data's length, or the binding's `min_size` if larger).
        size: u64,
        /// The limit in bytes.
        limit: u64,
        /// Which limit (`max_storage_buffer_binding_size`, ...).
        limit_name: &'static str,
    },
    /// The binding has no buffer in this set.
    #[error("binding {binding} has no buffer in the set `{set}`")]
    Missing {
        /// The set's label.
        set: String,
        /// The binding.
        binding: u32,
    },
    /// wgpu reported an error while creating or writing the buffer.
    #[error("binding {binding} (`{name}`): wgpu error: {message}")]
    Wgpu {
        /// The binding.
        binding: u32,
        /// Its name.
        name: String,
        /// wgpu's message.
        message: String,
    },
}

/// What one upload call did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UploadOutcome {
    /// Same data as last time: nothing was transferred.
    Unchanged,
    /// Written into the existing buffer.
    Uploaded,
    /// A new buffer was allocated (first use, growth or kind change) and written.
    Reallocated,
}

/// What happened since [`BufferSet::begin_frame`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UploadStats {
    /// Bytes handed to `queue.write_buffer` (padding included).
    pub bytes_uploaded: u64,
    /// Buffers written.
    pub buffers_uploaded: u32,
    /// Upload calls that found the data unchanged.
    pub buffers_unchanged: u32,
    /// Buffers (re)allocated.
    pub buffers_allocated: u32,
    /// Bytes of those allocations.
    pub bytes_allocated: u64,
    /// CPU time in upload calls (hashing, padding, `write_buffer` staging); the transfer itself
    /// runs at the next submit.
    pub upload_ms: f64,
}

/// How an entry's content was last identified.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Version {
    /// Content hash and unpadded length.
    Hash { hash: u64, len: u64 },
    /// Caller generation and unpadded length.
    Generation { generation: u64, len: u64 },
    /// Zero-filled by [`BufferSet::ensure_zeroed`] / [`BufferSet::clear`] (or written by the GPU).
    Zeroed { size: u64 },
}

#[derive(Debug)]
struct Entry {
    name: String,
    kind: BindingKind,
    buffer: wgpu::Buffer,
    capacity: u64,
    bound_size: u64,
    version: Version,
    /// Bytes from the start of the buffer that may hold something other than zeros (what the
    /// last whole upload wrote): a shorter upload zeroes what is left of them below the bound
    /// size, and writes nothing beyond. A buffer the GPU may write is always written whole.
    nonzero: u64,
}

/// GPU buffers keyed by binding, kept across frames.
#[derive(Debug)]
pub struct BufferSet {
    label: String,
    limits: BufferLimits,
    entries: BTreeMap<u32, Entry>,
    stats: UploadStats,
}

impl BufferSet {
    /// An empty set enforcing `gpu`'s limits.
    pub fn new(gpu: &Gpu, label: impl Into<String>) -> Self {
        Self {
            label: label.into(),
            limits: BufferLimits::of(gpu),
            entries: BTreeMap::new(),
            stats: UploadStats::default(),
        }
    }

    /// Replaces the enforced limits (tests fake tiny limits; a caller may want to be stricter).
    /// Limits above the device's are not checked here, but wgpu will still refuse them.
    pub fn with_limits(mut self, limits: BufferLimits) -> Self {
        self.limits = limits;
        self
    }

    /// The enforced limits.
    pub fn limits(&self) -> BufferLimits {
        self.limits
    }

    /// Resets the statistics; call once per frame before uploading.
    pub fn begin_frame(&mut self) {
        self.stats = UploadStats::default();
    }

    /// What happened since the last [`begin_frame`](Self::begin_frame).
    pub fn stats(&self) -> UploadStats {
        self.stats
    }

    /// Uploads `data` for `desc.binding` unless its content hash and length match the last
    /// upload's.
    pub fn upload(
        &mut self,
        gpu: &Gpu,
        desc: &BindingDesc,
        data: &[u8],
    ) -> Result<UploadOutcome, BufferError> {
        let start = Instant::now();
        let version = Version::Hash {
            hash: content_hash(data),
            len: data.len() as u64,
        };
        let result = self.write(gpu, desc, data, version);
        self.stats.upload_ms += elapsed_ms(start);
        result
    }

    /// Uploads `data` for `desc.binding` unless `generation` and the length match the last
    /// upload's. The caller bumps the generation whenever the data changes.
    pub fn upload_generation(
        &mut self,
        gpu: &Gpu,
        desc: &BindingDesc,
        data: &[u8],
        generation: u64,
    ) -> Result<UploadOutcome, BufferError> {
        let start = Instant::now();
        let version = Version::Generation {
            generation,
            len: data.len() as u64,
        };
        let result = self.write(gpu, desc, data, version);
        self.stats.upload_ms += elapsed_ms(start);
        result
    }

    /// Like [`upload_generation`](Self::upload_generation), but when the buffer holds exactly
    /// generation `base` of data of the same length, writes only the byte `ranges` of `data`
    /// (widened to 4-byte boundaries, merged where they touch) that changed since `base`, and
    /// records `generation`. Otherwise it uploads the whole of `data`.
    pub fn upload_ranges(
        &mut self,
        gpu: &Gpu,
        desc: &BindingDesc,
        data: &[u8],
        generation: u64,
        base: u64,
        ranges: &[std::ops::Range<u64>],
    ) -> Result<UploadOutcome, BufferError> {
        let len = data.len() as u64;
        let holds_base = self.entries.get(&desc.binding).is_some_and(|e| {
            e.kind == desc.kind
                && e.version
                    == Version::Generation {
                        generation: base,
                        len,
                    }
                && e.bound_size == padded_size(desc, len)
        });
        if !holds_base {
            return self.upload_generation(gpu, desc, data, generation);
        }
        let start = Instant::now();
        let mut spans: Vec<std::ops::Range<u64>> = ranges
            .iter()
            .map(|r| (r.start & !3)..(r.end.min(len).next_multiple_of(4)).min(len))
            .filter(|r| r.start < r.end)
            .collect();
        spans.sort_by_key(|r| r.start);
        let mut merged: Vec<std::ops::Range<u64>> = Vec::with_capacity(spans.len());
        for r in spans {
            match merged.last_mut() {
                Some(last) if r.start <= last.end => last.end = last.end.max(r.end),
                _ => merged.push(r),
            }
        }
        let Some(entry) = self.entries.get_mut(&desc.binding) else {
            return Err(self.missing(desc.binding));
        };
        let mut written = 0;
        let ((), error) = gpu.scoped(|| {
            for r in &merged {
                if let Some(bytes) = data.get(r.start as usize..r.end as usize) {
                    gpu.queue().write_buffer(&entry.buffer, r.start, bytes);
                    written += r.end - r.start;
                }
            }
        });
        if let Some(message) = error {
            return Err(BufferError::Wgpu {
                binding: desc.binding,
                name: desc.name.clone(),
                message,
            });
        }
        entry.version = Version::Generation { generation, len };
        self.stats.bytes_uploaded += written;
        self.stats.buffers_uploaded += u32::from(written > 0);
        self.stats.upload_ms += elapsed_ms(start);
        Ok(UploadOutcome::Uploaded)
    }

    /// Makes sure `desc.binding` has a buffer of (padded) `size` bytes for the GPU to write,
    /// such as an accumulation target. A new or grown buffer starts zeroed; an existing buffer of
    /// the same size keeps its contents (so accumulation continues across frames).
    pub fn ensure_zeroed(
        &mut self,
        gpu: &Gpu,
        desc: &BindingDesc,
        size: u64,
    ) -> Result<UploadOutcome, BufferError> {
        let requested = size;
        let size = padded_size(desc, size);
        self.check_limits(desc, size, requested)?;
        if let Some(entry) = self.entries.get(&desc.binding) {
            if entry.kind == desc.kind && entry.bound_size == size {
                return Ok(UploadOutcome::Unchanged);
            }
        }
        let realloc = self.needs_realloc(desc, size);
        if realloc {
            self.allocate(gpu, desc, size)?;
        } else {
            self.clear_range(gpu, desc.binding, size)?;
        }
        if let Some(entry) = self.entries.get_mut(&desc.binding) {
            entry.bound_size = size;
            entry.version = Version::Zeroed { size };
        }
        Ok(if realloc {
            UploadOutcome::Reallocated
        } else {
            UploadOutcome::Uploaded
        })
    }

    /// Zero-fills the bound range of `binding` on the GPU (e.g. to restart accumulation).
    pub fn clear(&mut self, gpu: &Gpu, binding: u32) -> Result<(), BufferError> {
        let size = self
            .entries
            .get(&binding)
            .map(|e| e.bound_size)
            .ok_or_else(|| self.missing(binding))?;
        self.clear_range(gpu, binding, size)?;
        if let Some(entry) = self.entries.get_mut(&binding) {
            entry.version = Version::Zeroed { size };
        }
        Ok(())
    }

    /// The buffer bound at `binding`, if any.
    pub fn buffer(&self, binding: u32) -> Option<&wgpu::Buffer> {
        self.entries.get(&binding).map(|e| &e.buffer)
    }

    /// The size in bytes `binding` is bound with (the padded length of the last upload).
    pub fn bound_size(&self, binding: u32) -> Option<u64> {
        self.entries.get(&binding).map(|e| e.bound_size)
    }

    /// The kind `binding`'s buffer was created for.
    pub fn kind(&self, binding: u32) -> Option<BindingKind> {
        self.entries.get(&binding).map(|e| e.kind)
    }

    /// The whole bound range of `binding`, ready for a bind group entry.
    pub fn binding_resource(&self, binding: u32) -> Result<wgpu::BindingResource<'_>, BufferError> {
        let entry = self
            .entries
            .get(&binding)
            .ok_or_else(|| self.missing(binding))?;
        Ok(wgpu::BindingResource::Buffer(wgpu::BufferBinding {
            buffer: &entry.buffer,
            offset: 0,
            size: wgpu::BufferSize::new(entry.bound_size),
        }))
    }

    /// Drops the buffer of `binding` (returns whether there was one).
    pub fn remove(&mut self, binding: u32) -> bool {
        self.entries.remove(&binding).is_some()
    }

    /// Bytes of GPU memory held by the set.
    pub fn allocated_bytes(&self) -> u64 {
        self.entries.values().map(|e| e.capacity).sum()
    }

    /// The set's label.
    pub fn label(&self) -> &str {
        &self.label
    }

    fn write(
        &mut self,
        gpu: &Gpu,
        desc: &BindingDesc,
        data: &[u8],
        version: Version,
    ) -> Result<UploadOutcome, BufferError> {
        let size = padded_size(desc, data.len() as u64);
        self.check_limits(desc, size, data.len() as u64)?;
        if let Some(entry) = self.entries.get(&desc.binding) {
            if entry.kind == desc.kind && entry.version == version && entry.bound_size == size {
                self.stats.buffers_unchanged += 1;
                return Ok(UploadOutcome::Unchanged);
            }
        }
        let realloc = self.needs_realloc(desc, size);
        if realloc {
            self.allocate(gpu, desc, size)?;
        }
        let Some(entry) = self.entries.get_mut(&desc.binding) else {
            return Err(self.missing(desc.binding));
        };
        // The data, then zeros over what an earlier upload left below the bound size; a new
        // buffer is zeroed already, so the padding up to `size` (a uniform table's 64 KiB, say)
        // is not written again.
        let data_len = (data.len() as u64).next_multiple_of(COPY_ALIGN).min(size);
        let upto = if desc.kind == BindingKind::StorageReadWrite {
            size
        } else {
            data_len.max(entry.nonzero.min(size))
        };
        let padded;
        let bytes = if data.len() as u64 == upto {
            data
        } else {
            let mut v = Vec::with_capacity(upto as usize);
            v.extend_from_slice(data);
            v.resize(upto as usize, 0);
            padded = v;
            &padded
        };
        let ((), error) = gpu.scoped(|| gpu.queue().write_buffer(&entry.buffer, 0, bytes));
        if let Some(message) = error {
            return Err(BufferError::Wgpu {
                binding: desc.binding,
                name: desc.name.clone(),
                message,
            });
        }
        entry.bound_size = size;
        entry.version = version;
        entry.nonzero = if desc.kind == BindingKind::StorageReadWrite {
            size
        } else {
            data_len
        };
        entry.name.clone_from(&desc.name);
        self.stats.bytes_uploaded += upto;
        self.stats.buffers_uploaded += 1;
        Ok(if realloc {
            UploadOutcome::Reallocated
        } else {
            UploadOutcome::Uploaded
        })
    }

    /// Checks the padded size against the limits; errors report the caller's `requested` size.
    fn check_limits(
        &self,
        desc: &BindingDesc,
        size: u64,
        requested: u64,
    ) -> Result<(), BufferError> {
        let (limit, limit_name) = if desc.kind.is_storage() {
            (
                self.limits.max_storage_buffer_binding_size,
                "max_storage_buffer_binding_size",
            )
        } else {
            (
                self.limits.max_uniform_buffer_binding_size,
                "max_uniform_buffer_binding_size",
            )
        };
        let (limit, limit_name) = if self.limits.max_buffer_size < limit {
            (self.limits.max_buffer_size, "max_buffer_size")
        } else {
            (limit, limit_name)
        };
        if size > limit {
            // Report what the caller asked for (or the binding's minimum when that is larger):
            // limits are multiples of 16 in practice, so alignment padding alone never fails.
            return Err(BufferError::TooLarge {
                binding: desc.binding,
                name: desc.name.clone(),
                size: requested.max(desc.min_size),
                limit,
                limit_name,
            });
        }
        Ok(())
    }

    fn needs_realloc(&self, desc: &BindingDesc, size: u64) -> bool {
        match self.entries.get(&desc.binding) {
            Some(entry) => entry.kind != desc.kind || entry.capacity < size,
            None => true,
        }
    }

    fn allocate(&mut self, gpu: &Gpu, desc: &BindingDesc, size: u64) -> Result<(), BufferError> {
        let usage = match desc.kind {
            BindingKind::Uniform => wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            BindingKind::StorageRead | BindingKind::StorageReadWrite => {
                wgpu::BufferUsages::STORAGE
                    | wgpu::BufferUsages::COPY_DST
                    | wgpu::BufferUsages::COPY_SRC
            }
        };
        let label = format!("{}: {} (binding {})", self.label, desc.name, desc.binding);
        let (buffer, error) = gpu.scoped(|| {
            gpu.device().create_buffer(&wgpu::BufferDescriptor {
                label: Some(&label),
                size,
                usage,
                mapped_at_creation: false,
            })
        });
        if let Some(message) = error {
            return Err(BufferError::Wgpu {
                binding: desc.binding,
                name: desc.name.clone(),
                message,
            });
        }
        self.stats.buffers_allocated += 1;
        self.stats.bytes_allocated += size;
        self.entries.insert(
            desc.binding,
            Entry {
                name: desc.name.clone(),
                kind: desc.kind,
                buffer,
                capacity: size,
                bound_size: size,
                version: Version::Zeroed { size },
                nonzero: 0,
            },
        );
        Ok(())
    }

    fn clear_range(&self, gpu: &Gpu, binding: u32, size: u64) -> Result<(), BufferError> {
        let entry = self
            .entries
            .get(&binding)
            .ok_or_else(|| self.missing(binding))?;
        let ((), error) = gpu.scoped(|| {
            let mut encoder =
                gpu.device()
                    .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                        label: Some("rtc clear"),
                    });
            encoder.clear_buffer(&entry.buffer, 0, Some(size));
            gpu.queue().submit([encoder.finish()]);
        });
        match error {
            Some(message) => Err(BufferError::Wgpu {
                binding,
                name: entry.name.clone(),
                message,
            }),
            None => Ok(()),
        }
    }

    fn missing(&self, binding: u32) -> BufferError {
        BufferError::Missing {
            set: self.label.clone(),
            binding,
        }
    }
}

/// The 64-bit content hash used for change detection (foldhash's quality variant, fixed seed,
/// so it is the same in every process).
fn content_hash(data: &[u8]) -> u64 {
    let mut hasher = foldhash::quality::FixedState::with_seed(0x7274_635f_6275_6673).build_hasher();
    hasher.write(data);
    hasher.finish()
}

/// `len` padded to the copy alignment (16 for uniforms) and to at least `desc.min_size` (and 4).
fn padded_size(desc: &BindingDesc, len: u64) -> u64 {
    let align = match desc.kind {
        BindingKind::Uniform => UNIFORM_ALIGN,
        _ => COPY_ALIGN,
    };
    let len = len.max(desc.min_size).max(COPY_ALIGN);
    len.div_ceil(align).saturating_mul(align)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn content_hash_sees_single_bit_changes() {
        let mut data = vec![0u8; 4096];
        let base = content_hash(&data);
        assert_eq!(base, content_hash(&data));
        for i in [0, 1, 17, 2048, 4095] {
            data[i] ^= 1;
            assert_ne!(content_hash(&data), base, "bit flip at {i}");
            data[i] ^= 1;
        }
        assert_ne!(content_hash(&data[..4092]), base);
    }

    #[test]
    fn padding_rules() {
        let s = BindingDesc::new(0, "s", BindingKind::StorageRead, 0);
        assert_eq!(padded_size(&s, 0), 4);
        assert_eq!(padded_size(&s, 5), 8);
        assert_eq!(padded_size(&s, 8), 8);
        let s16 = BindingDesc::new(0, "s", BindingKind::StorageRead, 16);
        assert_eq!(padded_size(&s16, 4), 16);
        let u = BindingDesc::new(0, "u", BindingKind::Uniform, 0);
        assert_eq!(padded_size(&u, 4), 16);
        assert_eq!(padded_size(&u, 20), 32);
    }
}
