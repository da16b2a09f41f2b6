//! Helpers shared by the end-to-end suites that run the `rtc` binary on a GPU (each suite includes
//! this with `mod common;`).

#![allow(dead_code)] // each suite uses some of these

use std::path::Path;
use std::process::{Command, Output};

#[path = "../../../runtime/tests/common/scratch.rs"]
mod scratch;

pub use scratch::Scratch;

/// Runs this build's `rtc` with `args`, without colour, with a runtime dir for Mesa.
pub fn rtc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_rtc"))
        .args(args)
        .env("XDG_RUNTIME_DIR", std::env::temp_dir())
        .env("NO_COLOR", "1")
        .output()
        .expect("run rtc")
}

/// What the command printed, stdout then stderr.
pub fn text(out: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// A fresh, empty scratch folder for one test of the suite `suite`, unique to this process,
/// removed when the test passes ([`Scratch`]).
pub fn scratch(suite: &str, name: &str) -> Scratch {
    Scratch::new(&format!("{suite}-{}-{name}", std::process::id()))
}

/// `p` as a command-line argument.
pub fn s(p: &Path) -> &str {
    p.to_str().expect("UTF-8 path")
}

/// True (after saying so) when the command failed because the machine has no GPU adapter at all,
/// so the test's GPU checks are skipped.
pub fn no_gpu(out: &Output) -> bool {
    let t = text(out);
    let none = !out.status.success() && t.contains("no GPU adapter found");
    if none {
        eprintln!("SKIPPED: no GPU adapter at all\n{t}");
    }
    none
}
