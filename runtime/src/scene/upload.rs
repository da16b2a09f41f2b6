//! The GPU stage: the scene's entities in persistent GPU buffers, one per ABI binding the kernel
//! declares, re-uploaded only when their contents changed.
//!
//! Change detection: the big geometry buffers (`nodes`, `triangles`, `attributes`, `texels`) and
//! `params` are compared by the [`Versions`](super::Versions) the entity stage keeps, without
//! hashing; `frame` and `instances` by content hash (they are small, and `instances` switches
//! between object order for the bounds kernel and TLAS order for rendering). So moving an object
//! re-uploads `nodes` and `instances` (and `frame` only if the instance count changed) and nothing
//! else. Every upload reports what happened per binding ([`UploadReport`]).
//!
//! Invariants: only bindings in the list given to [`GpuScene::new`] get buffers; data above a
//! device limit is refused with `BufferError::TooLarge` naming the binding, before anything is
//! written (for the mesh and texture bindings, [`SceneError::BindingTooLarge`] also names the
//! largest mesh or texture in it: its file, and for a glTF mesh the mesh); `accum` and `counters` are zeroed by [`GpuScene::clear_accumulation`], never by an
//! upload of scene data; so is the wavefront model's `paths`, which is sized by
//! [`GpuScene::set_path_bytes`].

use rtc_compiler::abi;
use rtc_compiler::back::ResourceKind;

use super::entities::Entities;

/// Bytes of the `counters` binding ([`abi::COUNTER_WORDS`] words).
pub(crate) const COUNTER_BYTES: u64 = abi::COUNTER_WORDS as u64 * 4;

/// The kernel's counters, read back (indices from the ABI table).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    /// `COUNTER_NONFINITE`: samples that were not finite and were replaced by zero.
    pub nonfinite: u32,
    /// `COUNTER_RAYS`: rays traced (camera, secondary and shadow), wrapping.
    pub rays: u32,
    /// `COUNTER_SHADOW_OVERFLOW`: shadow queries answered "unoccluded" without tracing: past
    /// what a shading step of the wavefront model records, or past what one light program's
    /// sample records in the megakernel.
    pub shadow_overflow: u32,
}
use super::gpu_types::{element_size, record, struct_size, FrameUniforms, GpuInstance};
use super::tables::UniformTables;
use super::SceneError;
use crate::gpu::{
    read_buffer, read_vec4_f32_prefix, BindingDesc, BindingKind, BufferError, BufferLimits,
    BufferSet, Gpu, TileParams, UploadOutcome, UploadStats,
};

/// The runtime's description of an ABI binding (kind and one element as the minimum size).
pub fn runtime_binding(b: &abi::BindingDesc) -> BindingDesc {
    let kind = match b.kind {
        ResourceKind::Uniform => BindingKind::Uniform,
        ResourceKind::StorageRead => BindingKind::StorageRead,
        ResourceKind::StorageReadWrite => BindingKind::StorageReadWrite,
    };
    BindingDesc::new(b.binding, b.name, kind, element_size(b.element) as u64)
}

/// What one upload did, per binding, and the buffer set's statistics for it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct UploadReport {
    /// Each binding handled, by ABI name, with its outcome.
    pub outcomes: Vec<(&'static str, UploadOutcome)>,
    /// Bytes and buffers written, and CPU time.
    pub stats: UploadStats,
}

impl UploadReport {
    /// The outcome for the binding called `name`, if it was handled.
    pub fn outcome(&self, name: &str) -> Option<UploadOutcome> {
        self.outcomes
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, o)| *o)
    }

    /// Names of the bindings whose data was written.
    pub fn written(&self) -> Vec<&'static str> {
        self.outcomes
            .iter()
            .filter(|(_, o)| *o != UploadOutcome::Unchanged)
            .map(|(n, _)| *n)
            .collect()
    }
}

/// Which instance order an upload writes.
#[derive(Clone, Copy, PartialEq, Eq)]
enum InstanceOrder {
    Tlas,
    Objects,
}

