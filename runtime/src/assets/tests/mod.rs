//! Tests of the asset stage, one file per loader, plus `fuzz.rs` (random and mutated input
//! never panics). Files are written to a fresh folder under the system temp dir ([`TempDir`])
//! that is removed afterwards; nothing outside the repository is read.

mod confine;
mod confine_memory;
mod fuzz;
mod fuzz_files;
mod gltf;
mod gltf_animation;
mod gltf_builder;
mod gltf_report;
mod gltf_scene;
mod mesh;
mod messages;
mod obj;
mod procedural;
mod texture;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A folder for one test's files, removed on drop.
pub(super) struct TempDir(PathBuf);

impl TempDir {
    pub fn new(tag: &str) -> Self {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let dir = std::env::temp_dir().join(format!(
            "rtc-assets-{tag}-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir_all(&dir).expect("create temp dir");
        Self(dir)
    }

    pub fn path(&self) -> &Path {
        &self.0
    }

    /// Writes `bytes` to `name` in the folder and returns the file's path.
    pub fn write(&self, name: &str, bytes: impl AsRef<[u8]>) -> PathBuf {
        let path = self.0.join(name);
        std::fs::write(&path, bytes).expect("write temp file");
        path
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Asserts two floats agree to `eps`.
#[track_caller]
pub(super) fn assert_close(a: f32, b: f32, eps: f32) {
    assert!((a - b).abs() <= eps, "{a} vs {b} (eps {eps})");
}

/// Asserts two vectors agree to `eps` per component.
#[track_caller]
pub(super) fn assert_close3(a: impl Into<glam::Vec3>, b: impl Into<glam::Vec3>, eps: f32) {
    let (a, b) = (a.into(), b.into());
    assert!((a - b).abs().max_element() <= eps, "{a} vs {b} (eps {eps})");
}
