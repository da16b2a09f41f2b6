//! Small read-only tables in uniform buffers, for lavapipe where its storage loads are per lane.
//!
//! Mesa 25's lavapipe compiles every storage-buffer load to a loop over the SIMD batch's lanes,
//! with a bounds check and a lane-mask branch per 32-bit word, and a uniform-buffer load to one
//! gather (docs/bench/lavapipe.md, "Measurements"). A scene whose object records
//! (`instances`, 128 bytes an object) or BVH records (`nodes`, 32 bytes each) fit in one uniform
//! binding of WebGPU's default size ([`UNIFORM_TABLE_BYTES`]) can have those bindings declared as
//! fixed-size `var<uniform>` arrays in every kernel: on Mesa 25.0.7 that makes the driver's cold
//! compile 1.3 to 2.0 times shorter, with frames the same or faster and byte-identical images
//! (docs/bench/compile.md, "Small tables in uniform buffers (2026-12-04)"). Mesa 26 compiles
//! storage loads to gathers, and on a CPU with AVX-512 it made compiles and most frames slower (up
//! to 1.28 and 1.19 times); without AVX-512 (AMD Zen 3) LLVM turns those gathers into a branch and
//! a load per lane, and there uniform tables made frames 0.71 to 0.99 times as long
//! (docs/bench/lavapipe.md, "Per-lane loads on CPUs without AVX-512 (2026-12-07)"). GPUs read a
//! uniform array indexed differently by each lane one address at a time. So by default only
//! lavapipe whose loads are per lane gets it ([`TablePlacement::Auto`],
//! [`crate::gpu::lavapipe_loads_per_lane`]); `RTC_UNIFORM_TABLES=on|off` or
//! [`RenderOptions::uniform_tables`](crate::render::RenderOptions::uniform_tables) overrides.
//!
//! The compiler's kernels, and every file `rtc compile` writes, keep storage buffers: this is a
//! specialisation of the modules for one adapter and one scene, made when the renderer creates
//! its pipelines ([`UniformTables::specialise`]).
//!
//! Invariants:
//! - The rewrite changes only the address space and the array type (runtime-sized to a fixed
//!   [`UNIFORM_TABLE_BYTES`] in all) of the chosen bindings' globals, and only where a module
//!   declares them as read-only storage arrays; every load stays what it was.
//! - A table is chosen only when everything it can hold without new kernels fits: for `nodes`,
//!   the object-level BVHs and a scene-level BVH over every object (moving objects rebuilds
//!   that one and may change its record count, never beyond one record per object and a header).
//! - The kernels and the GPU buffers of a scene are described by the same [`UniformTables`], so
//!   they always agree; buffers of a chosen table are [`UNIFORM_TABLE_BYTES`] long.

use std::num::NonZeroU32;

use rtc_compiler::abi;

use super::entities::Entities;
use super::gpu_types::GpuInstance;
use crate::gpu::{AdapterDescription, BindingDesc, BindingKind};

/// The size of a table placed in a uniform buffer: WebGPU's default
/// `maxUniformBufferBindingSize`, so the kernels stay within the default limits.
pub const UNIFORM_TABLE_BYTES: u32 = 64 << 10;

/// The environment variable that overrides the adapter's choice: `on` (also `1`, `true`) places
/// every table that fits on any adapter, `off` (also `0`, `false`) none; other values leave the
/// choice to the adapter.
pub const UNIFORM_TABLES_ENV: &str = "RTC_UNIFORM_TABLES";

/// The bindings that may be placed, in binding order.
const CANDIDATES: [&str; 2] = ["nodes", "instances"];

/// Where a render wants the small tables.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TablePlacement {
    /// [`UNIFORM_TABLES_ENV`] if it says `on` or `off`, else uniform buffers on lavapipe whose
    /// loads are per-lane code ([`prefers_uniform_tables`]) and storage buffers everywhere else.
    #[default]
    Auto,
    /// Every table that fits in a uniform buffer.
    Uniform,
    /// Storage buffers, as compiled.
    Storage,
}

impl TablePlacement {
    /// `on`/`off` from [`UNIFORM_TABLES_ENV`], or [`Auto`](Self::Auto).
    pub fn from_env() -> Self {
        match std::env::var(UNIFORM_TABLES_ENV).as_deref() {
            Ok("on" | "1" | "true") => TablePlacement::Uniform,
            Ok("off" | "0" | "false") => TablePlacement::Storage,
            _ => TablePlacement::Auto,
        }
    }

    /// Whether tables go to uniform buffers on this adapter.
    pub fn wants_uniform(self, adapter: &AdapterDescription) -> bool {
        match self {
            TablePlacement::Uniform => true,
            TablePlacement::Storage => false,
            TablePlacement::Auto => match TablePlacement::from_env() {
                TablePlacement::Auto => prefers_uniform_tables(adapter),
                placed => placed.wants_uniform(adapter),
            },
        }
    }
}

