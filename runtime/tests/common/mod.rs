//! The harness shared by the GPU test suites (each of `runtime/tests/` includes it with
//! `mod common;`, `tests/examples.rs` with a `#[path]` to this file):
//! the adapter ([`gpu_or_skip`]), a temporary folder per test ([`temp_dir`]), test scene files with
//! constant overrides, compiled and rendered ([`scene`]), and image assertions ([`image`]).
//!
//! A GPU test skips only when there is no adapter at all, and says so on stderr; any other adapter
//! error fails the test.

#![allow(dead_code)] // each suite uses some of these

pub mod image;
pub mod scene;
mod scratch;

pub use scratch::Scratch;

use rtc_runtime::gpu::{AdapterChoice, AdapterError, Gpu, GpuOptions, PipelineCacheConfig};

/// The default adapter, or `None` (with a `SKIPPED` line naming `test`) when there is none at all.
/// Its on-disk pipeline cache is off, so tests leave nothing in the user's cache folder.
pub fn gpu_or_skip(test: &str) -> Option<Gpu> {
    gpu_with_or_skip(
        test,
        &GpuOptions {
            pipeline_cache: PipelineCacheConfig::Off,
        },
    )
}

/// [`gpu_or_skip`] with explicit options (a pipeline cache in a temporary folder).
pub fn gpu_with_or_skip(test: &str, options: &GpuOptions) -> Option<Gpu> {
    match Gpu::with_options(&AdapterChoice::default(), options) {
        Ok(gpu) => {
            eprintln!("{test}: running on {}", gpu.description());
            Some(gpu)
        }
        Err(error @ AdapterError::NoAdapter { .. }) => {
            eprintln!("SKIPPED {test}: no GPU adapter at all: {error}");
            None
        }
        Err(error) => panic!("{test}: {error}"),
    }
}

/// A fresh, empty temporary folder for one test of the suite `suite`, unique to this process,
/// removed when the test passes ([`Scratch`]).
pub fn temp_dir(suite: &str, name: &str) -> Scratch {
    Scratch::new(&format!("{suite}-{name}-{}", std::process::id()))
}
