//! What a host application's device must offer for rtc to run on it ([`crate::gpu::Gpu::from_device`]):
//! the limits rtc's kernels and its resolve pass need ([`required_limits`]), the check of a device
//! against them ([`missing_capabilities`]), and the typed error naming every shortfall
//! ([`FromDeviceError`]).
//!
//! Guarantees: the check compares exactly the limits listed in `CHECKED`, each against the value
//! [`required_limits`] requests, so a device created with `required_limits()` (or with its
//! adapter's own limits, when they are at least as good) always passes; every failing limit is
//! reported, not only the first. Scene-dependent limits (the size of one storage binding) are not
//! checked here: the buffer set reports them per binding when a scene exceeds them.

use std::fmt;

/// One thing the host's device lacks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MissingCapability {
    /// A device limit below what rtc needs.
    Limit {
        /// The limit's name, as `wgpu::Limits` spells the field.
        name: &'static str,
        /// The device's value.
        have: u64,
        /// The least rtc needs.
        need: u64,
    },
    /// A downlevel capability the adapter lacks (compute shaders).
    Downlevel(&'static str),
}

impl fmt::Display for MissingCapability {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Limit { name, have, need } => {
                write!(f, "`{name}` is {have}, rtc needs at least {need}")
            }
            Self::Downlevel(what) => write!(f, "the adapter does not support {what}"),
        }
    }
}

/// Why [`crate::gpu::Gpu::from_device`] refused a host's device.
#[derive(Debug, thiserror::Error)]
pub enum FromDeviceError {
    /// The device's limits or the adapter's capabilities are below what rtc needs.
    #[error(
        "the device of adapter `{adapter}` cannot run rtc's kernels: {}\n\
         help: create the device with `required_limits: rtc_runtime::gpu::required_limits()` \
         (or `adapter.limits()` for large scenes)",
        missing.iter().map(ToString::to_string).collect::<Vec<_>>().join("; ")
    )]
    Unsupported {
        /// The adapter's name.
        adapter: String,
        /// Every shortfall.
        missing: Vec<MissingCapability>,
    },
}

/// The limits rtc checks on a host's device: the name and how to read it.
type LimitField = (&'static str, fn(&wgpu::Limits) -> u64);

/// Every limit [`missing_capabilities`] checks (all "higher is better").
const CHECKED: &[LimitField] = &[
    ("max_bind_groups", |l| l.max_bind_groups.into()),
    ("max_bindings_per_bind_group", |l| {
        l.max_bindings_per_bind_group.into()
    }),
    ("max_storage_buffers_per_shader_stage", |l| {
        l.max_storage_buffers_per_shader_stage.into()
    }),
    ("max_uniform_buffers_per_shader_stage", |l| {
        l.max_uniform_buffers_per_shader_stage.into()
    }),
    ("max_dynamic_uniform_buffers_per_pipeline_layout", |l| {
        l.max_dynamic_uniform_buffers_per_pipeline_layout.into()
    }),
    ("max_storage_textures_per_shader_stage", |l| {
        l.max_storage_textures_per_shader_stage.into()
    }),
    ("max_compute_workgroup_size_x", |l| {
        l.max_compute_workgroup_size_x.into()
    }),
    ("max_compute_workgroup_size_y", |l| {
        l.max_compute_workgroup_size_y.into()
    }),
    ("max_compute_invocations_per_workgroup", |l| {
        l.max_compute_invocations_per_workgroup.into()
    }),
];

/// Storage buffers one rtc kernel binds: every storage binding of the ABI (`nodes` … `paths`).
pub const KERNEL_STORAGE_BUFFERS: u32 = 9;

/// The limits to request when creating a device for rtc: WebGPU's defaults, with room for the
/// [`KERNEL_STORAGE_BUFFERS`] storage buffers of a kernel (the default allows 8). Every native
/// Vulkan, Metal and DX12 adapter offers them. A storage binding is then at most 128 MiB (the
/// WebGPU default); request `adapter.limits()` instead for scenes with larger buffers.
pub fn required_limits() -> wgpu::Limits {
    wgpu::Limits {
        max_storage_buffers_per_shader_stage: KERNEL_STORAGE_BUFFERS,
        ..wgpu::Limits::default()
    }
}

/// What `limits` (a device's) and `downlevel` (its adapter's) lack for rtc, empty when nothing.
pub fn missing_capabilities(
    limits: &wgpu::Limits,
    downlevel: &wgpu::DownlevelCapabilities,
) -> Vec<MissingCapability> {
    let required = required_limits();
    let mut missing: Vec<MissingCapability> = CHECKED
        .iter()
        .filter_map(|(name, get)| {
            let (have, need) = (get(limits), get(&required));
            (have < need).then_some(MissingCapability::Limit { name, have, need })
        })
        .collect();
    if !downlevel
        .flags
        .contains(wgpu::DownlevelFlags::COMPUTE_SHADERS)
    {
        missing.push(MissingCapability::Downlevel("compute shaders"));
    }
    missing
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn required_limits_cover_the_kernel_abi() {
        use rtc_compiler::abi::BINDINGS;
        use rtc_compiler::back::ResourceKind;
        let storage = BINDINGS
            .iter()
            .filter(|b| {
                matches!(
                    b.kind,
                    ResourceKind::StorageRead | ResourceKind::StorageReadWrite
                )
            })
            .count();
        assert_eq!(storage as u32, KERNEL_STORAGE_BUFFERS);
        let highest = BINDINGS.iter().map(|b| b.binding).max().unwrap_or(0);
        assert!(required_limits().max_bindings_per_bind_group > highest);
        let [x, y] = rtc_compiler::kernel::RENDER_WORKGROUP;
        let l = required_limits();
        assert!(l.max_compute_workgroup_size_x >= x.max(rtc_compiler::kernel::BOUNDS_WORKGROUP));
        assert!(l.max_compute_workgroup_size_y >= y);
        assert!(l.max_compute_invocations_per_workgroup >= x * y);
    }

    #[test]
    fn required_limits_pass_and_defaults_name_what_is_missing() {
        let downlevel = wgpu::DownlevelCapabilities::default();
        assert_eq!(missing_capabilities(&required_limits(), &downlevel), []);
        let missing = missing_capabilities(&wgpu::Limits::default(), &downlevel);
        assert_eq!(
            missing,
            [MissingCapability::Limit {
                name: "max_storage_buffers_per_shader_stage",
                have: 8,
                need: u64::from(KERNEL_STORAGE_BUFFERS),
            }]
        );
        let none = wgpu::DownlevelCapabilities {
            flags: wgpu::DownlevelFlags::empty(),
            ..downlevel
        };
        let missing = missing_capabilities(&wgpu::Limits::downlevel_webgl2_defaults(), &none);
        assert!(missing.len() > 2, "{missing:?}");
        assert_eq!(
            missing.last(),
            Some(&MissingCapability::Downlevel("compute shaders"))
        );
        let error = FromDeviceError::Unsupported {
            adapter: "test".into(),
            missing,
        };
        let text = error.to_string();
        assert!(text.contains("`max_storage_buffers_per_shader_stage` is 0, rtc needs at least 9"));
        assert!(text.contains("help: create the device with"));
    }
}