/// Whether `adapter` is lavapipe (Vulkan, llvmpipe) whose storage loads are per-lane code on this
/// machine ([`crate::gpu::lavapipe_loads_per_lane`]: Mesa before 26, or a CPU without AVX-512).
pub fn prefers_uniform_tables(adapter: &AdapterDescription) -> bool {
    adapter.backend == wgpu::Backend::Vulkan
        && adapter.device_type == wgpu::DeviceType::Cpu
        && adapter.name.starts_with("llvmpipe")
        && crate::gpu::lavapipe_loads_per_lane(&adapter.driver_info)
}

/// The bindings of one scene's kernels placed in uniform buffers (none by default).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct UniformTables {
    /// One bit per entry of `CANDIDATES`.
    bits: u8,
}

impl UniformTables {
    /// Every table that `placement` wants on `adapter` and whose data fits, for `entities`.
    pub fn choose(
        placement: TablePlacement,
        adapter: &AdapterDescription,
        entities: &Entities,
    ) -> Self {
        if !placement.wants_uniform(adapter) {
            return Self::default();
        }
        let objects = entities.objects().len() as u64;
        // The object-level BVHs, and the largest scene-level BVH the objects can have: a header
        // and one record per inner node, with one object per leaf.
        let blas_records = if entities.tlas_order().is_some() {
            u64::from(entities.tlas_root())
        } else {
            entities.nodes().len() as u64
        };
        let node_bytes =
            (blas_records + objects + 1) * std::mem::size_of::<rtc_bvh::NodeRecord>() as u64;
        // A record per object, and one per group of flattened objects (`flatten.rs`; moving one
        // of them only drops groups).
        let records = objects + u64::from(entities.stats().flat_bvhs);
        let instance_bytes = records * std::mem::size_of::<GpuInstance>() as u64;
        Self::of(
            node_bytes <= u64::from(UNIFORM_TABLE_BYTES),
            instance_bytes <= u64::from(UNIFORM_TABLE_BYTES),
        )
    }

    /// Every table, if `placement` wants them on `adapter`, whatever their size: what a render
    /// gets on this adapter for a scene whose tables fit (`rtc compile --timings driver`, which
    /// has no scene data).
    pub fn for_adapter(placement: TablePlacement, adapter: &AdapterDescription) -> Self {
        let on = placement.wants_uniform(adapter);
        Self::of(on, on)
    }

    /// `nodes` and/or `instances` in uniform buffers.
    pub fn of(nodes: bool, instances: bool) -> Self {
        Self {
            bits: u8::from(nodes) | u8::from(instances) << 1,
        }
    }

    /// Whether no table is placed.
    pub fn is_empty(self) -> bool {
        self.bits == 0
    }

