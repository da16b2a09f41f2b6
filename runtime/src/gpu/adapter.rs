//! Adapter selection: which GPU (or CPU rasteriser) the runtime runs on.
//!
//! Rules, in order:
//! 1. The instance is built from the environment (`WGPU_BACKEND`, `WGPU_DEBUG`, ... through
//!    `InstanceDescriptor::new_without_display_handle_from_env`). An explicit
//!    [`AdapterChoice::backend`] replaces the backend set (a CLI flag beats the environment).
//! 2. Every adapter of those backends is enumerated, then filtered by
//!    [`AdapterChoice::name_substring`] (case-insensitive; `WGPU_ADAPTER_NAME` is the default when
//!    the choice names none) and by [`AdapterChoice::force_cpu`].
//! 3. Of the remaining adapters the best device type wins (discrete GPU, then integrated, virtual,
//!    CPU, other), ties broken by backend (Vulkan, Metal, DX12, GL, others) and then by the
//!    enumeration order, so the choice is deterministic. On a machine without a GPU this picks
//!    Mesa's lavapipe on Vulkan, and llvmpipe on GL when Vulkan is absent.
//!
//! Invariant: selection never panics; "no adapter at all" and "adapters, but none matching" are
//! distinct errors, and the former says how to install a software adapter.

use std::fmt;
use std::str::FromStr;
use web_time::Instant;

use super::{elapsed_ms, AdapterError, InitTimings};

/// An explicit adapter choice, as given to the CLI's `--adapter` flag.
///
/// The default chooses automatically. Parse one from text with [`str::parse`]: a comma-separated
/// list of `cpu` (force a CPU adapter), a backend name (`vulkan`/`vk`, `metal`/`mtl`,
/// `dx12`/`d3d12`, `gl`/`gles`/`opengl`) and at most one other word, taken as a
/// case-insensitive substring of the adapter name; `auto` or an empty string is the default.
/// Example: `gl,llvmpipe`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct AdapterChoice {
    /// Keep only adapters whose name contains this (case-insensitive).
    pub name_substring: Option<String>,
    /// Use only this backend (overrides `WGPU_BACKEND`).
    pub backend: Option<wgpu::Backend>,
    /// Keep only CPU adapters (lavapipe, llvmpipe, WARP).
    pub force_cpu: bool,
}

/// Why an `--adapter` value could not be parsed.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum AdapterChoiceParseError {
    /// Two backends were named.
    #[error("`--adapter` names two backends, `{first}` and `{second}`; name at most one")]
    TwoBackends {
        /// The first backend named.
        first: String,
        /// The second backend named.
        second: String,
    },
    /// Two name substrings were given.
    #[error(
        "`--adapter` has two adapter names, `{first}` and `{second}`; give one name substring \
         (known words: cpu, auto, vulkan, metal, dx12, gl)"
    )]
    TwoNames {
        /// The first name.
        first: String,
        /// The second name.
        second: String,
    },
}

impl FromStr for AdapterChoice {
    type Err = AdapterChoiceParseError;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let mut choice = AdapterChoice::default();
        for word in text.split(',').map(str::trim).filter(|w| !w.is_empty()) {
            let lower = word.to_ascii_lowercase();
            let backend = match lower.as_str() {
                "auto" => continue,
                "cpu" => {
                    choice.force_cpu = true;
                    continue;
                }
                "vulkan" | "vk" => Some(wgpu::Backend::Vulkan),
                "metal" | "mtl" => Some(wgpu::Backend::Metal),
                "dx12" | "d3d12" => Some(wgpu::Backend::Dx12),
                "gl" | "gles" | "opengl" => Some(wgpu::Backend::Gl),
                _ => None,
            };
            match (backend, &choice.backend, &choice.name_substring) {
                (Some(new), Some(old), _) => {
                    return Err(AdapterChoiceParseError::TwoBackends {
                        first: old.to_string(),
                        second: new.to_string(),
                    })
                }
                (Some(new), None, _) => choice.backend = Some(new),
                (None, _, Some(old)) => {
                    return Err(AdapterChoiceParseError::TwoNames {
                        first: old.clone(),
                        second: word.to_string(),
                    })
                }
                (None, _, None) => choice.name_substring = Some(word.to_string()),
            }
        }
        Ok(choice)
    }
}

