//! The host CPU, for every speed figure rtc prints: on a CPU driver (lavapipe, llvmpipe, WARP) the
//! kernel's speed depends on the CPU's vector units far more than on anything else, so a rays/s
//! figure means little without the CPU model and whether it has AVX2 and AVX-512 (issue 23: the
//! same commit runs the thesis workload 2.5–4 times slower on an AVX2-only core than on one with
//! AVX-512).
//!
//! Guarantees: [`HostCpu::detect`] never fails; the model comes from `/proc/cpuinfo` where that
//! exists (else the architecture's name), the vector features from the running CPU
//! (`is_x86_feature_detected!`), and the thread count from `std::thread::available_parallelism`.
//! Mesa's own overrides of what llvmpipe may use or do (`GALLIUM_OVERRIDE_CPU_CAPS`,
//! `LP_NATIVE_VECTOR_WIDTH`, `GALLIVM_PERF`) are named when set, since they change the code
//! lavapipe generates without changing the CPU.

use std::fmt;

/// Mesa's variables that change what llvmpipe compiles for, or how (`GALLIVM_PERF=nopt` turns
/// LLVM's optimisation passes off); named in [`HostCpu`]'s line when set.
const MESA_CPU_VARIABLES: [&str; 3] = [
    "GALLIUM_OVERRIDE_CPU_CAPS",
    "LP_NATIVE_VECTOR_WIDTH",
    "GALLIVM_PERF",
];

/// The machine a figure was measured on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HostCpu {
    /// The model name, e.g. `AMD EPYC 7B13`.
    pub model: String,
    /// Hardware threads this process may use.
    pub threads: usize,
    /// The vector extensions that decide a CPU driver's speed, present on this CPU: `AVX2`,
    /// `AVX-512` (x86-64 only; empty elsewhere).
    pub vector: Vec<&'static str>,
    /// Mesa variables that restrict what llvmpipe uses (`NAME=value`), set in this process.
    pub mesa_overrides: Vec<String>,
}

impl HostCpu {
    /// Reads the running machine's CPU.
    pub fn detect() -> Self {
        let model = std::fs::read_to_string("/proc/cpuinfo")
            .ok()
            .and_then(|text| model_name(&text))
            .unwrap_or_else(|| std::env::consts::ARCH.to_string());
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
        let mesa_overrides = MESA_CPU_VARIABLES
            .iter()
            .filter_map(|name| {
                let value = std::env::var(name).ok()?;
                (!value.is_empty()).then(|| format!("{name}={value}"))
            })
            .collect();
        Self {
            model,
            threads,
            vector: vector_features(),
            mesa_overrides,
        }
    }

    /// `AVX2 and AVX-512`, `AVX2, no AVX-512`, or `no AVX2` (x86-64); `None` on other architectures.
    pub fn vector_summary(&self) -> Option<String> {
        if !cfg!(target_arch = "x86_64") {
            return None;
        }
        let avx2 = self.vector.contains(&"AVX2");
        let avx512 = self.vector.contains(&"AVX-512");
        Some(
            match (avx2, avx512) {
                (true, true) => "AVX2 and AVX-512",
                (true, false) => "AVX2, no AVX-512",
                (false, true) => "AVX-512, no AVX2",
                (false, false) => "no AVX2, no AVX-512",
            }
            .to_string(),
        )
    }
}

impl fmt::Display for HostCpu {
    /// One line: `AMD EPYC 7B13, 2 threads, AVX2 and AVX-512` (and `; GALLIUM_OVERRIDE_CPU_CAPS=avx`
    /// when such a variable is set).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}, {} thread{}",
            self.model,
            self.threads,
            if self.threads == 1 { "" } else { "s" }
        )?;
        if let Some(v) = self.vector_summary() {
            write!(f, ", {v}")?;
        }
        if !self.mesa_overrides.is_empty() {
            write!(f, "; {}", self.mesa_overrides.join(" "))?;
        }
        Ok(())
    }
}

/// The first `model name` line of a `/proc/cpuinfo` text, trimmed; `None` when there is none.
fn model_name(cpuinfo: &str) -> Option<String> {
    cpuinfo.lines().find_map(|line| {
        let (key, value) = line.split_once(':')?;
        (key.trim() == "model name" && !value.trim().is_empty()).then(|| value.trim().to_string())
    })
}

#[cfg(target_arch = "x86_64")]
fn vector_features() -> Vec<&'static str> {
    let mut v = Vec::new();
    if std::arch::is_x86_feature_detected!("avx2") {
        v.push("AVX2");
    }
    if std::arch::is_x86_feature_detected!("avx512f") {
        v.push("AVX-512");
    }
    v
}

#[cfg(not(target_arch = "x86_64"))]
fn vector_features() -> Vec<&'static str> {
    Vec::new()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_model_name_is_the_first_model_line() {
        let text = "processor\t: 0\nvendor_id\t: AuthenticAMD\nmodel name\t: AMD EPYC 7B13\n\
                    processor\t: 1\nmodel name\t: AMD EPYC 7B13\n";
        assert_eq!(model_name(text).as_deref(), Some("AMD EPYC 7B13"));
        assert_eq!(model_name("processor : 0\nmodel name :   \n"), None);
        assert_eq!(model_name(""), None);
    }

    #[test]
    fn the_line_names_model_threads_vectors_and_overrides() {
        let cpu = HostCpu {
            model: "AMD EPYC 7B13".into(),
            threads: 2,
            vector: vec!["AVX2"],
            mesa_overrides: vec!["GALLIUM_OVERRIDE_CPU_CAPS=avx".into()],
        };
        let line = cpu.to_string();
        if cfg!(target_arch = "x86_64") {
            assert_eq!(
                line,
                "AMD EPYC 7B13, 2 threads, AVX2, no AVX-512; GALLIUM_OVERRIDE_CPU_CAPS=avx"
            );
        } else {
            assert_eq!(
                line,
                "AMD EPYC 7B13, 2 threads; GALLIUM_OVERRIDE_CPU_CAPS=avx"
            );
        }
    }

    #[test]
    fn detection_does_not_fail() {
        let cpu = HostCpu::detect();
        assert!(!cpu.model.is_empty());
        assert!(cpu.threads >= 1);
    }
}