    /// The ABI names of the placed bindings, in binding order.
    pub fn names(self) -> Vec<&'static str> {
        CANDIDATES
            .iter()
            .enumerate()
            .filter(|(i, _)| self.bits & (1 << i) != 0)
            .map(|(_, name)| *name)
            .collect()
    }

    fn has_binding(self, binding: u32) -> bool {
        CANDIDATES.iter().enumerate().any(|(i, name)| {
            self.bits & (1 << i) != 0 && abi::binding(name).is_some_and(|b| b.binding == binding)
        })
    }

    /// The runtime description of ABI binding `b` with this placement: a placed table is a
    /// uniform binding of exactly [`UNIFORM_TABLE_BYTES`].
    pub fn describe(self, b: &abi::BindingDesc) -> BindingDesc {
        if self.has_binding(b.binding) {
            BindingDesc::new(
                b.binding,
                b.name,
                BindingKind::Uniform,
                u64::from(UNIFORM_TABLE_BYTES),
            )
        } else {
            super::runtime_binding(b)
        }
    }

    /// Rewrites the placed bindings of `module` (group 0, read-only storage, runtime-sized
    /// arrays) as uniform arrays of [`UNIFORM_TABLE_BYTES`]; other globals are left alone.
    pub fn specialise(self, module: &mut naga::Module) {
        if self.is_empty() {
            return;
        }
        let naga::Module {
            types,
            global_variables,
            ..
        } = module;
        for (_, global) in global_variables.iter_mut() {
            let Some(rb) = global.binding else { continue };
            if rb.group != 0 || !self.has_binding(rb.binding) {
                continue;
            }
            if !matches!(global.space, naga::AddressSpace::Storage { access } if access == naga::StorageAccess::LOAD)
            {
                continue;
            }
            let naga::TypeInner::Array {
                base,
                size: naga::ArraySize::Dynamic,
                stride,
            } = types[global.ty].inner
            else {
                continue;
            };
            let Some(count) = UNIFORM_TABLE_BYTES
                .checked_div(stride)
                .and_then(NonZeroU32::new)
            else {
                continue;
            };
            global.ty = types.insert(
                naga::Type {
                    name: None,
                    inner: naga::TypeInner::Array {
                        base,
                        size: naga::ArraySize::Constant(count),
                        stride,
                    },
                },
                naga::Span::UNDEFINED,
            );
            global.space = naga::AddressSpace::Uniform;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn adapter(name: &str, backend: wgpu::Backend, driver_info: &str) -> AdapterDescription {
        AdapterDescription {
            name: name.into(),
            backend,
            device_type: wgpu::DeviceType::Cpu,
            driver: "llvmpipe".into(),
            driver_info: driver_info.into(),
            vendor: 0x10005,
            device: 0,
        }
    }

    #[test]
    fn lavapipe_with_per_lane_loads_prefers_uniform_tables() {
        let vk = wgpu::Backend::Vulkan;
        let lvp = "llvmpipe (LLVM 15.0.6, 128 bits)";
        assert!(prefers_uniform_tables(&adapter(
            lvp,
            vk,
            "Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)"
        )));
        assert!(prefers_uniform_tables(&adapter(lvp, vk, "Mesa 22.3.6")));
        // From Mesa 26 on, as this machine's CPU decides (`gpu::cpu`'s tests take both).
        let mesa_26 = "Mesa 26.1.6-1~bpo13+1 (LLVM 19.1.7)";
        assert_eq!(
            prefers_uniform_tables(&adapter(lvp, vk, mesa_26)),
            crate::gpu::lavapipe_loads_per_lane(mesa_26)
        );
        assert!(!prefers_uniform_tables(&adapter(lvp, vk, "Mesa devel")));
        // llvmpipe under GL, and any GPU, keep storage buffers.
        assert!(!prefers_uniform_tables(&adapter(
            lvp,
            wgpu::Backend::Gl,
            "Mesa 25.0.7"
        )));
        let mut gpu = adapter("NVIDIA H200", vk, "Mesa 25.0.7");
        gpu.device_type = wgpu::DeviceType::DiscreteGpu;
        assert!(!prefers_uniform_tables(&gpu));
        assert!(TablePlacement::Uniform.wants_uniform(&gpu));
        assert!(!TablePlacement::Storage.wants_uniform(&adapter(lvp, vk, "Mesa 25.0.7")));
    }

    #[test]
    fn names_describe_and_rewrite_only_the_placed_tables() {
        let both = UniformTables::of(true, true);
        assert_eq!(both.names(), ["nodes", "instances"]);
        assert_eq!(UniformTables::of(false, true).names(), ["instances"]);
        assert!(UniformTables::default().is_empty());
        let nodes = abi::binding("nodes").expect("nodes");
        let params = abi::binding("params").expect("params");
        let d = UniformTables::of(true, false).describe(nodes);
        assert_eq!(d.kind, BindingKind::Uniform);
        assert_eq!(d.min_size, u64::from(UNIFORM_TABLE_BYTES));
        assert_eq!(
            both.describe(params).kind,
            BindingKind::StorageRead,
            "params stays storage"
        );
        assert_eq!(
            UniformTables::of(false, true).describe(nodes).kind,
            BindingKind::StorageRead
        );

        let wgsl = "struct N { a: vec4<u32>, b: vec4<u32> }
            @group(0) @binding(2) var<storage, read> nodes: array<N>;
            @group(0) @binding(6) var<storage, read> params: array<u32>;
            @group(0) @binding(8) var<storage, read_write> accum: array<vec4<f32>>;
            @compute @workgroup_size(8, 8)
            fn main(@builtin(global_invocation_id) id: vec3<u32>) {
                accum[id.x] = vec4<f32>(nodes[params[id.x]].a + nodes[id.y].b);
            }";
        let mut module = naga::front::wgsl::parse_str(wgsl).expect("parses");
        both.specialise(&mut module);
        let mut spaces: Vec<(String, naga::AddressSpace, Option<naga::ArraySize>)> = module
            .global_variables
            .iter()
            .map(|(_, g)| {
                let size = match module.types[g.ty].inner {
                    naga::TypeInner::Array { size, .. } => Some(size),
                    _ => None,
                };
                (g.name.clone().unwrap_or_default(), g.space, size)
            })
            .collect();
        spaces.sort_by(|a, b| a.0.cmp(&b.0));
        assert_eq!(spaces[1].0, "nodes");
        assert_eq!(spaces[1].1, naga::AddressSpace::Uniform);
        assert_eq!(
            spaces[1].2,
            Some(naga::ArraySize::Constant(
                NonZeroU32::new(2048).expect("2048")
            ))
        );
        assert!(matches!(spaces[2].1, naga::AddressSpace::Storage { .. }));
        assert!(matches!(spaces[0].1, naga::AddressSpace::Storage { .. }));
        // The rewritten module is valid, and WGSL for WebGPU.
        let info = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::empty(),
        )
        .validate(&module)
        .expect("valid");
        let text =
            naga::back::wgsl::write_string(&module, &info, naga::back::wgsl::WriterFlags::empty())
                .expect("writes");
        assert!(
            text.contains("var<uniform> nodes: array<N, 2048>;"),
            "{text}"
        );
    }
}