impl fmt::Display for AdapterChoice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts = Vec::new();
        if let Some(name) = &self.name_substring {
            parts.push(format!("name containing `{name}`"));
        }
        if let Some(backend) = self.backend {
            parts.push(format!("backend {backend}"));
        }
        if self.force_cpu {
            parts.push("a CPU adapter".to_string());
        }
        if parts.is_empty() {
            parts.push("any adapter".to_string());
        }
        f.write_str(&parts.join(", "))
    }
}

/// What an adapter is, for printing (`rtc render` shows it; `--adapter` errors list them).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AdapterDescription {
    /// The adapter's name, e.g. `llvmpipe (LLVM 15.0.6, 256 bits)`.
    pub name: String,
    /// The backend (Vulkan, GL, ...).
    pub backend: wgpu::Backend,
    /// Discrete, integrated, virtual, CPU or other.
    pub device_type: wgpu::DeviceType,
    /// The driver's name (may be empty, e.g. on GL).
    pub driver: String,
    /// The driver's version text (may be empty).
    pub driver_info: String,
    /// PCI vendor id (or a backend-specific id).
    pub vendor: u32,
    /// PCI device id (or a backend-specific id).
    pub device: u32,
}

impl AdapterDescription {
    pub(super) fn from_info(info: &wgpu::AdapterInfo) -> Self {
        Self {
            name: info.name.clone(),
            backend: info.backend,
            device_type: info.device_type,
            driver: info.driver.clone(),
            driver_info: info.driver_info.clone(),
            vendor: info.vendor,
            device: info.device,
        }
    }

    /// The device type in words (`discrete GPU`, `CPU`, ...).
    pub fn device_type_name(&self) -> &'static str {
        match self.device_type {
            wgpu::DeviceType::DiscreteGpu => "discrete GPU",
            wgpu::DeviceType::IntegratedGpu => "integrated GPU",
            wgpu::DeviceType::VirtualGpu => "virtual GPU",
            wgpu::DeviceType::Cpu => "CPU",
            wgpu::DeviceType::Other => "other",
        }
    }
}

impl fmt::Display for AdapterDescription {
    /// One line: `name (backend, device type, driver driver_info)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} ({}, {}",
            self.name,
            self.backend,
            self.device_type_name()
        )?;
        let driver = [self.driver.as_str(), self.driver_info.as_str()]
            .into_iter()
            .filter(|s| !s.is_empty())
            .collect::<Vec<_>>()
            .join(" ");
        if !driver.is_empty() {
            write!(f, ", driver {driver}")?;
        }
        f.write_str(")")
    }
}

/// Lists every adapter the instance sees under `choice.backend` (or `WGPU_BACKEND`), unfiltered
/// by name or device type, in enumeration order. Not on the web, which offers one adapter and
/// no blocking wait for it.
#[cfg(not(target_arch = "wasm32"))]
pub fn list_adapters(choice: &AdapterChoice) -> Vec<AdapterDescription> {
    let (instance, backends) = instance_for(choice);
    pollster::block_on(instance.enumerate_adapters(backends))
        .iter()
        .map(|adapter| AdapterDescription::from_info(&adapter.get_info()))
        .collect()
}

/// Chooses the adapter by the rules in the module docs.
pub(super) async fn select(
    choice: &AdapterChoice,
) -> Result<(wgpu::Adapter, InitTimings), AdapterError> {
    let mut timings = InitTimings::default();
    let start = Instant::now();
    let (instance, backends) = instance_for(choice);
    timings.instance_ms = elapsed_ms(start);

    let start = Instant::now();
    let adapters = instance.enumerate_adapters(backends).await;
    if adapters.is_empty() {
        return Err(AdapterError::NoAdapter {
            backends: backend_names(backends),
        });
    }
    let name_filter = choice
        .name_substring
        .clone()
        .or_else(|| std::env::var("WGPU_ADAPTER_NAME").ok())
        .filter(|name| !name.is_empty())
        .map(|name| name.to_lowercase());
    let best = adapters
        .iter()
        .enumerate()
        .filter(|(_, adapter)| {
            let info = adapter.get_info();
            let name_ok = name_filter
                .as_ref()
                .is_none_or(|needle| info.name.to_lowercase().contains(needle));
            let type_ok = !choice.force_cpu || info.device_type == wgpu::DeviceType::Cpu;
            name_ok && type_ok
        })
        .min_by_key(|(index, adapter)| {
            let info = adapter.get_info();
            (
                device_type_rank(info.device_type),
                backend_rank(info.backend),
                *index,
            )
        })
        .map(|(_, adapter)| adapter.clone());
    let Some(adapter) = best else {
        let mut shown = choice.clone();
        shown.name_substring = name_filter;
        return Err(AdapterError::NoMatch {
            choice: shown.to_string(),
            available: adapters
                .iter()
                .map(|a| AdapterDescription::from_info(&a.get_info()).to_string())
                .collect(),
        });
    };
    timings.adapter_ms = elapsed_ms(start);
    Ok((adapter, timings))
}