/// The scene's GPU buffers.
#[derive(Debug)]
pub struct GpuScene {
    buffers: BufferSet,
    bindings: Vec<(&'static abi::BindingDesc, BindingDesc)>,
    /// Which tables are uniform buffers (the kernels' [`UniformTables`]).
    tables: UniformTables,
    /// Bytes of the wavefront model's `paths` binding (see [`GpuScene::set_path_bytes`]).
    path_bytes: u64,
}

/// `bindings` once each, with their runtime descriptions under `tables`, in binding order.
fn binding_list(
    bindings: &[&'static abi::BindingDesc],
    tables: UniformTables,
) -> Vec<(&'static abi::BindingDesc, BindingDesc)> {
    let mut list: Vec<(&'static abi::BindingDesc, BindingDesc)> = Vec::new();
    for &b in bindings {
        if !list.iter().any(|(have, _)| have.binding == b.binding) {
            list.push((b, tables.describe(b)));
        }
    }
    list.sort_by_key(|(b, _)| b.binding);
    list
}

impl GpuScene {
    /// Buffers for exactly these bindings (duplicates are kept once), with `gpu`'s limits, all
    /// of them where the kernel was compiled to have them (storage buffers but for `frame` and
    /// `tile`).
    pub fn new(gpu: &Gpu, bindings: &[&'static abi::BindingDesc]) -> Self {
        Self::with_tables(gpu, bindings, UniformTables::default())
    }

    /// [`new`](Self::new), with the tables in `tables` as uniform buffers (the kernels must have
    /// been specialised with the same [`UniformTables`]).
    pub fn with_tables(
        gpu: &Gpu,
        bindings: &[&'static abi::BindingDesc],
        tables: UniformTables,
    ) -> Self {
        Self {
            buffers: BufferSet::new(gpu, "rtc scene"),
            bindings: binding_list(bindings, tables),
            tables,
            path_bytes: 16,
        }
    }

    /// Which tables are uniform buffers.
    pub fn tables(&self) -> UniformTables {
        self.tables
    }

    /// Makes the set hold exactly `bindings` (a replaced kernel's), with `tables` as uniform
    /// buffers: buffers of bindings it keeps in the same kind stay, with their contents; the
    /// others are dropped or reallocated.
    pub fn rebind(&mut self, bindings: &[&'static abi::BindingDesc], tables: UniformTables) {
        self.tables = tables;
        let list = binding_list(bindings, tables);
        for (old, _) in &self.bindings {
            if !list.iter().any(|(b, _)| b.binding == old.binding) {
                self.buffers.remove(old.binding);
            }
        }
        self.bindings = list;
    }

    /// A set with the same bindings, limits and `paths` size but no buffers yet (its first
    /// upload writes everything).
    pub fn emptied(&self, gpu: &Gpu) -> GpuScene {
        GpuScene {
            buffers: BufferSet::new(gpu, "rtc scene").with_limits(self.buffers.limits()),
            bindings: self.bindings.clone(),
            tables: self.tables,
            path_bytes: self.path_bytes,
        }
    }

    /// Zeroes the kernel's counters only (between calls that continue an accumulation).
    pub fn clear_counters(&mut self, gpu: &Gpu) -> Result<(), SceneError> {
        self.clear(gpu, &["counters"])
    }

    /// Sizes the wavefront model's `paths` binding (one tile's path records) for the next
    /// upload; it is zeroed when (re)allocated and by [`GpuScene::clear_accumulation`].
    pub fn set_path_bytes(&mut self, bytes: u64) {
        self.path_bytes = bytes.max(16);
    }

    /// Replaces the enforced limits (tests fake tiny ones).
    pub fn with_limits(mut self, limits: BufferLimits) -> Self {
        self.buffers = self.buffers.with_limits(limits);
        self
    }

    /// The buffers, for binding to kernels.
    pub fn buffers(&self) -> &BufferSet {
        &self.buffers
    }

    /// The runtime descriptions of the given ABI bindings (for `create_kernel`), with `tables`
    /// as uniform buffers.
    pub fn runtime_bindings_with(
        bindings: &[&'static abi::BindingDesc],
        tables: UniformTables,
    ) -> Vec<BindingDesc> {
        bindings.iter().map(|b| tables.describe(b)).collect()
    }

    fn has(&self, name: &str) -> bool {
        self.bindings.iter().any(|(b, _)| b.name == name)
    }

    /// Uploads what changed for rendering: instances in TLAS order, `accum` sized for `pixels`
    /// pixels (zeroed if new or resized; see [`clear_accumulation`](Self::clear_accumulation)).
    /// The entities' in-place changes are then cleared ([`Entities::clear_dirty`]): the GPU
    /// holds them.
    pub fn upload(
        &mut self,
        gpu: &Gpu,
        entities: &mut Entities,
        frame: &FrameUniforms,
        pixels: u64,
    ) -> Result<UploadReport, SceneError> {
        self.write(gpu, entities, frame, InstanceOrder::Tlas, pixels)
    }

    /// Uploads what the bounds kernel reads: instances in object order, `accum` holding at least
    /// two entries per object.
    pub fn upload_for_bounds(
        &mut self,
        gpu: &Gpu,
        entities: &mut Entities,
        frame: &FrameUniforms,
    ) -> Result<UploadReport, SceneError> {
        let entries = 2 * entities.objects().len() as u64;
        self.write(gpu, entities, frame, InstanceOrder::Objects, entries)
    }

    fn write(
        &mut self,
        gpu: &Gpu,
        entities: &mut Entities,
        frame: &FrameUniforms,
        order: InstanceOrder,
        accum_entries: u64,
    ) -> Result<UploadReport, SceneError> {
        self.buffers.begin_frame();
        let versions = entities.versions();
        let dirty = entities.dirty();
        let object_order;
        let instances: &[GpuInstance] = match order {
            InstanceOrder::Tlas => entities.instances(),
            InstanceOrder::Objects => {
                object_order = entities.instances_in_object_order();
                &object_order
            }
        };
        let mut outcomes = Vec::with_capacity(self.bindings.len());
        for (abi_desc, desc) in &self.bindings {
            let set = &mut self.buffers;
            let binding = abi_desc.name;
            let named = |e: BufferError| name_the_largest_part(e, binding, entities);
            let outcome = match abi_desc.name {
                "frame" => set.upload(gpu, desc, bytemuck::bytes_of(frame))?,
                // Only for a bounds kernel that reads it; the tile dispatcher binds its own.
                "tile" => set.upload(gpu, desc, bytemuck::bytes_of(&TileParams::default()))?,
                "nodes" => {
                    let record = std::mem::size_of::<rtc_bvh::NodeRecord>() as u64;
                    let data: &[u8] = bytemuck::cast_slice(entities.nodes());
                    match dirty.nodes {
                        Some((base, from)) => set.upload_ranges(
                            gpu,
                            desc,
                            data,
                            versions.nodes,
                            base,
                            std::slice::from_ref(&(from as u64 * record..data.len() as u64)),
                        ),
                        None => set.upload_generation(gpu, desc, data, versions.nodes),
                    }
                    .map_err(named)?
                }
                "instances" => set.upload(gpu, desc, bytemuck::cast_slice(instances))?,
                "triangles" => set
                    .upload_generation(
                        gpu,
                        desc,
                        bytemuck::cast_slice(entities.triangles()),
                        versions.triangles,
                    )
                    .map_err(named)?,
                "attributes" => set
                    .upload_generation(
                        gpu,
                        desc,
                        bytemuck::cast_slice(entities.attributes()),
                        versions.attributes,
                    )
                    .map_err(named)?,
                "params" => {
                    let data: &[u8] = bytemuck::cast_slice(entities.params());
                    match &dirty.params {
                        Some((base, ranges)) => {
                            let bytes: Vec<_> = ranges
                                .iter()
                                .map(|r| r.start as u64 * 4..r.end as u64 * 4)
                                .collect();
                            set.upload_ranges(gpu, desc, data, versions.params, *base, &bytes)?
                        }
                        None => set.upload_generation(gpu, desc, data, versions.params)?,
                    }
                }
                "texels" => set
                    .upload_generation(
                        gpu,
                        desc,
                        bytemuck::cast_slice(entities.texels()),
                        versions.texels,
                    )
                    .map_err(named)?,
                "accum" => set.ensure_zeroed(gpu, desc, accum_entries.max(1) * 16)?,
                "counters" => set.ensure_zeroed(gpu, desc, COUNTER_BYTES)?,
                "paths" => set.ensure_zeroed(gpu, desc, self.path_bytes)?,
                // A binding this runtime does not know: nothing to put in it.
                _ => continue,
            };
            outcomes.push((abi_desc.name, outcome));
        }
        entities.clear_dirty();
        Ok(UploadReport {
            outcomes,
            stats: self.buffers.stats(),
        })
    }

    /// Zeroes `accum`, `counters` and the wavefront model's `paths` (before the first pass of a
    /// render).
    pub fn clear_accumulation(&mut self, gpu: &Gpu) -> Result<(), SceneError> {
        self.clear(gpu, &["accum", "counters", "paths"])
    }

    /// Zeroes the named bindings that exist.
    fn clear(&mut self, gpu: &Gpu, names: &[&str]) -> Result<(), SceneError> {
        for &name in names {
            if let Some(b) = abi::binding(name).filter(|_| self.has(name)) {
                if self.buffers.buffer(b.binding).is_some() {
                    self.buffers.clear(gpu, b.binding)?;
                }
            }
        }
        Ok(())
    }

    /// Reads `accum` back (every bound entry).
    pub fn read_accumulation(&self, gpu: &Gpu) -> Result<Vec<[f32; 4]>, SceneError> {
        self.read_accumulation_prefix(gpu, u64::MAX)
    }

    /// Reads back the first `count` entries of `accum` (a preview's pixels).
    pub fn read_accumulation_prefix(
        &self,
        gpu: &Gpu,
        count: u64,
    ) -> Result<Vec<[f32; 4]>, SceneError> {
        let Some(b) = abi::binding("accum").filter(|_| self.has("accum")) else {
            return Ok(Vec::new());
        };
        Ok(read_vec4_f32_prefix(gpu, &self.buffers, b.binding, count)?)
    }

    /// Reads the kernel's counters back (zeros when the kernel declares no `counters`).
    pub fn read_counters(&self, gpu: &Gpu) -> Result<Counters, SceneError> {
        let buffer = abi::binding("counters")
            .filter(|_| self.has("counters"))
            .and_then(|b| self.buffers.buffer(b.binding));
        let Some(buffer) = buffer else {
            return Ok(Counters::default());
        };
        let bytes = read_buffer(gpu, buffer, COUNTER_BYTES)?;
        Ok(counters_from(&bytes))
    }

    /// [`read_accumulation`](Self::read_accumulation) without blocking (the web).
    #[cfg(target_arch = "wasm32")]
    pub async fn read_accumulation_async(&self, gpu: &Gpu) -> Result<Vec<[f32; 4]>, SceneError> {
        let Some(b) = abi::binding("accum").filter(|_| self.has("accum")) else {
            return Ok(Vec::new());
        };
        Ok(crate::gpu::read_vec4_f32_async(gpu, &self.buffers, b.binding).await?)
    }

    /// [`read_counters`](Self::read_counters) without blocking (the web).
    #[cfg(target_arch = "wasm32")]
    pub async fn read_counters_async(&self, gpu: &Gpu) -> Result<Counters, SceneError> {
        let buffer = abi::binding("counters")
            .filter(|_| self.has("counters"))
            .and_then(|b| self.buffers.buffer(b.binding));
        let Some(buffer) = buffer else {
            return Ok(Counters::default());
        };
        let bytes = crate::gpu::read_buffer_async(gpu, buffer, COUNTER_BYTES).await?;
        Ok(counters_from(&bytes))
    }
}

/// The counters from the first bytes of the `counters` buffer (missing words read as 0).
fn counters_from(bytes: &[u8]) -> Counters {
    let word = |index: u32| {
        let at = index as usize * 4;
        bytes
            .get(at..at + 4)
            .and_then(|b| <[u8; 4]>::try_from(b).ok())
            .map_or(0, u32::from_le_bytes)
    };
    Counters {
        nonfinite: word(abi::COUNTER_NONFINITE),
        rays: word(abi::COUNTER_RAYS),
        shadow_overflow: word(abi::COUNTER_SHADOW_OVERFLOW),
    }
}

/// A [`BufferError::TooLarge`] of a binding that holds meshes (`nodes`, `triangles`,
/// `attributes`) or textures (`texels`), with the largest mesh or texture in it named (its file,
/// and for a glTF file the mesh), since that is what the user can change.
pub(crate) fn name_the_largest_part(
    error: BufferError,
    binding: &str,
    entities: &Entities,
) -> SceneError {
    if !matches!(error, BufferError::TooLarge { .. }) {
        return SceneError::Buffer(error);
    }
    // Bytes per triangle slot and per BVH record, as the ABI table lays them out.
    let part = match binding {
        "triangles" | "attributes" | "nodes" => {
            let bytes = |m: &super::MeshEntity| match binding {
                "triangles" => u64::from(m.slots) * record::bytes(&abi::TRIANGLE),
                "attributes" => u64::from(m.slots) * record::bytes(&abi::ATTRIBUTE),
                _ => u64::from(m.node_count) * struct_size(&abi::NODE) as u64,
            };
            entities.meshes().iter().max_by_key(|m| bytes(m)).map(|m| {
                format!(
                    "the mesh `{}` ({} triangles, {} bytes of `{binding}`)",
                    m.source,
                    m.triangles,
                    bytes(m)
                )
            })
        }
        "texels" => {
            let bytes = |t: &super::TextureEntity| {
                u64::from(t.width) * u64::from(t.height) * t.format.words_per_texel() as u64 * 4
            };
            entities
                .textures()
                .iter()
                .max_by_key(|t| bytes(t))
                .map(|t| {
                    format!(
                        "the texture `{}` ({}x{} texels, {} bytes)",
                        t.source,
                        t.width,
                        t.height,
                        bytes(t)
                    )
                })
        }
        _ => None,
    };
    match part {
        Some(part) => SceneError::BindingTooLarge {
            source: error,
            part,
        },
        None => SceneError::Buffer(error),
    }
}
