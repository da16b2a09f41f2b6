//! What a host application's device must offer for rtc to run on it ([`crate::gpu::Gpu::from_device`]):
//! the limits rtc's kernels and its resolve pass need ([`required_limits`]), the check of a device
//! against them ([`missing_capabilities`]), and the typed error naming every shortfall
//! ([`FromDeviceError`]).
//!
//! Guarantees: the check compares exactly the limits listed in `CHECKED`, each against what
//! rtc's kernels need (tested against the ABI table), all within WebGPU's defaults, so a device
//! created with `required_limits()` (WebGPU's defaults) or with its adapter's own limits always
//! passes; every failing limit is reported, not only the first. Scene-dependent limits (the size of one storage binding) are not
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

/// A limit rtc checks on a host's device: its name, how to read it, and the least rtc needs.
type LimitNeed = (&'static str, fn(&wgpu::Limits) -> u64, u64);

/// Storage buffers one rtc kernel binds at most: every storage binding of the ABI but the
/// wavefront model's `paths` (the megakernel), or one wavefront stage's subset (tested in the
/// compiler), within WebGPU's default of 8.
pub const KERNEL_STORAGE_BUFFERS: u32 = 8;

/// Every limit [`missing_capabilities`] checks (all "higher is better"), with what rtc's kernels
/// (group 0 only, 11 dense bindings, 8 x 8 and 64 x 1 workgroups, a dynamic-offset tile uniform
/// and the frame uniform) and its resolve pass (one storage texture) need.
const CHECKED: &[LimitNeed] = &[
    ("max_bind_groups", |l| l.max_bind_groups.into(), 1),
    (
        "max_bindings_per_bind_group",
        |l| l.max_bindings_per_bind_group.into(),
        11,
    ),
    (
        "max_storage_buffers_per_shader_stage",
        |l| l.max_storage_buffers_per_shader_stage.into(),
        KERNEL_STORAGE_BUFFERS as u64,
    ),
    (
        "max_uniform_buffers_per_shader_stage",
        |l| l.max_uniform_buffers_per_shader_stage.into(),
        2,
    ),
    (
        "max_buffers_and_acceleration_structures_per_shader_stage",
        |l| {
            l.max_buffers_and_acceleration_structures_per_shader_stage
                .into()
        },
        KERNEL_STORAGE_BUFFERS as u64 + 2,
    ),
    (
        "max_dynamic_uniform_buffers_per_pipeline_layout",
        |l| l.max_dynamic_uniform_buffers_per_pipeline_layout.into(),
        1,
    ),
    (
        "max_storage_textures_per_shader_stage",
        |l| l.max_storage_textures_per_shader_stage.into(),
        1,
    ),
    (
        "max_compute_workgroup_size_x",
        |l| l.max_compute_workgroup_size_x.into(),
        64,
    ),
    (
        "max_compute_workgroup_size_y",
        |l| l.max_compute_workgroup_size_y.into(),
        8,
    ),
    (
        "max_compute_invocations_per_workgroup",
        |l| l.max_compute_invocations_per_workgroup.into(),
        64,
    ),
];

/// The limits to request when creating a device for rtc: WebGPU's defaults, which cover every
/// limit rtc checks. A storage binding is then at most 128 MiB; request `adapter.limits()` (or at
/// least its `max_storage_buffer_binding_size` and `max_buffer_size`) for scenes with larger
/// buffers.
pub fn required_limits() -> wgpu::Limits {
    wgpu::Limits::default()
}

/// What `limits` (a device's) and `downlevel` (its adapter's) lack for rtc, empty when nothing.
pub fn missing_capabilities(
    limits: &wgpu::Limits,
    downlevel: &wgpu::DownlevelCapabilities,
) -> Vec<MissingCapability> {
    let mut missing: Vec<MissingCapability> = CHECKED
        .iter()
        .filter_map(|&(name, get, need)| {
            let have = get(limits);
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
    fn the_checked_limits_cover_the_kernel_abi() {
        use rtc_compiler::abi::BINDINGS;
        use rtc_compiler::back::ResourceKind;
        let need = |name: &str| {
            CHECKED
                .iter()
                .find(|c| c.0 == name)
                .map(|c| c.2)
                .unwrap_or_else(|| panic!("{name} is not checked"))
        };
        let storage = BINDINGS
            .iter()
            .filter(|b| b.kind != ResourceKind::Uniform && b.name != "paths")
            .count() as u64;
        assert_eq!(storage, u64::from(KERNEL_STORAGE_BUFFERS));
        assert_eq!(need("max_storage_buffers_per_shader_stage"), storage);
        let uniforms = BINDINGS
            .iter()
            .filter(|b| b.kind == ResourceKind::Uniform)
            .count() as u64;
        assert_eq!(need("max_uniform_buffers_per_shader_stage"), uniforms);
        assert_eq!(need("max_bindings_per_bind_group"), BINDINGS.len() as u64);
        let [x, y] = rtc_compiler::kernel::RENDER_WORKGROUP;
        let bounds = rtc_compiler::kernel::BOUNDS_WORKGROUP;
        assert_eq!(
            need("max_compute_workgroup_size_x"),
            u64::from(x.max(bounds))
        );
        assert_eq!(need("max_compute_workgroup_size_y"), u64::from(y));
        assert_eq!(
            need("max_compute_invocations_per_workgroup"),
            u64::from((x * y).max(bounds))
        );
    }

    #[test]
    fn webgpu_defaults_pass_and_lower_limits_name_what_is_missing() {
        let downlevel = wgpu::DownlevelCapabilities::default();
        assert_eq!(missing_capabilities(&required_limits(), &downlevel), []);
        let missing = missing_capabilities(&wgpu::Limits::downlevel_defaults(), &downlevel);
        assert_eq!(
            missing,
            [MissingCapability::Limit {
                name: "max_storage_buffers_per_shader_stage",
                have: 4,
                need: 8,
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
        assert!(
            text.contains("`max_storage_buffers_per_shader_stage` is 0, rtc needs at least 8"),
            "{text}"
        );
        assert!(text.contains("help: create the device with"), "{text}");
    }
}