/// The instance from the environment, with the explicit backend (if any) replacing the set.
fn instance_for(choice: &AdapterChoice) -> (wgpu::Instance, wgpu::Backends) {
    let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
    if let Some(backend) = choice.backend {
        descriptor.backends = wgpu::Backends::from(backend);
    }
    let backends = descriptor.backends;
    (wgpu::Instance::new(descriptor), backends)
}

/// Lower is better.
fn device_type_rank(device_type: wgpu::DeviceType) -> u8 {
    match device_type {
        wgpu::DeviceType::DiscreteGpu => 0,
        wgpu::DeviceType::IntegratedGpu => 1,
        wgpu::DeviceType::VirtualGpu => 2,
        wgpu::DeviceType::Cpu => 3,
        wgpu::DeviceType::Other => 4,
    }
}

/// Lower is better: native explicit APIs before GL.
fn backend_rank(backend: wgpu::Backend) -> u8 {
    match backend {
        wgpu::Backend::Vulkan => 0,
        wgpu::Backend::Metal => 1,
        wgpu::Backend::Dx12 => 2,
        wgpu::Backend::Gl => 3,
        wgpu::Backend::BrowserWebGpu => 4,
        wgpu::Backend::Noop => 5,
    }
}

fn backend_names(backends: wgpu::Backends) -> String {
    let names: Vec<&str> = wgpu::Backend::ALL
        .iter()
        .filter(|b| backends.contains(wgpu::Backends::from(**b)))
        .map(|b| b.to_str())
        .collect();
    if names.is_empty() {
        "none".to_string()
    } else {
        names.join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_adapter_choice() {
        assert_eq!("".parse(), Ok(AdapterChoice::default()));
        assert_eq!("auto".parse(), Ok(AdapterChoice::default()));
        assert_eq!(
            "gl, LLVMpipe".parse(),
            Ok(AdapterChoice {
                name_substring: Some("LLVMpipe".into()),
                backend: Some(wgpu::Backend::Gl),
                force_cpu: false,
            })
        );
        assert_eq!(
            "cpu,vk".parse(),
            Ok(AdapterChoice {
                name_substring: None,
                backend: Some(wgpu::Backend::Vulkan),
                force_cpu: true,
            })
        );
        assert!(matches!(
            "gl,vulkan".parse::<AdapterChoice>(),
            Err(AdapterChoiceParseError::TwoBackends { .. })
        ));
        assert!(matches!(
            "nvidia,amd".parse::<AdapterChoice>(),
            Err(AdapterChoiceParseError::TwoNames { .. })
        ));
    }

    #[test]
    fn ranks_prefer_real_gpus_and_vulkan() {
        assert!(
            device_type_rank(wgpu::DeviceType::DiscreteGpu)
                < device_type_rank(wgpu::DeviceType::Cpu)
        );
        assert!(backend_rank(wgpu::Backend::Vulkan) < backend_rank(wgpu::Backend::Gl));
        assert_eq!(
            backend_names(wgpu::Backends::VULKAN | wgpu::Backends::GL),
            "vulkan, gl"
        );
        assert_eq!(backend_names(wgpu::Backends::empty()), "none");
    }

    #[test]
    fn description_is_one_line() {
        let d = AdapterDescription {
            name: "llvmpipe".into(),
            backend: wgpu::Backend::Vulkan,
            device_type: wgpu::DeviceType::Cpu,
            driver: "llvmpipe".into(),
            driver_info: "Mesa 22.3.6".into(),
            vendor: 0,
            device: 0,
        };
        assert_eq!(
            d.to_string(),
            "llvmpipe (vulkan, CPU, driver llvmpipe Mesa 22.3.6)"
        );
    }
}
