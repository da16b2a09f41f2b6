//! A temporary folder for one test that removes itself when the test passes.
//!
//! Included by `runtime/tests/common/mod.rs` and, with a `#[path]`, by the CLI suites' helpers
//! and `tests/targets.rs`. A folder outlives its test only when the test fails (the guard is
//! dropped while the thread panics), so a failure's files stay where its message points and a
//! passing run leaves nothing in the system's temporary folder.

use std::ops::Deref;
use std::path::{Path, PathBuf};

/// A fresh, empty folder under the system's temporary folder; derefs to its path.
#[derive(Debug)]
pub struct Scratch {
    path: PathBuf,
}

impl Scratch {
    /// Creates `rtc-{name}` in the system's temporary folder, emptied first if it exists.
    /// Callers put the process id in `name` so concurrent runs do not meet.
    pub fn new(name: &str) -> Scratch {
        let path = std::env::temp_dir().join(format!("rtc-{name}"));
        let _ = std::fs::remove_dir_all(&path);
        std::fs::create_dir_all(&path).expect("create a temporary folder");
        Scratch { path }
    }
}

impl Deref for Scratch {
    type Target = Path;

    fn deref(&self) -> &Path {
        &self.path
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.path
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            let _ = std::fs::remove_dir_all(&self.path);
        }
    }
}
